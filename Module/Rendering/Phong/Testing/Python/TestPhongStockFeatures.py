"""VTK's own rendering features keep working through the switch (`import vtkphong.overrides`):
each named case builds the same scene twice, once with the switch off (VTK's mapper) and once
with it on (vtkPhong's), and compares the pictures. A case either matches within the harness's
strict threshold (at most 24 pixels more than 6 levels off) or names the intended difference,
whose measured size it bounds. docs/compatibility.md quotes the table this test prints.

Run alone, it prints the table:
    PYTHONPATH=<build>/lib/python3/dist-packages:Testing/Core xvfb-run -a /usr/bin/python3 \\
        TestPhongStockFeatures.py -B Module/Rendering/Phong/Testing/Data/Baseline -T /tmp [case...]
"""

import argparse
import ctypes
import ctypes.util
import math
import os

import numpy
import vtkphong.overrides
from vtkmodules.vtkCommonComputationalGeometry import vtkParametricSpline
from vtkmodules.vtkCommonCore import (vtkLogger, vtkObjectFactory, vtkOutputWindow, vtkPoints,
                                      vtkStringOutputWindow, vtkUnsignedCharArray, vtkVersion)
from vtkmodules.vtkCommonDataModel import vtkPlane
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import (vtkDataObject, vtkDataSetAttributes, vtkImageData,
                                           vtkMultiBlockDataSet)
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkCleanPolyData, vtkTriangleFilter
from vtkmodules.vtkFiltersGeneral import vtkVertexGlyphFilter
from vtkmodules.vtkFiltersSources import (vtkConeSource, vtkCubeSource, vtkLineSource, vtkParametricFunctionSource,
                                          vtkPlaneSource,
                                          vtkRegularPolygonSource, vtkSphereSource)
from vtkmodules.vtkRenderingCore import (vtkActor, vtkCompositeDataDisplayAttributes,
                                         vtkGlyph3DMapper, vtkHardwareSelector, vtkLightKit,
                                         vtkMapper, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer)
from vtkmodules.vtkRenderingOpenGL2 import (vtkCameraPass, vtkLightingMapPass,
                                            vtkLightsPass, vtkPointFillPass,
                                            vtkRenderPassCollection,
                                            vtkRenderStepsPass, vtkSequencePass,
                                            vtkShadowMapPass, vtkSSAAPass, vtkSSAOPass,
                                            vtkToneMappingPass)
import vtkmodules.vtkRenderingCore as rendering_core
import vtkmodules.vtkRenderingOpenGL2 as opengl2
from vtkphong import vtkOpenMeshNormals, vtkPhongPolyDataMapper
from vtkphong_testing import STRICT_LEVELS, STRICT_PIXEL_BUDGET, Checks, scene_light, snapshot

SIZE = 160
VTK_9_3 = (vtkVersion.GetVTKMajorVersion(), vtkVersion.GetVTKMinorVersion()) >= (9, 3)
GL = ctypes.CDLL(ctypes.util.find_library("GL") or "libGL.so.1")
GL.glGetError.restype = ctypes.c_uint
checks = Checks()

# A replacement of //VTK::Light::Impl in the style of VTK's cube-map and sphere-map tests: it
# reads VTK's own `diffuse` and `specular` and writes the colour itself.
CUBE_MAP_STYLE = ("//VTK::Light::Impl\n"
                  "  gl_FragData[0] = vec4(ambientColor + diffuse + specular"
                  " + vec3(0.1, 0.0, 0.2), opacity);\n")
BROKEN = "//VTK::Light::Impl\n  this is not GLSL;\n"


def shared_display(window):
    """Give every window the first one's X connection: Xvfb refuses, now and then, a connection
    made right after another closed (vtkPhongSharedDisplay.h), and each case opens windows."""
    if DISPLAY_OWNER:
        window.SetDisplayId(DISPLAY_OWNER[0].GetGenericDisplayId())
    else:
        window.SetOffScreenRendering(1)
        window.SetSize(8, 8)
        window.Render()
        DISPLAY_OWNER.append(window)


DISPLAY_OWNER = []


class Scene:
    """One renderer in an offscreen window; `phong` tells which mapper the factory gives."""

    def __init__(self, phong, direct=False):
        self.phong = phong
        self.direct = direct
        self.renderer = vtkRenderer()
        self.window = vtkRenderWindow()
        shared_display(self.window)
        self.window.SetOffScreenRendering(1)
        self.window.SetSize(SIZE, SIZE)
        self.window.SetMultiSamples(0)
        self.window.AddRenderer(self.renderer)
        self.mappers = []

    def mapper(self):
        """A polydata mapper as an unmodified script makes it (or vtkPhong's, named)."""
        made = vtkPhongPolyDataMapper() if self.phong and self.direct else vtkPolyDataMapper()
        self.mappers.append(made)
        return made

    def actor(self, source, mapper=None):
        mapper = mapper or self.mapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        self.renderer.AddActor(actor)
        return actor


def composite_mapper():
    """VTK's composite mapper as ParaView asks the factory for it, by name (its Python
    constructor does not consult the factory on VTK 9.1). VTK 9.3 draws composite data with
    vtkCompositePolyDataMapper, before with vtkCompositePolyDataMapper2."""
    name = "vtkCompositePolyDataMapper" if VTK_9_3 else "vtkCompositePolyDataMapper2"
    made = vtkObjectFactory.CreateInstance(name)
    if made is None:  # no override: VTK's own class, from whichever module has it
        made = getattr(opengl2, name, None) or getattr(rendering_core, name)
        made = made()
    return made


def sphere(resolution=48, center=(0.0, 0.0, 0.0), radius=0.5):
    source = vtkSphereSource()
    source.SetThetaResolution(resolution)
    source.SetPhiResolution(resolution)
    source.SetCenter(*center)
    source.SetRadius(radius)
    return source


def two_lights(renderer):
    scene_light(renderer, (1.0, 1.0, 1.0), (1.0, 0.85, 0.7))
    scene_light(renderer, (-1.0, 0.5, 0.3), (0.35, 0.5, 1.0))


def shiny(actor, color=(0.9, 0.45, 0.2)):
    prop = actor.GetProperty()
    prop.SetColor(*color)
    prop.SetAmbient(0.1)
    prop.SetSpecular(0.5)
    prop.SetSpecularPower(30.0)
    return prop


def finish(scene):
    scene.renderer.ResetCamera()
    scene.window.Render()


# ---- the cases: each builds its scene into `scene` -----------------------------------------

def light_replacement(scene, replace_first=True):
    """A vtkShaderProperty replacement of //VTK::Light::Impl reading `diffuse`, `specular`."""
    actor = scene.actor(sphere())
    shiny(actor)
    actor.GetShaderProperty().AddFragmentShaderReplacement(
        "//VTK::Light::Impl", replace_first, CUBE_MAP_STYLE, False)
    two_lights(scene.renderer)
    finish(scene)


def light_replacement_direct(scene):
    """The same, with vtkPhongPolyDataMapper named (no factory)."""
    scene.direct = True
    light_replacement(scene)


def light_replacement_after(scene):
    """The replacement applied after VTK's own substitutions (ReplaceFirst off)."""
    light_replacement(scene, replace_first=False)


def composite_actor(scene, centers=((-0.6, 0.0, 0.0), (0.6, 0.0, 0.0)), radius=0.5):
    """Spheres as the blocks of one multiblock, drawn by the composite mapper (VTK's, or
    vtkPhong's through the switch)."""
    blocks = vtkMultiBlockDataSet()
    for index, center in enumerate(centers):
        source = sphere(32, center, radius)
        source.Update()
        blocks.SetBlock(index, source.GetOutput())
    mapper = composite_mapper()
    scene.mappers.append(mapper)
    mapper.SetInputDataObject(blocks)
    actor = vtkActor()
    actor.SetMapper(mapper)
    scene.renderer.AddActor(actor)
    return actor


def light_replacement_composite(scene):
    """The replacement on composite data."""
    actor = composite_actor(scene)
    shiny(actor)
    actor.GetShaderProperty().AddFragmentShaderReplacement(
        "//VTK::Light::Impl", True, CUBE_MAP_STYLE, False)
    two_lights(scene.renderer)
    finish(scene)


def edges_composite(scene):
    prop = shiny(composite_actor(scene))
    prop.EdgeVisibilityOn()
    prop.SetEdgeColor(0.1, 0.9, 0.3)
    two_lights(scene.renderer)
    finish(scene)


def block_attributes(actor):
    """The composite mapper's per-block attributes (ParaView's block colours, visibilities)
    and its blocks."""
    mapper = actor.GetMapper()
    attributes = vtkCompositeDataDisplayAttributes()
    mapper.SetCompositeDataDisplayAttributes(attributes)
    blocks = mapper.GetInputDataObject(0, 0)
    return attributes, [blocks.GetBlock(i) for i in range(blocks.GetNumberOfBlocks())]


def block_colours_composite(scene):
    """Per-block colours: the closed spheres' back faces are culled all the same."""
    actor = composite_actor(scene)
    shiny(actor)
    attributes, blocks = block_attributes(actor)
    attributes.SetBlockColor(blocks[0], (0.2, 0.5, 0.9))
    two_lights(scene.renderer)
    finish(scene)


def hidden_block_composite(scene):
    """A block hidden: its block mapper draws the others with their back faces."""
    actor = composite_actor(scene, ((-0.6, 0.0, 0.0), (0.6, 0.0, 0.0), (0.0, 0.6, 0.0)))
    shiny(actor)
    attributes, blocks = block_attributes(actor)
    attributes.SetBlockVisibility(blocks[2], False)
    two_lights(scene.renderer)
    finish(scene)


def shadows_composite(scene):
    """Shadows on composite data (ParaView draws surfaces with the composite mapper)."""
    shiny(composite_actor(scene, ((0.0, 0.2, 0.6), (0.6, 0.0, -0.5)), 0.25), (0.3, 0.8, 0.3))
    shadow_scene(scene, shadow_spots)


def lighting_map_luminance(scene):
    luminance = vtkLightingMapPass()
    luminance.SetRenderType(vtkLightingMapPass.LUMINANCE)
    scene.renderer.SetPass(camera_over(vtkLightsPass(), luminance))
    lit_spheres(scene)
    finish(scene)


def surface_with_edges(scene, ambient=0.0, tubes=False):
    """EdgeVisibilityOn: VTK mixes the edge colour into ambientColor, diffuseColor to black."""
    actor = scene.actor(sphere(16))
    prop = shiny(actor)
    prop.SetAmbient(ambient)
    prop.EdgeVisibilityOn()
    prop.SetEdgeColor(0.1, 0.9, 0.3)
    prop.SetLineWidth(2.0)
    prop.SetRenderLinesAsTubes(tubes)
    two_lights(scene.renderer)
    finish(scene)


def surface_with_edges_ambient(scene):
    surface_with_edges(scene, ambient=0.3)


def surface_with_edges_tubes(scene):
    surface_with_edges(scene, tubes=True)


def plane_points_lines():
    """A plane's polygons, a polyline and vertices, without normals: stock VTK lights the
    polygons (flat, their normal) and draws the lines and vertices unlit."""
    plane = vtkPlaneSource()
    plane.SetResolution(6, 6)
    line = vtkLineSource()
    line.SetPoint1(-0.5, -0.3, 0.05)
    line.SetPoint2(0.5, 0.3, 0.05)
    line.SetResolution(8)
    points = vtkRegularPolygonSource()  # its vertices, as verts
    points.SetNumberOfSides(12)
    points.SetRadius(0.35)
    points.SetCenter(0.0, 0.0, 0.1)
    points.GeneratePolygonOff()
    points.GeneratePolylineOff()
    vertices = vtkVertexGlyphFilter()
    vertices.SetInputConnection(points.GetOutputPort())
    append = vtkAppendPolyData()
    for source in (plane, line, vertices):
        append.AddInputConnection(source.GetOutputPort())
    append.Update()
    data = append.GetOutput()
    data.GetPointData().SetNormals(None)
    return data


def points_and_lines(scene, representation=None):
    mapper = scene.mapper()
    mapper.SetInputData(plane_points_lines())
    actor = vtkActor()
    actor.SetMapper(mapper)
    prop = shiny(actor)
    prop.SetPointSize(5.0)
    prop.SetLineWidth(3.0)
    if representation:
        representation(prop)
    scene.renderer.AddActor(actor)
    scene_light(scene.renderer, (0.3, 0.5, 1.0))
    finish(scene)


def points_representation(scene):
    """A surface without normals drawn as points: stock VTK draws them unlit."""
    points_and_lines(scene, lambda prop: prop.SetRepresentationToPoints())


def vertex_visibility(scene):
    actor = scene.actor(sphere(16))
    prop = shiny(actor)
    prop.VertexVisibilityOn()
    prop.SetVertexColor(0.9, 0.9, 0.1)
    prop.SetPointSize(4.0)
    two_lights(scene.renderer)
    finish(scene)


def coincident_topology(scene):
    """A wireframe over the same surface, resolved by VTK's polygon offsets."""
    for wireframe in (False, True):
        actor = scene.actor(sphere(20))
        prop = shiny(actor, (0.2, 0.3, 0.9) if wireframe else (0.9, 0.45, 0.2))
        if wireframe:
            prop.SetRepresentationToWireframe()
            actor.GetMapper().SetRelativeCoincidentTopologyLineOffsetParameters(-1.0, -4.0)
    vtkMapper.SetResolveCoincidentTopologyToPolygonOffset()
    two_lights(scene.renderer)
    finish(scene)


def shadow_scene(scene, lights, budget=0.0):
    """VTK's TestShadowMapPass in small: a plane, a few objects, scene lights that cast
    shadows, drawn through vtkShadowMapPass (vtkPhong's mappers under `budget` levels)."""
    shadow_scene_geometry(scene)
    for mapper in scene.mappers:
        if hasattr(mapper, "SetErrorBudget"):
            mapper.SetErrorBudget(budget)
    scene.renderer.AutomaticLightCreationOff()
    lights(scene.renderer)
    shadows = vtkShadowMapPass()
    scene.renderer.SetPass(camera_over(shadows.GetShadowMapBakerPass(), shadows))
    scene.window.Render()


def shadow_scene_geometry(scene):
    plane = vtkPlaneSource()
    plane.SetOrigin(-1.5, -0.5, -1.5)
    plane.SetPoint1(1.5, -0.5, -1.5)
    plane.SetPoint2(-1.5, -0.5, 1.5)
    plane.SetResolution(4, 4)
    shiny(scene.actor(plane), (0.8, 0.8, 0.8)).SetSpecular(0.2)
    for center, color in (((-0.5, 0.0, 0.0), (0.9, 0.4, 0.2)), ((0.4, 0.1, 0.3), (0.2, 0.5, 0.9))):
        shiny(scene.actor(sphere(32, center, 0.35)), color)
    scene.renderer.GetActiveCamera().SetPosition(0.0, 2.5, 4.0)
    scene.renderer.GetActiveCamera().SetFocalPoint(0.0, -0.2, 0.0)
    scene.renderer.ResetCameraClippingRange()


def shadow_spots(renderer):
    for position, color in (((1.5, 3.0, 1.0), (1.0, 0.9, 0.8)), ((-2.0, 2.5, 1.5), (0.5, 0.6, 1.0))):
        light = scene_light(renderer, position, color, positional=True)
        light.SetConeAngle(40.0)


def shadow_directional(renderer):
    scene_light(renderer, (1.0, 2.0, 0.5), (1.0, 0.95, 0.9))
    scene_light(renderer, (-1.0, 1.5, 1.0), (0.4, 0.5, 0.9))


def shadow_mixed(renderer):
    """A spot, a directional light, and a switched-off light between them (the pass numbers
    every light of the renderer)."""
    spot = scene_light(renderer, (1.5, 3.0, 1.0), (1.0, 0.9, 0.8), positional=True)
    spot.SetConeAngle(40.0)
    scene_light(renderer, (0.0, 1.0, 0.0)).SwitchOff()
    scene_light(renderer, (-1.0, 2.0, 0.5), (0.5, 0.6, 1.0))


def shadows_spots(scene):
    shadow_scene(scene, shadow_spots)


def shadows_directional(scene):
    shadow_scene(scene, shadow_directional)


def shadows_mixed(scene):
    shadow_scene(scene, shadow_mixed)


def shadows_budget(scene):
    """An error budget under directional lights would light the plane per vertex (its normals
    are equal: the bound is 0), where the pass's factors cannot be read: vtkPhong must stay
    per fragment, shadows and all."""
    shadow_scene(scene, shadow_directional, budget=2.0)


def ssao(scene):
    """vtkSSAOPass appends its G-buffer outputs after the lighting code."""
    shadow_scene_geometry(scene)
    two_lights(scene.renderer)
    pass_ = vtkSSAOPass()
    pass_.SetRadius(0.3)
    pass_.SetKernelSize(64)
    pass_.SetDelegatePass(vtkRenderStepsPass())
    scene.renderer.SetPass(pass_)
    scene.window.Render()


def lit_spheres(scene, opacity=1.0, resolution=32):
    """Two overlapping shiny spheres (with normals) under two scene lights."""
    actors = []
    for center, color in (((-0.25, 0.0, 0.0), (0.9, 0.4, 0.2)), ((0.25, 0.1, 0.2), (0.2, 0.5, 0.9))):
        actor = scene.actor(sphere(resolution, center, 0.45))
        shiny(actor, color).SetOpacity(opacity)
        actors.append(actor)
    two_lights(scene.renderer)
    return actors


def depth_peeling(scene):
    scene.window.SetAlphaBitPlanes(1)
    scene.renderer.SetUseDepthPeeling(1)
    scene.renderer.SetMaximumNumberOfPeels(8)
    scene.renderer.SetOcclusionRatio(0.0)
    lit_spheres(scene, 0.5)
    finish(scene)


def translucency_oit(scene):
    lit_spheres(scene, 0.5)
    finish(scene)


def fxaa(scene):
    scene.renderer.UseFXAAOn()
    lit_spheres(scene, resolution=12)
    finish(scene)


def with_pass(scene, make_pass):
    pass_ = make_pass()
    pass_.SetDelegatePass(vtkRenderStepsPass())
    scene.renderer.SetPass(pass_)


def ssaa(scene):
    with_pass(scene, vtkSSAAPass)
    lit_spheres(scene, resolution=12)
    finish(scene)


def tone_mapping(scene):
    def tone():
        made = vtkToneMappingPass()
        made.SetToneMappingType(vtkToneMappingPass.GenericFilmic)
        return made
    with_pass(scene, tone)
    for light in (lit_spheres(scene) and scene.renderer.GetLights()):
        light.SetIntensity(3.0)
    finish(scene)


def clipping_planes(scene):
    for actor in lit_spheres(scene):
        plane = vtkPlane()
        plane.SetNormal(0.3, -1.0, 0.2)
        actor.GetMapper().AddClippingPlane(plane)
    finish(scene)


def large_coordinates(scene):
    """Far from the origin: VTK shifts and scales the vertex buffer and the camera."""
    offset = (2.0e6, -1.0e6, 3.0e6)
    for center, color in (((-0.25, 0.0, 0.0), (0.9, 0.4, 0.2)), ((0.25, 0.1, 0.2), (0.2, 0.5, 0.9))):
        moved = [c + o for c, o in zip(center, offset)]
        shiny(scene.actor(sphere(32, moved, 0.45)), color)
    for position, color in (((1.0, 1.0, 1.0), (1.0, 0.85, 0.7)), ((-1.0, 0.5, 0.3), (0.35, 0.5, 1.0))):
        light = scene_light(scene.renderer, [p + o for p, o in zip(position, offset)], color)
        light.SetFocalPoint(*offset)
    finish(scene)


def glyphs(scene):
    """vtkGlyph3DMapper draws with VTK's glyph helper, which the switch does not replace."""
    mapper = vtkGlyph3DMapper()
    centers = vtkRegularPolygonSource()
    centers.SetNumberOfSides(6)
    centers.SetRadius(0.6)
    mapper.SetInputConnection(centers.GetOutputPort())
    glyph = sphere(16, radius=0.2)  # kept: an output port does not keep its algorithm alive
    mapper.SetSourceConnection(glyph.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    shiny(actor)
    scene.renderer.AddActor(actor)
    scene.actor(sphere(32, radius=0.3))  # and one polydata mapper, lit by vtkPhong
    two_lights(scene.renderer)
    finish(scene)


def helix():
    source = vtkParametricFunctionSource()
    spiral = vtkParametricSpline()
    points = vtkPoints()
    for i in range(40):
        angle = 0.35 * i
        points.InsertNextPoint(0.5 * math.cos(angle), -0.6 + 0.03 * i, 0.5 * math.sin(angle))
    spiral.SetPoints(points)
    source.SetParametricFunction(spiral)
    source.SetUResolution(200)
    return source


def lines_as_tubes(scene):
    prop = shiny(scene.actor(helix()))
    prop.SetLineWidth(8.0)
    prop.RenderLinesAsTubesOn()
    two_lights(scene.renderer)
    finish(scene)


def points_as_spheres(scene):
    prop = shiny(scene.actor(sphere(12)))
    prop.SetRepresentationToPoints()
    prop.SetPointSize(10.0)
    prop.RenderPointsAsSpheresOn()
    two_lights(scene.renderer)
    finish(scene)


def light_kit(scene):
    lit_spheres(scene)
    scene.renderer.RemoveAllLights()
    vtkLightKit().AddLightsToRenderer(scene.renderer)
    finish(scene)


def stereo_split(scene):
    scene.window.SetStereoTypeToSplitViewportHorizontal()
    scene.window.StereoRenderOn()
    lit_spheres(scene)
    finish(scene)


def stereo_off_axis(scene):
    lit_spheres(scene)
    scene.renderer.ResetCamera()
    camera = scene.renderer.GetActiveCamera()
    camera.UseOffAxisProjectionOn()
    camera.SetScreenBottomLeft(-0.6, -0.6, -1.0)
    camera.SetScreenBottomRight(0.6, -0.6, -1.0)
    camera.SetScreenTopRight(0.6, 0.6, -1.0)
    camera.SetEyePosition((0.1, 0.1, 2.0))
    scene.renderer.ResetCameraClippingRange()
    scene.window.Render()


def srgb(scene):
    scene.window.SetUseSRGBColorSpace(True)
    lit_spheres(scene)
    finish(scene)


def camera_over(*steps):
    """A camera pass over the sequence of `steps`, as VTK's tests build their pipelines."""
    passes = vtkRenderPassCollection()
    for step in steps:
        passes.AddItem(step)
    sequence = vtkSequencePass()
    sequence.SetPasses(passes)
    camera = vtkCameraPass()
    camera.SetDelegatePass(sequence)
    return camera


def point_fill(scene):
    """vtkPointFillPass between a camera pass and the render steps, as VTK's test has it."""
    scene.window.SetAlphaBitPlanes(1)
    fill = vtkPointFillPass()
    fill.SetDelegatePass(vtkRenderStepsPass())
    camera = vtkCameraPass()
    camera.SetDelegatePass(fill)
    scene.renderer.SetPass(camera)
    prop = shiny(scene.actor(sphere(40)))
    prop.SetRepresentationToPoints()
    prop.SetPointSize(2.0)
    two_lights(scene.renderer)
    finish(scene)


def edge_flags(scene):
    """Surface with edges where a point-data edge flag hides some edges."""
    plane = vtkPlaneSource()
    plane.SetResolution(5, 5)
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(plane.GetOutputPort())
    triangles.Update()
    data = triangles.GetOutput()
    flags = vtkUnsignedCharArray()
    flags.SetName("edge flags")
    for i in range(data.GetNumberOfPoints()):
        flags.InsertNextValue(i % 3 != 0)
    data.GetPointData().AddArray(flags)
    data.GetPointData().SetActiveAttribute("edge flags", vtkDataSetAttributes.EDGEFLAG)
    mapper = scene.mapper()
    mapper.SetInputData(data)
    actor = vtkActor()
    actor.SetMapper(mapper)
    prop = shiny(actor)
    prop.EdgeVisibilityOn()
    prop.SetEdgeColor(0.1, 0.2, 0.9)
    prop.SetLineWidth(2.0)
    scene.renderer.AddActor(actor)
    scene_light(scene.renderer, (0.3, 0.5, 1.0))
    finish(scene)


def lighting_map_normals(scene):
    normals = vtkLightingMapPass()
    normals.SetRenderType(vtkLightingMapPass.NORMALS)
    scene.renderer.SetPass(camera_over(vtkLightsPass(), normals))
    lit_spheres(scene)
    finish(scene)


def wireframe_without_normals(scene):
    """Triangles drawn as lines, input without normals: stock lights them with per-fragment
    screen-space normals, vtkPhong with the normals it computes."""
    source = sphere(16)
    source.Update()
    data = source.GetOutput()
    data.GetPointData().SetNormals(None)
    mapper = scene.mapper()
    mapper.SetInputData(data)
    actor = vtkActor()
    actor.SetMapper(mapper)
    shiny(actor).SetRepresentationToWireframe()
    scene.renderer.AddActor(actor)
    two_lights(scene.renderer)
    finish(scene)


def cone_source(resolution):
    cone = vtkConeSource()
    cone.SetResolution(resolution)
    cone.SetDirection(0.0, 1.0, 0.0)
    cone.SetHeight(1.2)
    cone.SetRadius(0.5)
    cone.CappingOff()
    return cone


def cone(scene):
    """A cone without normals: stock VTK shades its faces flat, vtkPhong smoothly with the
    normals it computes; at the apex each face keeps its own normal."""
    source = cone_source(48)  # kept: an output port does not keep its algorithm alive
    shiny(scene.actor(source))
    two_lights(scene.renderer)
    scene.renderer.GetActiveCamera().Elevation(15.0)
    finish(scene)


def apex_normals():
    """The normals vtkOpenMeshNormals gives a cone's apex: one per face, none along the axis
    (the mean of the faces' normals, which would light the tip as a flat top)."""
    source = cone_source(48)
    normals = vtkOpenMeshNormals()
    normals.SetInputConnection(source.GetOutputPort())
    normals.Update()
    output = normals.GetOutput()
    apex = [i for i in range(output.GetNumberOfPoints()) if output.GetPoint(i)[1] > 0.59]
    along_axis = max(output.GetPointData().GetNormals().GetTuple3(i)[1] for i in apex)
    checks.expect(len(apex) == 48 and along_axis < 0.5,
                  "the cone's apex is split per face (%d points, largest axial component "
                  "%.2f)" % (len(apex), along_axis))
    print("| cone apex normals (vtkOpenMeshNormals) | - | - | - | %d points, axial component "
          "<= %.2f |" % (len(apex), along_axis))


CASES = [
    # name, scene, expectation: "match", "match, unlit" (stock VTK does not light it), or
    # (reason, the most pixels over the threshold)
    ("user //VTK::Light::Impl replacement", light_replacement, "match"),
    ("the same, vtkPhongPolyDataMapper named", light_replacement_direct, "match"),
    ("the same, replaced after VTK's substitutions", light_replacement_after, "match"),
    ("the same, composite mapper", light_replacement_composite, "match"),
    ("surface with edges", surface_with_edges, "match"),
    ("surface with edges, Ambient 0.3", surface_with_edges_ambient, "match"),
    ("surface with edges as tubes", surface_with_edges_tubes, "match"),
    ("surface with edges, composite mapper", edges_composite, "match"),
    ("block colours, composite mapper", block_colours_composite, "match"),
    ("a hidden block, composite mapper", hidden_block_composite, "match"),
    ("vertex visibility", vertex_visibility, "match"),
    ("points and lines of input without normals", points_and_lines, "match"),
    ("surface without normals as points", points_representation, "match, unlit"),
    ("coincident topology (wireframe over surface)", coincident_topology, "match"),
    ("vtkShadowMapPass, two spot lights", shadows_spots, "match"),
    ("vtkShadowMapPass, two directional lights", shadows_directional, "match"),
    ("vtkShadowMapPass, spot, switched-off and directional", shadows_mixed,
     ("stock VTK pairs the pass's factor of the i-th light of the renderer with its i-th "
      "switched-on light: past a switched-off light, a light loses its shadow", 1900)),
    ("vtkShadowMapPass, composite mapper", shadows_composite, "match"),
    ("vtkShadowMapPass, directional lights, error budget 2 levels", shadows_budget, "match"),
    ("vtkSSAOPass", ssao, "match"),
    ("depth peeling", depth_peeling, "match"),
    ("translucency without depth peeling (OIT)", translucency_oit, "match"),
    ("FXAA", fxaa, "match"),
    # Supersampled, the pixels along the coarse spheres' silhouette edges where stock VTK's
    # back faces win the depth test by rounding add up to a visible line (29 pixels): vtkPhong
    # culls those hidden back faces, and matches stock VTK told to cull them itself.
    ("vtkSSAAPass", ssaa, "match, back faces culled"),
    ("vtkToneMappingPass (HDR)", tone_mapping, "match"),
    ("clipping planes", clipping_planes, "match"),
    ("large coordinates (shift and scale)", large_coordinates, "match"),
    ("glyph mapper", glyphs, "match"),
    ("lines as tubes", lines_as_tubes, "match"),
    ("points as spheres", points_as_spheres, "match"),
    ("vtkLightKit", light_kit, "match"),
    ("stereo, split viewport", stereo_split, "match"),
    ("off-axis projection", stereo_off_axis, "match"),
] + ([] if VTK_9_3 else [
    # VTK 9.3 asks X for an sRGB-capable visual, which Xvfb lacks: stock VTK aborts there.
    ("sRGB window", srgb, "match"),
]) + [
    ("vtkPointFillPass", point_fill, "match"),
    ("surface with edges and edge flags", edge_flags, "match"),
    ("vtkLightingMapPass, normals", lighting_map_normals, "match, unlit"),
    ("vtkLightingMapPass, luminance", lighting_map_luminance, "match, unlit"),
    ("cone without normals", cone,
     ("computed smooth normals where stock shades each face flat", 800)),
    ("wireframe of input without normals", wireframe_without_normals,
     ("computed smooth normals where stock lights each fragment with screen-space normals",
      4500)),
]


def gl_errors(window):
    """The OpenGL errors pending in the window's context (glGetError, through ctypes)."""
    window.MakeCurrent()
    errors = []
    while len(errors) < 16:
        error = GL.glGetError()
        if error == 0:
            break
        errors.append(hex(error))
    return errors


def render(build, phong, cull_back_faces=False):
    """The picture of one case, and the class names of the mappers it made. With
    `cull_back_faces`, every actor culls its back faces (VTK's own vtkProperty setting)."""
    if phong:
        vtkphong.overrides.enable()
    else:
        vtkphong.overrides.disable()
    # A case may set VTK's global coincident-topology mode; the next cases must not inherit
    # it (VTK 9.3's tube imposters then read gl_FragDepth before writing it, and their
    # pictures depend on how each shader happens to compile).
    coincident = vtkMapper.GetResolveCoincidentTopology()
    scene = Scene(phong)
    build(scene)
    if cull_back_faces:
        for actor in scene.renderer.GetActors():
            actor.GetProperty().BackfaceCullingOn()
        scene.window.Render()
    if phong and OPTIONS.depth_prepass:
        for mapper in scene.mappers:
            if hasattr(mapper, "SetDepthPrePass"):
                mapper.SetDepthPrePass(vtkPhongPolyDataMapper.DepthPrePassOn)
        # Occlusion culling leaves hidden clusters out of the depth pass once their counts
        # are in (a frame later): the picture compared is the fourth frame.
        for _ in range(3):
            scene.window.Render()
    pixels, _ = snapshot(scene.window)
    PREPASS_CASES.update(build.__name__ for m in scene.mappers
                         if phong and hasattr(m, "GetUsedDepthPrePass") and m.GetUsedDepthPrePass())
    CULLED_CASES.update(build.__name__ for m in scene.mappers
                        if phong and hasattr(m, "GetDepthPassTriangles") and m.GetInput()
                        and 0 < m.GetDepthPassTriangles() < m.GetInput().GetNumberOfPolys())
    CLOSED_SURFACE_CASES.update(build.__name__ for m in scene.mappers
                                if phong and hasattr(m, "GetUsedClosedSurfaceCulling")
                                and m.GetUsedClosedSurfaceCulling())
    errors = gl_errors(scene.window)
    checks.expect(not errors, "%s drew with no OpenGL error (%s)"
                  % ("vtkPhong" if phong else "stock VTK", errors))
    vtkMapper.SetResolveCoincidentTopology(coincident)
    names = sorted({m.GetClassName() for m in scene.mappers})
    # Whether vtkPhong's lighting drew (not its fallback to VTK's): a signature is set. The
    # signature is the last draw's. From VTK 9.4 on, an actor's vertices are a draw of their
    # own, unlit by stock VTK and so by vtkPhong: the surface is drawn again without them.
    vertex_actors = [a for a in scene.renderer.GetActors()
                     if a.GetProperty().GetVertexVisibility()]
    for actor in vertex_actors:
        actor.GetProperty().VertexVisibilityOff()
    if vertex_actors:
        scene.window.Render()
    lit = all(m.GetLastShaderSignature() for m in scene.mappers
              if hasattr(m, "GetLastShaderSignature"))
    scene.window.Finalize()
    return pixels, names, lit


def difference(stock, phong):
    levels = numpy.abs(stock - phong).max(axis=2)
    return {"max": int(levels.max()), "mean": float(levels.mean()),
            "over": int((levels > STRICT_LEVELS).sum())}


def save(pixels, path):
    """Both pictures of a case side by side, for a reviewer."""
    image = vtkImageData()
    height, width, _ = pixels.shape
    image.SetDimensions(width, height, 1)
    image.GetPointData().SetScalars(numpy_to_vtk(pixels.reshape(-1, 3).astype(numpy.uint8)))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def run_case(name, build, expectation):
    culled = expectation == "match, back faces culled"
    stock, stock_mappers, _ = render(build, False, cull_back_faces=culled)
    phong, phong_mappers, lit = render(build, True)
    if culled:
        checks.expect(build.__name__ in CLOSED_SURFACE_CASES,
                      "%s: vtkPhong culled the closed surfaces' back faces" % name)
        plain = difference(render(build, False)[0], phong)
        print("(%s: %d pixels over %d levels against stock VTK drawing the back faces)"
              % (name, plain["over"], STRICT_LEVELS))
    if OPTIONS.temporary:
        slug = "".join(c if c.isalnum() else "_" for c in name)[:40]
        save(numpy.hstack((stock, phong)), os.path.join(
            OPTIONS.temporary, "TestPhongStockFeatures_%s.png" % slug))
    unlit = expectation == "match, unlit"  # stock VTK draws it unlit, and so does vtkPhong
    checks.expect(lit != unlit, "%s: vtkPhong lights it (not its fallback) exactly where "
                  "stock VTK does" % name)
    expectation = "match" if unlit or culled else expectation
    checks.expect(all("Phong" not in n for n in stock_mappers),
                  "%s: the stock run used VTK's mappers %s" % (name, stock_mappers))
    checks.expect(phong_mappers and all("Phong" in n for n in phong_mappers),
                  "%s: the switched run used vtkPhong's mappers %s" % (name, phong_mappers))
    checks.expect(phong.max() > 0, "%s: vtkPhong drew something" % name)
    measured = difference(stock, phong)
    if expectation == "match":
        checks.expect(measured["over"] <= STRICT_PIXEL_BUDGET,
                      "%s: matches stock (%d pixels over %d levels)"
                      % (name, measured["over"], STRICT_LEVELS))
        why = "matches"
    else:
        why, budget = expectation
        checks.expect(0 < measured["over"] <= budget, "%s: the difference shows, within %d "
                      "pixels (%d)" % (name, budget, measured["over"]))
    print("| %s | %d | %.2f | %.1f %% | %s |" % (name, measured["max"], measured["mean"],
                                                100.0 * measured["over"] / SIZE / SIZE, why))


def broken_replacement(composite):
    """A replacement that does not compile, for stock VTK either (VTK 9.1 then dereferences
    the null program and crashes): vtkPhong reports it and draws without it."""
    captured = vtkStringOutputWindow()
    previous = vtkOutputWindow.GetInstance()
    vtkOutputWindow.SetInstance(captured)
    verbosity = vtkLogger.GetCurrentVerbosityCutoff()
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
    try:
        vtkphong.overrides.enable()
        scene = Scene(True)
        if composite:
            blocks = vtkMultiBlockDataSet()
            source = sphere(32)
            source.Update()
            blocks.SetBlock(0, source.GetOutput())
            mapper = composite_mapper()
            mapper.SetInputDataObject(blocks)
            actor = vtkActor()
            actor.SetMapper(mapper)
            scene.renderer.AddActor(actor)
        else:
            actor = scene.actor(sphere())
        actor.GetShaderProperty().AddFragmentShaderReplacement(
            "//VTK::Light::Impl", True, BROKEN, False)
        two_lights(scene.renderer)
        finish(scene)
        scene.window.Render()
        pixels, _ = snapshot(scene.window)
        scene.window.Finalize()
    finally:
        vtkLogger.SetStderrVerbosity(verbosity)
        vtkOutputWindow.SetInstance(previous)
    log = captured.GetOutput()
    what = "composite" if composite else "polydata"
    checks.expect("fail to compile with VTK's own lighting too" in log,
                  "%s: the broken replacement is reported" % what)
    checks.expect(pixels.max() > 0, "%s: the primitive is still drawn, without it" % what)
    print("| broken //VTK::Light::Impl replacement, %s mapper | - | - | - | no crash (stock "
          "VTK 9.1 crashes); drawn without the replacement, with an error |" % what)


def selected_ids(phong, field):
    """The ids vtkHardwareSelector finds over the whole window, on a cube without normals
    (vtkPhong splits its points at the edges: ids must still be the input's)."""
    if phong:
        vtkphong.overrides.enable()
    else:
        vtkphong.overrides.disable()
    scene = Scene(phong)
    cube = vtkCubeSource()
    merged = vtkCleanPolyData()  # 8 shared corners, which vtkPhong's normals split
    merged.SetInputConnection(cube.GetOutputPort())
    merged.Update()
    data = merged.GetOutput()
    data.GetPointData().SetNormals(None)
    mapper = scene.mapper()
    mapper.SetInputData(data)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.RotateX(30.0)
    actor.RotateY(40.0)
    scene.renderer.AddActor(actor)
    finish(scene)
    selector = vtkHardwareSelector()
    selector.SetRenderer(scene.renderer)
    selector.SetArea(0, 0, SIZE - 1, SIZE - 1)
    selector.SetFieldAssociation(field)
    selection = selector.Select()
    ids = set()
    for n in range(selection.GetNumberOfNodes()):
        found = selection.GetNode(n).GetSelectionList()
        ids.update(int(found.GetTuple1(i)) for i in range(found.GetNumberOfTuples()))
    scene.window.Finalize()
    return sorted(ids), mapper.GetClassName()


def selection():
    for field, what in ((vtkDataObject.FIELD_ASSOCIATION_CELLS, "cell"),
                        (vtkDataObject.FIELD_ASSOCIATION_POINTS, "point")):
        stock, _ = selected_ids(False, field)
        phong, name = selected_ids(True, field)
        checks.expect(name == "vtkPhongPolyDataMapper", "selection drew with vtkPhong: " + name)
        checks.expect(stock and stock == phong and max(stock) < 8, "hardware selection of %s ids: stock %s, "
                      "vtkPhong %s" % (what, stock, phong))
        print("| hardware selection, %s ids (normals split) | - | - | - | %s |"
              % (what, "the same ids" if stock == phong else "DIFFERENT ids"))


def options():
    parser = argparse.ArgumentParser()
    parser.add_argument("-B", dest="baselines")
    parser.add_argument("-T", dest="temporary")
    parser.add_argument("--depth-prepass", action="store_true",
                        help="vtkPhong's mappers draw with the depth pre-pass on")
    parser.add_argument("cases", nargs="*", help="run only the cases whose names hold these")
    return parser.parse_args()


OPTIONS = options()
PREPASS_CASES = set()  # the cases where a mapper drew with the depth pre-pass
CULLED_CASES = set()  # those where its depth pass left hidden triangles out
CLOSED_SURFACE_CASES = set()  # those where a mapper culled a closed surface's back faces


def main():
    shared_display(vtkRenderWindow())
    wanted = OPTIONS.cases
    print("| case | max | mean | pixels > %d levels | result |" % STRICT_LEVELS)
    print("|---|---|---|---|---|")
    for name, build, expectation in CASES:
        if not wanted or any(w in name for w in wanted):
            run_case(name, build, expectation)
    if not wanted or "apex" in wanted:
        apex_normals()
    if not wanted or "selection" in wanted:
        selection()
    if not wanted or "broken" in wanted:
        broken_replacement(False)
        broken_replacement(True)
    print("closed surfaces' back faces culled: %s" % ", ".join(sorted(CLOSED_SURFACE_CASES)))
    checks.expect(wanted or len(CLOSED_SURFACE_CASES) >= 10,
                  "closed surfaces' back faces culled in %d cases" % len(CLOSED_SURFACE_CASES))
    if OPTIONS.depth_prepass:
        print("drawn with the depth pre-pass: %s" % ", ".join(sorted(PREPASS_CASES)))
        print("its depth pass culled: %s" % ", ".join(sorted(CULLED_CASES)))
        checks.expect(wanted or len(PREPASS_CASES) >= 20, "the pre-pass drew in %d cases"
                      % len(PREPASS_CASES))
        checks.expect(wanted or len(CULLED_CASES) >= 10, "its depth pass was culled in %d cases"
                      % len(CULLED_CASES))
    checks.exit()


main()
