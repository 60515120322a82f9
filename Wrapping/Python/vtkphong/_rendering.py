"""Rendering for vtkphong-render: the VTK pipeline that draws the parts and the
image file it writes.

The picture is read back through vtkPhongFloatRenderPass, so that an .exr
keeps the unclamped values; a .png clamps them as it is written.
"""

import math
import os
import sys
import time

from vtkphong._errors import RenderError
from vtkphong._scene import STUDIO_RIG

# How long to keep trying to connect to the X server: under xvfb-run, one server takes the
# connections of every render running at once, and may refuse one for a moment.
DISPLAY_ATTEMPT_DELAYS = (0.05, 0.1, 0.2, 0.4, 0.8, 1.0, 1.0, 1.0, 1.0)

OUTPUTS = {
    ".png": "8-bit RGB (RGBA with --transparent), clamped to [0, 1]",
    ".exr": "32-bit float RGBA, unclamped (values above 1 kept)",
}


def render(parts, settings, progress):
    """The float RGBA image of the parts (a vtkImageData)."""
    display = XDisplay.open()
    try:
        return _render_on(display, parts, settings, progress)
    finally:
        display.close()


def _render_on(display, parts, settings, progress):
    import vtkphong
    from vtkmodules.vtkCommonDataModel import vtkImageData

    window, renderer = _make_window(settings)
    display.give_to(window)
    for part in parts:
        renderer.AddActor(_actor_for(part, settings, progress))
    _place_camera(renderer, settings["camera"])
    center, radius = _bounding_sphere(renderer)
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


class XDisplay:
    """The X server connection the window renders on, opened here rather than by VTK.

    VTK 9.1's X11 window aborts the process when it cannot connect, before it says why
    anywhere the command shows. Here a refused connection is tried again for a few
    seconds, and then it is a RenderError naming the display. Off X11 (another window
    class, no libX11) there is nothing to open and VTK connects as it does."""

    def __init__(self, library=None, pointer=None):
        self._library = library
        self._pointer = pointer

    @classmethod
    def open(cls, delays=DISPLAY_ATTEMPT_DELAYS):
        library = _libx11()
        if library is None:
            return cls()
        for delay in delays + (None,):
            pointer = library.XOpenDisplay(None)
            if pointer:
                return cls(library, pointer)
            if delay is not None:
                time.sleep(delay)
        raise RenderError("cannot connect to the X display %s (refused for %g s)"
                          % (os.environ.get("DISPLAY", "(DISPLAY not set)"), sum(delays)))

    def give_to(self, window):
        if self._pointer and window.GetClassName() == "vtkXOpenGLRenderWindow":
            window.SetDisplayId("_%x_p_void" % self._pointer)

    def close(self):
        """After the window is finalized (VTK leaves a display it was given open)."""
        if self._pointer:
            self._library.XCloseDisplay(self._pointer)
            self._pointer = None


def _libx11():
    """libX11 through ctypes, or None where the platform has none."""
    if not sys.platform.startswith("linux"):
        return None
    import ctypes
    try:
        library = ctypes.CDLL("libX11.so.6")
    except OSError:
        return None
    library.XOpenDisplay.restype = ctypes.c_void_p
    library.XOpenDisplay.argtypes = [ctypes.c_char_p]
    library.XCloseDisplay.argtypes = [ctypes.c_void_p]
    return library


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


# --- the window, the camera ------------------------------------------------------

def _make_window(settings):
    """An offscreen window and its renderer, lit only by the lights added later (no
    automatic headlight)."""
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetMultiSamples(0)
    window.SetSize(settings["size"])
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    renderer.SetBackground(settings["background"])
    renderer.SetAmbient(settings["renderer_ambient"])
    renderer.AutomaticLightCreationOff()
    return window, renderer


def _place_camera(renderer, camera_settings):
    """Fit the camera to the mesh, turn it, then fit again so the turned view is framed."""
    camera = renderer.GetActiveCamera()
    renderer.ResetCamera()
    camera.Azimuth(camera_settings["azimuth"])
    camera.Elevation(camera_settings["elevation"])
    camera.OrthogonalizeViewUp()
    renderer.ResetCamera()
    camera.Zoom(camera_settings["zoom"])
    renderer.ResetCameraClippingRange()


def _bounding_sphere(renderer):
    """The centre and radius of the visible props: the unit of scene-light positions."""
    bounds = renderer.ComputeVisiblePropBounds()
    center = [(bounds[2 * i] + bounds[2 * i + 1]) / 2.0 for i in range(3)]
    radius = 0.5 * math.sqrt(sum((bounds[2 * i + 1] - bounds[2 * i]) ** 2 for i in range(3)))
    if not math.isfinite(radius) or radius <= 0.0:
        radius = 1.0
    return center, radius


# --- an actor per part -----------------------------------------------------------

def _actor_for(part, settings, progress):
    from vtkmodules.vtkRenderingCore import vtkActor
    mapper = _mapper_for(part, settings, progress)
    actor = vtkActor()
    actor.SetMapper(mapper)
    prop = _property_for(part, settings)
    _size_points_and_lines(prop, part.polydata, settings["size"])
    actor.SetProperty(prop)
    if part.texture is not None and settings["material"]["color"] is None:
        actor.SetTexture(part.texture)
    return actor


def _size_points_and_lines(prop, polydata, size):
    """Points and lines are drawn a few pixels wide, in proportion to the image, so a point
    cloud or a polyline shows at any size; a part without surfaces and without normals is
    drawn unlit in its colour (a point or a line has no surface to light)."""
    scale = max(size) / 1024.0
    prop.SetPointSize(max(3.0, 5.0 * scale))
    prop.SetLineWidth(max(1.0, 2.0 * scale))
    surfaces = polydata.GetNumberOfPolys() + polydata.GetNumberOfStrips()
    if surfaces == 0 and polydata.GetPointData().GetNormals() is None:
        prop.LightingOff()


def _mapper_for(part, settings, progress):
    from vtkphong import vtkOpenMeshNormals, vtkPhongPolyDataMapper
    # Names to the wrapped enum constants: the C++ order of the enums is not relied on.
    weightings = {"uniform": vtkOpenMeshNormals.Uniform, "area": vtkOpenMeshNormals.Area,
                  "angle": vtkOpenMeshNormals.Angle, "max": vtkOpenMeshNormals.Max}
    views = {"final": vtkPhongPolyDataMapper.Final,
             "ambient": vtkPhongPolyDataMapper.AmbientTerm,
             "diffuse": vtkPhongPolyDataMapper.DiffuseTerm,
             "specular": vtkPhongPolyDataMapper.SpecularTerm,
             "emission": vtkPhongPolyDataMapper.EmissionTerm,
             "normal": vtkPhongPolyDataMapper.ShadingNormal,
             "single-light": vtkPhongPolyDataMapper.SingleLight,
             "budget-use": vtkPhongPolyDataMapper.BudgetUse}
    mapper = vtkPhongPolyDataMapper()
    mapper.SetInputData(part.polydata)
    colors = _has_colors(part.polydata) and settings["material"]["color"] is None
    mapper.SetScalarVisibility(colors)
    mapper.SetNormalsWeighting(weightings[settings["normals"]["weighting"]])
    mapper.SetNormalsFeatureAngle(settings["normals"]["feature_angle"])
    mapper.SetNormalsSplitting(settings["normals"]["splitting"])
    mapper.SetDebugView(views[settings["debug_view"]])
    mapper.SetDebugLightIndex(settings["debug_light"])
    mapper.SetErrorBudget(settings["error_budget"])
    mapper.SetSpecularAntiAliasing(settings["specular_aa"])
    progress.observe(mapper.GetNormalsGenerator(), "computing normals")
    return mapper


def _has_colors(polydata):
    """Whether the file has 8-bit colours, which the mapper shows as they are."""
    for data in (polydata.GetPointData(), polydata.GetCellData()):
        scalars = data.GetScalars()
        if (scalars is not None and scalars.GetDataTypeAsString() == "unsigned char"
                and scalars.GetNumberOfComponents() in (3, 4)):
            return True
    return False


# --- the material ----------------------------------------------------------------

def _property_for(part, settings):
    """The part's material: the defaults, then the file's material (vtkphong.materials),
    then what the scene file or the flags set."""
    from vtkphong import vtkPhongProperty
    from vtkphong.materials import apply_material
    lobes = {"phong": vtkPhongProperty.Phong, "blinn-phong": vtkPhongProperty.BlinnPhong,
             "normalized-phong": vtkPhongProperty.NormalizedPhong,
             "normalized-blinn-phong": vtkPhongProperty.NormalizedBlinnPhong}
    material = settings["material"]
    prop = vtkPhongProperty()
    _apply_settings(prop, material, set(material))
    apply_material(prop, part.material)
    _apply_settings(prop, material, settings["material_set"])
    prop.SetLightingModel(lobes[settings["lobe"]])
    _set_interpolation(prop, settings["interpolation"])
    return prop


def _apply_settings(prop, material, chosen):
    """The chosen keys of the settings' material."""
    if "color" in chosen:
        # vtkProperty.SetColor sets the ambient, diffuse and specular colours; only the
        # first two are the surface's colour.
        color = material["color"] if material["color"] is not None else [0.8, 0.8, 0.8]
        prop.SetAmbientColor(color)
        prop.SetDiffuseColor(color)
    if "specular_color" in chosen:
        prop.SetSpecularColor(material["specular_color"])
    for key, setter in (("ambient", prop.SetAmbient), ("diffuse", prop.SetDiffuse),
                        ("specular", prop.SetSpecular), ("shininess", prop.SetShininess),
                        ("emission", prop.SetEmission)):
        if key in chosen and material.get(key) is not None:
            setter(material[key])


def _set_interpolation(prop, interpolation):
    setters = {"flat": prop.SetInterpolationToFlat,
               "gouraud": prop.SetInterpolationToGouraud,
               "per-vertex-gouraud": prop.SetInterpolationToPerVertexGouraud,
               "phong": prop.SetInterpolationToPhong}
    setters[interpolation]()


# --- the lights ------------------------------------------------------------------

def _add_lights(renderer, lights, center, radius):
    for spec in lights:
        renderer.AddLight(_make_light(spec, center, radius))


def _make_light(spec, center, radius):
    """A vtkLight from a light of the settings (a scene file's or --light's, validated)."""
    from vtkmodules.vtkRenderingCore import vtkLight
    light = vtkLight()
    _place_light(light, spec, center, radius)
    light.SetPositional(spec["type"] != "directional")
    light.SetConeAngle(spec.get("cone_angle", 30.0) if spec["type"] == "spot" else 180.0)
    light.SetExponent(spec.get("exponent", 1.0))
    light.SetAttenuationValues(spec.get("attenuation", [1.0, 0.0, 0.0]))
    color = spec.get("color", [1.0, 1.0, 1.0])
    light.SetDiffuseColor(spec.get("diffuse_color", color))
    light.SetSpecularColor(spec.get("specular_color", color))
    light.SetAmbientColor(spec.get("ambient_color", [0.0, 0.0, 0.0]))
    light.SetIntensity(spec.get("intensity", 1.0))
    return light


def _place_light(light, spec, center, radius):
    """Scene lights are placed in units of the mesh's bounding radius from its centre,
    so one scene file fits meshes of any size and position."""
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
