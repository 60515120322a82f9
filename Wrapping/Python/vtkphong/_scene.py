"""The scene of vtkphong-render: its defaults, the studio light rig and the
JSON scene file.

The settings are layered: the defaults, then the scene file, then the flags.
This module holds the first two layers, so that the scene-file schema and the
defaults it overrides read in one place; the flags are vtkphong.render's.
"""

import json
import math

from vtkphong._errors import UsageError

LOBES = ("phong", "blinn-phong", "normalized-phong", "normalized-blinn-phong")
INTERPOLATIONS = ("flat", "gouraud", "per-vertex-gouraud", "phong")
DEBUG_VIEWS = ("final", "ambient", "diffuse", "specular", "emission", "normal",
               "single-light", "budget-use")
WEIGHTINGS = ("uniform", "area", "angle", "max")
LIGHT_TYPES = ("directional", "point", "spot")
LIGHT_KINDS = ("scene", "camera", "headlight")

# The camera's ranges, the same for the flags and the scene file.
CAMERA_LIMITS = {"azimuth": (-360, 360), "elevation": (-89, 89), "zoom": (0.01, 100)}

DEFAULTS = {
    "size": [1024, 768],
    "background": [0.12, 0.12, 0.14],
    "transparent": False,
    "lobe": "blinn-phong",
    "interpolation": "phong",
    "debug_view": "final",
    "debug_light": 0,
    "error_budget": 0.0,  # levels; 0 is the exact mode
    "specular_aa": False,  # the highlights averaged over each pixel
    "material": {
        "color": None,  # None: the file's colours, else light grey
        "ambient": 0.1,
        "diffuse": 0.8,
        "specular": 0.4,
        "shininess": 60.0,
        "specular_color": [1.0, 1.0, 1.0],
        "emission": [0.0, 0.0, 0.0],
    },
    "camera": {"azimuth": 30.0, "elevation": 20.0, "zoom": 1.0},
    "renderer_ambient": [1.0, 1.0, 1.0],
    "normals": {"weighting": "max", "feature_angle": 30.0, "splitting": True},
    "lights": None,  # None: the studio rig
}

# The default three-light studio rig: camera lights, so the lighting follows any
# view. Positions in VTK's camera-light coordinates (the camera at (0, 0, 1),
# looking at the focal point at the origin).
STUDIO_RIG = [
    {"kind": "camera", "type": "directional", "position": [-0.6, 0.7, 1.0],
     "color": [1.0, 0.96, 0.9], "intensity": 0.9},   # key: upper left, warm
    {"kind": "camera", "type": "directional", "position": [0.8, -0.1, 0.9],
     "color": [0.85, 0.9, 1.0], "intensity": 0.35},  # fill: right, cool, dim
    {"kind": "camera", "type": "directional", "position": [0.2, 0.9, -1.0],
     "color": [1.0, 1.0, 1.0], "intensity": 0.6},    # rim: behind, above
]


def check_size(size, what):
    """UsageError unless size is [W, H]: --size and the scene file share the limits."""
    if (not isinstance(size, list) or len(size) != 2
            or not all(isinstance(v, int) and not isinstance(v, bool) for v in size)
            or not all(1 <= v <= 16384 for v in size)):
        raise UsageError("%s must be two whole numbers from 1 to 16384, not %r" % (what, size))


def scene_settings(scene_path):
    """The defaults with the scene file's settings (when there is one) over them.

    "material_set" names the material keys the user chose: those override an
    OBJ's .mtl, whereas the defaults do not."""
    settings = json.loads(json.dumps(DEFAULTS))  # a deep copy
    settings["material_set"] = set()
    if scene_path:
        for key, value in load_scene_file(scene_path).items():
            if isinstance(value, dict):
                settings[key].update(value)
            else:
                settings[key] = value
            if key == "material":
                settings["material_set"].update(value)
    return settings


def load_scene_file(path):
    """The settings of a scene file, validated (UsageError on a bad file)."""
    scene = _read_json(path)
    _keys(scene, "", list(DEFAULTS))
    settings = {}
    # In this order, so that of several mistakes the same one is reported first.
    for section in (_renderer_settings, _shading_settings, _material_settings,
                    _camera_settings, _normals_settings, _lights_settings):
        settings.update(section(scene))
    return settings


def _read_json(path):
    """The file's JSON value; a file that cannot be read or parsed is the user's error."""
    try:
        with open(path, encoding="utf-8") as stream:
            return json.load(stream)
    except OSError as error:
        raise UsageError("cannot read the scene file %s: %s" % (path, error.strerror or error))
    except (ValueError, UnicodeDecodeError) as error:
        raise UsageError("scene file %s is not valid JSON: %s" % (path, error))


# --- the scene file's sections ------------------------------------------------

def _renderer_settings(scene):
    """The image size, background, transparency and the renderer's ambient light."""
    settings = {}
    if "size" in scene:
        try:
            check_size(scene["size"], "size")
        except UsageError as error:
            raise UsageError("scene file: %s" % error)
        settings["size"] = list(scene["size"])
    for key in ("background", "renderer_ambient"):
        if key in scene:
            settings[key] = _vector(scene[key], key)
    if "transparent" in scene:
        settings["transparent"] = _boolean(scene["transparent"], "transparent")
    return settings


def _shading_settings(scene):
    """The lobe, the interpolation and the debug view."""
    settings = {}
    for key, choices in (("lobe", LOBES), ("interpolation", INTERPOLATIONS),
                         ("debug_view", DEBUG_VIEWS)):
        if key in scene:
            settings[key] = _choice(scene[key], key, choices)
    if "debug_light" in scene:
        settings["debug_light"] = int(_number(scene["debug_light"], "debug_light", 0, 1e6))
    if "error_budget" in scene:
        settings["error_budget"] = _number(scene["error_budget"], "error_budget", 0, 255)
    if "specular_aa" in scene:
        settings["specular_aa"] = _boolean(scene["specular_aa"], "specular_aa")
    return settings


def _material_settings(scene):
    """The material keys the file gives, and only those (see scene_settings)."""
    material = _section(scene, "material")
    if material is None:
        return {}
    result = {}
    for key in ("color", "specular_color", "emission"):
        if key in material:
            result[key] = _vector(material[key], "material." + key)
    for key in ("ambient", "diffuse", "specular"):
        if key in material:
            result[key] = _number(material[key], "material." + key, 0, 1)
    if "shininess" in material:
        result["shininess"] = _number(material["shininess"], "material.shininess", 0, 1e6)
    return {"material": result}


def _camera_settings(scene):
    camera = _section(scene, "camera")
    if camera is None:
        return {}
    return {"camera": {key: _number(camera[key], "camera." + key, *CAMERA_LIMITS[key])
                       for key in camera}}


def _normals_settings(scene):
    """How normals are computed for a mesh without them."""
    normals = _section(scene, "normals")
    if normals is None:
        return {}
    result = {}
    if "weighting" in normals:
        result["weighting"] = _choice(normals["weighting"], "normals.weighting", WEIGHTINGS)
    if "feature_angle" in normals:
        result["feature_angle"] = _number(normals["feature_angle"],
                                          "normals.feature_angle", 0, 180)
    if "splitting" in normals:
        result["splitting"] = _boolean(normals["splitting"], "normals.splitting")
    return {"normals": result}


def _lights_settings(scene):
    if "lights" not in scene:
        return {}
    _expect(isinstance(scene["lights"], list), "lights", "must be a list")
    return {"lights": [_light_from_json(light, "lights[%d]" % index)
                       for index, light in enumerate(scene["lights"])]}


def _section(scene, name):
    """The scene's object of that name, its keys checked, or None when it has none."""
    if name not in scene:
        return None
    _keys(scene[name], name, list(DEFAULTS[name]))
    return scene[name]


def _light_from_json(light, path):
    allowed = ("type", "kind", "position", "focal_point", "color", "intensity",
               "ambient_color", "diffuse_color", "specular_color", "attenuation",
               "cone_angle", "exponent")
    _keys(light, path, allowed)
    result = {"type": _choice(light.get("type", "directional"), path + ".type", LIGHT_TYPES),
              "kind": _choice(light.get("kind", "scene"), path + ".kind", LIGHT_KINDS)}
    for key in ("position", "focal_point"):
        if key in light:
            result[key] = _vector(light[key], "%s.%s" % (path, key), non_negative=False)
    for key in ("color", "ambient_color", "diffuse_color", "specular_color", "attenuation"):
        if key in light:
            result[key] = _vector(light[key], "%s.%s" % (path, key))
    if "intensity" in light:
        result["intensity"] = _number(light["intensity"], path + ".intensity", 0.0, 1e6)
    if "cone_angle" in light:
        result["cone_angle"] = _number(light["cone_angle"], path + ".cone_angle", 0.0, 180.0)
    if "exponent" in light:
        result["exponent"] = _number(light["exponent"], path + ".exponent", 0.0, 1e6)
    _expect(result["kind"] == "headlight" or "position" in result, path,
            "needs a position (or \"kind\": \"headlight\")")
    return result


# --- checking JSON values: each error names the value's path in the file -------

def _expect(condition, path, what):
    if not condition:
        raise UsageError("scene file: %s %s" % (path, what))


def _is_number(value):
    # JSON's true and false are ints to Python; they are not numbers here.
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _vector(value, path, count=3, non_negative=True):
    _expect(isinstance(value, list) and len(value) == count and all(_is_number(v) for v in value),
            path, "must be a list of %d numbers" % count)
    if non_negative:
        _expect(min(value) >= 0.0, path, "must not be negative")
    return [float(v) for v in value]


def _number(value, path, low, high):
    _expect(_is_number(value) and low <= value <= high, path,
            "must be a number in [%g, %g]" % (low, high))
    return float(value)


def _boolean(value, path):
    _expect(isinstance(value, bool), path, "must be true or false")
    return value


def _choice(value, path, choices):
    _expect(value in choices, path, "must be one of " + ", ".join(choices))
    return value


def _keys(dictionary, path, allowed):
    """A misspelt key is an error rather than a setting silently ignored."""
    _expect(isinstance(dictionary, dict), path, "must be an object")
    for key in dictionary:
        _expect(key in allowed, "%s.%s" % (path, key) if path != "" else key,
                "is not a known key (known: %s)" % ", ".join(sorted(allowed)))
