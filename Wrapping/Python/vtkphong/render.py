"""vtkphong-render: render a mesh file to an image with vtkPhong's lighting.

The command-line renderer (``vtkphong-render MESH -o OUT.png``), also usable
from Python::

    from vtkphong import render
    render.main(["bunny.off", "-o", "bunny.png", "--lobe", "phong"])

Run ``vtkphong-render --help`` for the options, the scene-file format and the
exit codes.
"""

import argparse
import json
import math
import os
import struct
import sys

PROGRAM = "vtkphong-render"

FORMATS = {
    ".obj": "Wavefront OBJ, with the colours and Ns shininess of its .mtl file",
    ".ply": "PLY (its vertex colours are used)",
    ".stl": "STL, ASCII or binary",
    ".off": "OFF (polygons of any size, vertex colours)",
    ".vtp": "VTK XML polydata",
    ".vtk": "VTK legacy file (any dataset; its outer surface is drawn)",
}
OUTPUTS = {
    ".png": "8-bit RGB (RGBA with --transparent), clamped to [0, 1]",
    ".exr": "32-bit float RGBA, unclamped (values above 1 kept)",
}
LOBES = ("phong", "blinn-phong", "normalized-phong", "normalized-blinn-phong")
INTERPOLATIONS = ("flat", "gouraud", "per-vertex-gouraud", "phong")
DEBUG_VIEWS = ("final", "ambient", "diffuse", "specular", "emission", "normal",
               "single-light")
WEIGHTINGS = ("uniform", "area", "angle", "max")
LIGHT_TYPES = ("directional", "point", "spot")
LIGHT_KINDS = ("scene", "camera", "headlight")

# Meshes bigger than this (bytes on disk) get a progress line.
PROGRESS_FILE_SIZE = 8 * 1024 * 1024

DEFAULTS = {
    "size": [1024, 768],
    "background": [0.12, 0.12, 0.14],
    "transparent": False,
    "lobe": "blinn-phong",
    "interpolation": "phong",
    "debug_view": "final",
    "debug_light": 0,
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

EPILOG = """\
input formats:
%(formats)s

output formats (by the extension of -o):
%(outputs)s

lights:
  Without --light or a scene file's "lights", a three-light studio rig is used
  (key, fill and rim camera lights that follow the view). --light TYPE:X,Y,Z
  adds a scene light (TYPE: directional, point or spot) at X,Y,Z measured from
  the mesh's centre in units of its bounding radius, aimed at the centre;
  optional :R,G,B colour and :INTENSITY follow, e.g.
      --light point:1,1,1.5:1,0.9,0.8:1.2
  Any --light replaces the rig and the scene file's lights.

scene file (--scene FILE.json), every key optional, flags win over it:
  {
    "size": [W, H], "background": [R, G, B], "transparent": false,
    "lobe": "blinn-phong", "interpolation": "phong",
    "debug_view": "final", "debug_light": 0,
    "renderer_ambient": [1, 1, 1],
    "camera": {"azimuth": 30, "elevation": 20, "zoom": 1},
    "material": {"color": [R, G, B], "ambient": 0.1, "diffuse": 0.8,
                 "specular": 0.4, "shininess": 60,
                 "specular_color": [1, 1, 1], "emission": [0, 0, 0]},
    "normals": {"weighting": "max", "feature_angle": 30, "splitting": true},
    "lights": [{"type": "point", "kind": "scene",
                "position": [1, 1, 1.5], "focal_point": [0, 0, 0],
                "color": [1, 1, 1], "intensity": 1,
                "ambient_color": [0, 0, 0], "specular_color": [1, 1, 1],
                "attenuation": [1, 0, 0], "cone_angle": 30, "exponent": 1}]
  }
  Light "kind": "scene" (positions relative to the mesh, as --light),
  "camera" (VTK camera-light coordinates: the camera at (0, 0, 1), the focal
  point at the origin) or "headlight" (at the camera; no position).

materials:
  An OBJ's .mtl gives each part its Kd, Ka, Ks colours and its Ns shininess
  (used as is with the default Blinn-Phong lobe). Material flags override the
  file. Meshes with 8-bit vertex or cell colours (PLY, OFF, VTK) keep them
  unless --color is given.

exit status: 0 on success, 1 when the mesh cannot be read or the image cannot
be made or written, 2 for bad options or a bad scene file. Errors are one line
on stderr. Rendering needs an X display (run under xvfb-run -a on a server).
""" % {
    "formats": "\n".join("  %-6s %s" % item for item in FORMATS.items()),
    "outputs": "\n".join("  %-6s %s" % item for item in OUTPUTS.items()),
}


class UsageError(Exception):
    """Bad options or scene file: exit status 2."""


class RenderError(Exception):
    """The mesh or the image failed: exit status 1."""


# --- option values ---------------------------------------------------------

def _numbers(text, count, what):
    try:
        values = [float(part) for part in text.split(",")]
    except ValueError:
        raise UsageError("%s must be %d comma-separated numbers, not %r" % (what, count, text))
    if len(values) != count or not all(math.isfinite(v) for v in values):
        raise UsageError("%s must be %d comma-separated finite numbers, not %r"
                         % (what, count, text))
    return values


def _color(text, what="a colour"):
    values = _numbers(text, 3, what)
    if min(values) < 0.0:
        raise UsageError("%s must not be negative: %r" % (what, text))
    return values


def _size(text):
    parts = text.lower().split("x")
    try:
        width, height = (int(part) for part in parts)
    except ValueError:
        raise UsageError("--size must be WIDTHxHEIGHT, e.g. 1024x768, not %r" % text)
    _check_size([width, height], "--size")
    return [width, height]


def _check_size(size, what):
    if (not isinstance(size, list) or len(size) != 2
            or not all(isinstance(v, int) and not isinstance(v, bool) for v in size)
            or not all(1 <= v <= 16384 for v in size)):
        raise UsageError("%s must be two whole numbers from 1 to 16384, not %r" % (what, size))


def _unit_range(name, low=0.0, high=1.0):
    def parse(text):
        try:
            value = float(text)
        except ValueError:
            raise UsageError("%s must be a number, not %r" % (name, text))
        if not (low <= value <= high):
            raise UsageError("%s must be in [%g, %g], not %r" % (name, low, high, text))
        return value
    return parse


def _light_option(text):
    parts = text.split(":")
    if len(parts) < 2 or len(parts) > 4 or parts[0] not in LIGHT_TYPES:
        raise UsageError("--light must be TYPE:X,Y,Z[:R,G,B[:INTENSITY]] with TYPE one of %s,"
                         " not %r" % (", ".join(LIGHT_TYPES), text))
    light = {"kind": "scene", "type": parts[0],
             "position": _numbers(parts[1], 3, "a --light position")}
    if len(parts) > 2:
        light["color"] = _color(parts[2], "a --light colour")
    if len(parts) > 3:
        light["intensity"] = _unit_range("a --light intensity", 0.0, 1e6)(parts[3])
    return light


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        raise UsageError("%s (see --help)" % message)


def make_parser():
    parser = _Parser(
        prog=PROGRAM,
        description="Render a mesh to an image with vtkPhong's exact Phong / Blinn-Phong"
                    " lighting: camera fitted to the mesh, a three-light studio rig,"
                    " Blinn-Phong, normals computed when the file has none.",
        epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mesh", help="the mesh file (%s)" % ", ".join(FORMATS))
    parser.add_argument("-o", "--output", required=True, help="the image to write (.png or .exr)")
    parser.add_argument("--scene", metavar="FILE.json", help="a scene file (format below)")
    parser.add_argument("--size", type=_size, metavar="WxH", help="image size (default 1024x768)")
    parser.add_argument("--background", type=_color, metavar="R,G,B",
                        help="background colour (default 0.12,0.12,0.14)")
    parser.add_argument("--transparent", action="store_true", default=None,
                        help="PNG with alpha: the background transparent")
    parser.add_argument("--lobe", choices=LOBES, help="specular lobe (default blinn-phong)")
    parser.add_argument("--interpolation", choices=INTERPOLATIONS,
                        help="shading interpolation (default phong)")
    parser.add_argument("--color", type=_color, metavar="R,G,B",
                        help="surface colour (default: the file's colours, else 0.8 grey)")
    parser.add_argument("--ambient", type=_unit_range("--ambient"), metavar="K",
                        help="ambient coefficient ka in [0, 1] (default 0.1)")
    parser.add_argument("--diffuse", type=_unit_range("--diffuse"), metavar="K",
                        help="diffuse coefficient kd in [0, 1] (default 0.8)")
    parser.add_argument("--specular", type=_unit_range("--specular"), metavar="K",
                        help="specular coefficient ks in [0, 1] (default 0.4)")
    parser.add_argument("--shininess", type=_unit_range("--shininess", 0.0, 1e6), metavar="N",
                        help="specular exponent n in [0, 1e6] (default 60)")
    parser.add_argument("--emission", type=_color, metavar="R,G,B", help="emitted colour")
    parser.add_argument("--light", type=_light_option, action="append", metavar="SPEC",
                        help="add a scene light (see 'lights' below); repeatable")
    parser.add_argument("--azimuth", type=_unit_range("--azimuth", -360, 360), metavar="DEG",
                        help="camera azimuth around the mesh (default 30)")
    parser.add_argument("--elevation", type=_unit_range("--elevation", -89, 89), metavar="DEG",
                        help="camera elevation (default 20)")
    parser.add_argument("--zoom", type=_unit_range("--zoom", 0.01, 100), metavar="F",
                        help="camera zoom factor (default 1)")
    parser.add_argument("--debug-view", choices=DEBUG_VIEWS,
                        help="show one term, the normal, or one light (default final)")
    parser.add_argument("--debug-light", type=int, metavar="I",
                        help="the light shown by --debug-view single-light (default 0)")
    parser.add_argument("--normals-weighting", choices=WEIGHTINGS,
                        help="weighting of computed normals (default max)")
    parser.add_argument("--feature-angle", type=_unit_range("--feature-angle", 0, 180),
                        metavar="DEG", help="normals split above this angle (default 30)")
    parser.add_argument("--quiet", action="store_true", help="no progress line, no output path")
    return parser


# --- the scene: defaults < scene file < flags --------------------------------

def _expect(condition, path, what):
    if not condition:
        raise UsageError("scene file: %s %s" % (path, what))


def _is_number(value):
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


def _choice(value, path, choices):
    _expect(value in choices, path, "must be one of " + ", ".join(choices))
    return value


def _keys(dictionary, path, allowed):
    _expect(isinstance(dictionary, dict), path, "must be an object")
    for key in dictionary:
        _expect(key in allowed, "%s.%s" % (path, key) if path != "" else key,
                "is not a known key (known: %s)" % ", ".join(sorted(allowed)))


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


def load_scene_file(path):
    """The settings of a scene file, validated (UsageError on a bad file)."""
    try:
        with open(path, encoding="utf-8") as stream:
            scene = json.load(stream)
    except OSError as error:
        raise UsageError("cannot read the scene file %s: %s" % (path, error.strerror or error))
    except (ValueError, UnicodeDecodeError) as error:
        raise UsageError("scene file %s is not valid JSON: %s" % (path, error))
    _keys(scene, "", list(DEFAULTS))
    settings = {}
    if "size" in scene:
        try:
            _check_size(scene["size"], "size")
        except UsageError as error:
            raise UsageError("scene file: %s" % error)
        settings["size"] = list(scene["size"])
    for key in ("background", "renderer_ambient"):
        if key in scene:
            settings[key] = _vector(scene[key], key)
    if "transparent" in scene:
        _expect(isinstance(scene["transparent"], bool), "transparent", "must be true or false")
        settings["transparent"] = scene["transparent"]
    for key, choices in (("lobe", LOBES), ("interpolation", INTERPOLATIONS),
                         ("debug_view", DEBUG_VIEWS)):
        if key in scene:
            settings[key] = _choice(scene[key], key, choices)
    if "debug_light" in scene:
        settings["debug_light"] = int(_number(scene["debug_light"], "debug_light", 0, 1e6))
    if "material" in scene:
        material = scene["material"]
        _keys(material, "material", list(DEFAULTS["material"]))
        settings["material"] = {}
        for key in ("color", "specular_color", "emission"):
            if key in material:
                settings["material"][key] = _vector(material[key], "material." + key)
        for key in ("ambient", "diffuse", "specular"):
            if key in material:
                settings["material"][key] = _number(material[key], "material." + key, 0, 1)
        if "shininess" in material:
            settings["material"]["shininess"] = _number(material["shininess"],
                                                        "material.shininess", 0, 1e6)
    if "camera" in scene:
        camera = scene["camera"]
        _keys(camera, "camera", list(DEFAULTS["camera"]))
        limits = {"azimuth": (-360, 360), "elevation": (-89, 89), "zoom": (0.01, 100)}
        settings["camera"] = {key: _number(camera[key], "camera." + key, *limits[key])
                              for key in camera}
    if "normals" in scene:
        normals = scene["normals"]
        _keys(normals, "normals", list(DEFAULTS["normals"]))
        settings["normals"] = {}
        if "weighting" in normals:
            settings["normals"]["weighting"] = _choice(normals["weighting"],
                                                       "normals.weighting", WEIGHTINGS)
        if "feature_angle" in normals:
            settings["normals"]["feature_angle"] = _number(normals["feature_angle"],
                                                           "normals.feature_angle", 0, 180)
        if "splitting" in normals:
            _expect(isinstance(normals["splitting"], bool), "normals.splitting",
                    "must be true or false")
            settings["normals"]["splitting"] = normals["splitting"]
    if "lights" in scene:
        _expect(isinstance(scene["lights"], list), "lights", "must be a list")
        settings["lights"] = [_light_from_json(light, "lights[%d]" % index)
                              for index, light in enumerate(scene["lights"])]
    return settings


def settings_from(options):
    """The full settings: the defaults, then the scene file, then the flags."""
    settings = json.loads(json.dumps(DEFAULTS))  # a deep copy
    # The material keys the user chose (scene file or flags): they override an OBJ's .mtl.
    settings["material_set"] = set()
    if options.scene:
        for key, value in load_scene_file(options.scene).items():
            if isinstance(value, dict):
                settings[key].update(value)
            else:
                settings[key] = value
            if key == "material":
                settings["material_set"].update(value)
    flags = {"size": options.size, "background": options.background,
             "transparent": options.transparent, "lobe": options.lobe,
             "interpolation": options.interpolation, "debug_view": options.debug_view,
             "debug_light": options.debug_light, "lights": options.light}
    for key, value in flags.items():
        if value is not None:
            settings[key] = value
    for key in ("color", "ambient", "diffuse", "specular", "shininess", "emission"):
        value = getattr(options, key)
        if value is not None:
            settings["material"][key] = value
            settings["material_set"].add(key)
    for key in ("azimuth", "elevation", "zoom"):
        if getattr(options, key) is not None:
            settings["camera"][key] = getattr(options, key)
    if options.normals_weighting is not None:
        settings["normals"]["weighting"] = options.normals_weighting
    if options.feature_angle is not None:
        settings["normals"]["feature_angle"] = options.feature_angle
    if settings["debug_light"] < 0:
        raise UsageError("--debug-light must be 0 or more")
    return settings


# --- reading ---------------------------------------------------------------

class Progress:
    """One line on stderr, rewritten in place, for big meshes."""

    def __init__(self, enabled):
        self.enabled = enabled
        self.shown = False

    def observe(self, algorithm, stage):
        if not self.enabled:
            return

        def report(caller, _event):
            sys.stderr.write("\r%s: %s %3d%%" % (PROGRAM, stage, int(100 * caller.GetProgress())))
            sys.stderr.flush()
            self.shown = True
        algorithm.AddObserver("ProgressEvent", report)

    def stage(self, stage):
        if self.enabled:
            sys.stderr.write("\r%s: %s     " % (PROGRAM, stage))
            sys.stderr.flush()
            self.shown = True

    def done(self):
        if self.shown:
            sys.stderr.write("\r%s: done%s\n" % (PROGRAM, " " * 24))
            sys.stderr.flush()
            self.shown = False


def _vtk_messages():
    """Collect VTK's warnings and errors instead of printing them: the command
    prints one line of its own."""
    from vtkmodules.vtkCommonCore import vtkLogger, vtkOutputWindow, vtkStringOutputWindow
    collector = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(collector)
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
    return collector


def _first_vtk_error(collector):
    """The first VTK error message collected, on one printable line, or ''."""
    text = collector.GetOutput()
    if isinstance(text, bytes):
        text = text.decode("utf-8", "replace")
    for block in text.split("\n\n"):
        if "ERROR" in block or "Warning" in block:
            # "ERROR: In file, line N\nvtkClass (0x...): message, maybe on several lines"
            message = " ".join(block.split("\n")[1:]) if "\n" in block else block
            if "): " in message:
                message = message.split("): ", 1)[1]
            message = "".join(c if " " <= c <= "~" else "?" for c in message).strip()
            return message if len(message) <= 160 else message[:157] + "..."
    return ""


def _check_stl(path):
    """vtkSTLReader reads any file as binary STL; refuse files that are neither."""
    with open(path, "rb") as stream:
        head = stream.read(1024)
    if head.lstrip().lower().startswith(b"solid") and all(
            byte in b"\t\n\r" or 32 <= byte < 127 for byte in head):
        return  # ASCII
    size = os.path.getsize(path)
    if size < 84:
        raise RenderError("cannot read %s: not an STL file (too short)" % path)
    (count,) = struct.unpack("<I", head[80:84])
    if size != 84 + 50 * count:
        raise RenderError("cannot read %s: not an STL file (as binary STL it would hold %d"
                          " triangles in %d bytes; it has %d)" % (path, count, 84 + 50 * count, size))


def _mtl_library(obj_path):
    """The .mtl file an OBJ names (mtllib), or None."""
    with open(obj_path, "rb") as stream:
        for raw in stream:
            line = raw.decode("utf-8", "replace").strip()
            if line.startswith("mtllib "):
                return os.path.join(os.path.dirname(obj_path), line[7:].strip())
    return None


def _mtl_shininess(mtl_path):
    """Ns of each material of an .mtl file (VTK's importer clamps it)."""
    shininess = {}
    current = None
    with open(mtl_path, "rb") as stream:
        for raw in stream:
            parts = raw.decode("utf-8", "replace").split()
            if len(parts) >= 2 and parts[0] == "newmtl":
                current = parts[1]
            elif len(parts) >= 2 and parts[0] == "Ns" and current is not None:
                try:
                    shininess[current] = float(parts[1])
                except ValueError:
                    pass
    return shininess


class Part:
    """A piece of geometry with, for OBJ files, the material of its .mtl."""

    def __init__(self, polydata, material=None, texture=None):
        self.polydata = polydata
        self.material = material  # a vtkProperty from the file, or None
        self.shininess = None     # the file's Ns
        self.texture = texture


def _read_obj(path, warnings):
    from vtkmodules.vtkIOImport import vtkOBJImporter
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    importer = vtkOBJImporter()
    importer.SetFileName(path)
    importer.SetTexturePath(os.path.dirname(os.path.abspath(path)))
    shininess = {}
    library = _mtl_library(path)
    if library is not None:
        if os.path.isfile(library):
            importer.SetFileNameMTL(library)
            shininess = _mtl_shininess(library)
        else:
            warnings.append("%s names the material file %s, which is missing; the default"
                            " material is used" % (path, library))
    importer.SetRenderWindow(window)
    importer.Update()
    parts = []
    actors = renderer.GetActors()
    actors.InitTraversal()
    for index in range(actors.GetNumberOfItems()):
        actor = actors.GetNextActor()
        polydata = actor.GetMapper().GetInput() if actor.GetMapper() else None
        if polydata is None or polydata.GetNumberOfCells() == 0:
            continue
        description = importer.GetOutputDescription(index)
        name = None
        if " with material named " in description:
            name = description.split(" with material named ", 1)[1].split(" texture file ")[0]
        part = Part(polydata)
        if name is not None and name != "x" and library is not None and os.path.isfile(library):
            part.material = actor.GetProperty()
            part.shininess = shininess.get(name)
            part.texture = actor.GetTexture()
        parts.append(part)
    # The importer keeps its render window; it is not needed any more.
    window.Finalize()
    return parts


def read_mesh(path, progress, warnings):
    """The mesh's parts; RenderError when it cannot be read."""
    extension = os.path.splitext(path)[1].lower()
    if extension not in FORMATS:
        raise RenderError("cannot read %s: unknown extension %r (known: %s)"
                          % (path, extension, ", ".join(FORMATS)))
    if not os.path.isfile(path):
        raise RenderError("cannot read %s: no such file" % path)
    if extension == ".obj":
        parts = _read_obj(path, warnings)
    else:
        if extension == ".stl":
            _check_stl(path)
            from vtkmodules.vtkIOGeometry import vtkSTLReader as Reader
        elif extension == ".ply":
            from vtkmodules.vtkIOPLY import vtkPLYReader as Reader
        elif extension == ".off":
            from vtkphong import vtkPhongOFFReader as Reader
        elif extension == ".vtp":
            from vtkmodules.vtkIOXML import vtkXMLPolyDataReader as Reader
        else:
            from vtkmodules.vtkIOLegacy import vtkGenericDataObjectReader as Reader
        reader = Reader()
        reader.SetFileName(path)
        progress.observe(reader, "reading")
        reader.Update()
        output = reader.GetOutput()
        if output is not None and output.IsA("vtkDataSet") and not output.IsA("vtkPolyData"):
            from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
            surface = vtkDataSetSurfaceFilter()
            surface.SetInputData(output)
            surface.Update()
            output = surface.GetOutput()
        if output is None or not output.IsA("vtkPolyData"):
            raise RenderError("cannot read %s: it holds no dataset" % path)
        parts = [Part(output)]
    if sum(part.polydata.GetNumberOfCells() for part in parts) == 0:
        raise RenderError("cannot read %s: it holds no geometry" % path)
    return parts


def _with_reason(error, collector):
    """The error, with VTK's first complaint appended when there is one."""
    reason = _first_vtk_error(collector)
    return RenderError("%s (%s)" % (error, reason) if reason else str(error))


# --- rendering -------------------------------------------------------------

def _property_for(part, settings, vtkphong):
    """The part's material: the .mtl file's values for an OBJ part, else the defaults;
    then whatever the scene file or the flags set."""
    material = settings["material"]
    chosen = settings["material_set"] if part.material is not None else set(material)
    prop = vtkphong.vtkPhongProperty()
    if part.material is not None:
        source = part.material
        prop.SetAmbientColor(source.GetAmbientColor())
        prop.SetDiffuseColor(source.GetDiffuseColor())
        prop.SetSpecularColor(source.GetSpecularColor())
        prop.SetAmbient(source.GetAmbient())
        prop.SetDiffuse(source.GetDiffuse())
        prop.SetSpecular(source.GetSpecular())
        prop.SetOpacity(source.GetOpacity())
        prop.SetLighting(source.GetLighting())
        prop.SetShininess(part.shininess if part.shininess is not None else material["shininess"])
    if "color" in chosen:
        # vtkProperty.SetColor also sets the specular colour; highlights stay as chosen.
        prop.SetColor(material["color"] if material["color"] is not None else [0.8, 0.8, 0.8])
        if part.material is not None:
            prop.SetSpecularColor(part.material.GetSpecularColor())
    if "specular_color" in chosen:
        prop.SetSpecularColor(material["specular_color"])
    for key, setter in (("ambient", prop.SetAmbient), ("diffuse", prop.SetDiffuse),
                        ("specular", prop.SetSpecular), ("shininess", prop.SetShininess)):
        if key in chosen:
            setter(material[key])
    prop.SetEmission(material["emission"])
    prop.SetLightingModel(LOBES.index(settings["lobe"]))
    interpolation = settings["interpolation"]
    if interpolation == "flat":
        prop.SetInterpolationToFlat()
    elif interpolation == "gouraud":
        prop.SetInterpolationToGouraud()
    elif interpolation == "per-vertex-gouraud":
        prop.SetInterpolationToPerVertexGouraud()
    else:
        prop.SetInterpolationToPhong()
    return prop


def _has_colors(polydata):
    for data in (polydata.GetPointData(), polydata.GetCellData()):
        scalars = data.GetScalars()
        if (scalars is not None and scalars.GetDataTypeAsString() == "unsigned char"
                and scalars.GetNumberOfComponents() in (3, 4)):
            return True
    return False


def _add_lights(renderer, lights, center, radius):
    from vtkmodules.vtkRenderingCore import vtkLight
    for spec in lights:
        light = vtkLight()
        kind = spec.get("kind", "scene")
        position = spec.get("position", [0.0, 0.0, 1.0])
        focal = spec.get("focal_point", [0.0, 0.0, 0.0])
        if kind == "headlight":
            light.SetLightTypeToHeadlight()
        elif kind == "camera":
            light.SetLightTypeToCameraLight()
            light.SetPosition(position)
            light.SetFocalPoint(focal)
        else:
            light.SetLightTypeToSceneLight()
            light.SetPosition([c + radius * p for c, p in zip(center, position)])
            light.SetFocalPoint([c + radius * f for c, f in zip(center, focal)])
        light.SetPositional(spec["type"] != "directional")
        light.SetConeAngle(spec.get("cone_angle", 30.0) if spec["type"] == "spot" else 180.0)
        light.SetExponent(spec.get("exponent", 1.0))
        light.SetAttenuationValues(spec.get("attenuation", [1.0, 0.0, 0.0]))
        color = spec.get("color", [1.0, 1.0, 1.0])
        light.SetDiffuseColor(spec.get("diffuse_color", color))
        light.SetSpecularColor(spec.get("specular_color", color))
        light.SetAmbientColor(spec.get("ambient_color", [0.0, 0.0, 0.0]))
        light.SetIntensity(spec.get("intensity", 1.0))
        renderer.AddLight(light)


def render(parts, settings, progress):
    """The float RGBA image of the parts (a vtkImageData)."""
    import vtkphong
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkRenderWindow

    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetMultiSamples(0)
    window.SetSize(settings["size"])
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    renderer.SetBackground(settings["background"])
    renderer.SetAmbient(settings["renderer_ambient"])
    renderer.AutomaticLightCreationOff()

    views = {"final": "Final", "ambient": "AmbientTerm", "diffuse": "DiffuseTerm",
             "specular": "SpecularTerm", "emission": "EmissionTerm",
             "normal": "ShadingNormal", "single-light": "SingleLight"}
    for part in parts:
        mapper = vtkphong.vtkPhongPolyDataMapper()
        mapper.SetInputData(part.polydata)
        colors = _has_colors(part.polydata) and settings["material"]["color"] is None
        mapper.SetScalarVisibility(colors)
        mapper.SetNormalsWeighting(WEIGHTINGS.index(settings["normals"]["weighting"]))
        mapper.SetNormalsFeatureAngle(settings["normals"]["feature_angle"])
        mapper.SetNormalsSplitting(settings["normals"]["splitting"])
        getattr(mapper, "SetDebugViewTo" + views[settings["debug_view"]])()
        mapper.SetDebugLightIndex(settings["debug_light"])
        progress.observe(mapper.GetNormalsGenerator(), "computing normals")
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.SetProperty(_property_for(part, settings, vtkphong))
        if part.texture is not None:
            actor.SetTexture(part.texture)
        renderer.AddActor(actor)

    camera = renderer.GetActiveCamera()
    renderer.ResetCamera()
    camera.Azimuth(settings["camera"]["azimuth"])
    camera.Elevation(settings["camera"]["elevation"])
    camera.OrthogonalizeViewUp()
    renderer.ResetCamera()
    camera.Zoom(settings["camera"]["zoom"])
    renderer.ResetCameraClippingRange()

    bounds = renderer.ComputeVisiblePropBounds()
    center = [(bounds[2 * i] + bounds[2 * i + 1]) / 2.0 for i in range(3)]
    radius = 0.5 * math.sqrt(sum((bounds[2 * i + 1] - bounds[2 * i]) ** 2 for i in range(3)))
    if not math.isfinite(radius) or radius <= 0.0:
        radius = 1.0
    lights = settings["lights"] if settings["lights"] is not None else STUDIO_RIG
    _add_lights(renderer, lights, center, radius)

    float_pass = vtkphong.vtkPhongFloatRenderPass()
    renderer.SetPass(float_pass)
    progress.stage("rendering")
    window.Render()
    image = vtkImageData()
    image.DeepCopy(float_pass.GetFloatImage())
    window.Finalize()
    return image


def write_image(image, path, settings):
    import vtkphong
    from vtkmodules.vtkImagingCore import vtkImageExtractComponents
    extension = os.path.splitext(path)[1].lower()
    if extension == ".png" and not settings["transparent"]:
        rgb = vtkImageExtractComponents()
        rgb.SetInputData(image)
        rgb.SetComponents(0, 1, 2)
        rgb.Update()
        image = rgb.GetOutput()
    if not vtkphong.vtkPhongImageIO().WriteImage(image, path):
        raise RenderError("cannot write %s" % path)


def run(arguments):
    """Render as the command line asks; raises UsageError or RenderError."""
    options = make_parser().parse_args(arguments)
    settings = settings_from(options)
    output_extension = os.path.splitext(options.output)[1].lower()
    if output_extension not in OUTPUTS:
        raise UsageError("-o must name a .png or .exr file, not %r" % options.output)
    output_directory = os.path.dirname(os.path.abspath(options.output))
    if not os.path.isdir(output_directory):
        raise RenderError("cannot write %s: no directory %s" % (options.output, output_directory))
    if sys.platform.startswith("linux") and not os.environ.get("DISPLAY"):
        raise RenderError("no X display to render with: run under xvfb-run -a")

    collector = _vtk_messages()
    try:
        big = os.path.getsize(options.mesh) > PROGRESS_FILE_SIZE
    except OSError:
        big = False
    progress = Progress(big and not options.quiet)
    warnings = []
    try:
        parts = read_mesh(options.mesh, progress, warnings)
    except RenderError as error:
        progress.done()
        raise _with_reason(error, collector)
    except OSError as error:
        progress.done()
        raise RenderError("cannot read %s: %s" % (options.mesh, error.strerror or error))
    for warning in warnings:
        progress.done()
        print("%s: warning: %s" % (PROGRAM, warning), file=sys.stderr)
    image = render(parts, settings, progress)
    progress.done()
    scalars = image.GetPointData().GetScalars()
    if scalars is None or image.GetNumberOfPoints() == 0:
        message = _first_vtk_error(collector)
        raise RenderError("rendering failed" + (": " + message if message else ""))
    write_image(image, options.output, settings)
    if not options.quiet:
        print(options.output)


def main(arguments=None):
    """The command: returns its exit status."""
    if arguments is None:
        arguments = sys.argv[1:]
    try:
        run(arguments)
    except UsageError as error:
        print("%s: error: %s" % (PROGRAM, error), file=sys.stderr)
        return 2
    except RenderError as error:
        print("%s: error: %s" % (PROGRAM, error), file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("%s: interrupted" % PROGRAM, file=sys.stderr)
        return 130
    except Exception as error:  # a bug: still one line, unless asked for the traceback
        if os.environ.get("VTKPHONG_DEBUG"):
            raise
        print("%s: error: internal error: %s: %s (VTKPHONG_DEBUG=1 shows the traceback)"
              % (PROGRAM, type(error).__name__, error), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
