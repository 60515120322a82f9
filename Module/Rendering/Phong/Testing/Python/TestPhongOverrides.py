"""The one switch: after `import vtkphong.overrides`, a script that never names vtkPhong
(a PyVista-style scene: a vtkPolyDataMapper it builds itself, SetInterpolationToPhong,
vtkLightKit) draws with vtkPhong's mapper; code asking the factory for VTK's OpenGL or
composite mapper by name gets vtkPhong's; the switch turns off and on at run time, and
objects made before it keep their class. Mappers made through it start from the factory
defaults (vtkphong.overrides.defaults(), VTKPHONG_ERROR_BUDGET)."""

import os
import subprocess
import sys

from vtkmodules.vtkCommonCore import vtkObjectFactory, vtkVersion
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkImagingSources import vtkImageCanvasSource2D
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLightKit, vtkPolyDataMapper,
                                         vtkRenderWindow, vtkRenderer, vtkTexture,
                                         vtkWindowToImageFilter)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkphong_testing import Checks

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (as any rendering script imports it)

# VTK 9.3 draws composite data with vtkCompositePolyDataMapper, before with ...2.
VTK_9_3 = (vtkVersion.GetVTKMajorVersion(), vtkVersion.GetVTKMinorVersion()) >= (9, 3)
COMPOSITE = "vtkCompositePolyDataMapper" if VTK_9_3 else "vtkCompositePolyDataMapper2"

checks = Checks()

# One window for every scene: Xvfb in this project's sandboxes refuses some connections made
# right after another closed (see vtkPhongSharedDisplay.h).
WINDOW = vtkRenderWindow()
WINDOW.SetOffScreenRendering(1)


def picture_of(renderer, width, height):
    """Render `renderer` alone in the shared window; its pixels."""
    previous = WINDOW.GetRenderers().GetFirstRenderer()
    if previous is not None:
        WINDOW.RemoveRenderer(previous)
    WINDOW.SetSize(width, height)
    WINDOW.AddRenderer(renderer)
    renderer.ResetCamera()
    WINDOW.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(WINDOW)
    grab.ReadFrontBufferOff()
    grab.Update()
    return vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(int)


def composite_mapper_class():
    """VTK's own composite mapper class (vtkRenderingCore's from 9.3, OpenGL2's before)."""
    import vtkmodules.vtkRenderingOpenGL2 as opengl2
    import vtkmodules.vtkRenderingCore as core
    return getattr(core, COMPOSITE, None) or getattr(opengl2, COMPOSITE)


def composite_by_name():
    """PyVista's add_composite: VTK's own composite mapper made by its class name, two blocks,
    a renderer ambient light stock VTK ignores and vtkPhong adds (docs/compatibility.md)."""
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
    mapper_class = composite_mapper_class()
    blocks = vtkMultiBlockDataSet()
    for index, centre in enumerate(((-0.6, 0, 0), (0.6, 0, 0))):
        sphere = vtkSphereSource()
        sphere.SetCenter(*centre)
        sphere.SetRadius(0.5)
        sphere.Update()
        blocks.SetBlock(index, sphere.GetOutput())
    mapper = mapper_class()
    mapper.SetInputDataObject(blocks)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetAmbient(0.4)
    renderer = vtkRenderer()
    renderer.SetAmbient(0.3, 0.3, 0.6)
    renderer.AddActor(actor)
    return mapper, picture_of(renderer, 120, 80)



def unmodified_script(lights=True):
    """What a PyVista user's code does, with no vtkPhong name in it; without lights, as
    PyVista's lighting=None or remove_all_lights() leaves the renderer (a colour map's true
    colours). Returns the mapper and the picture."""
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(48)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(sphere.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetInterpolationToPhong()
    actor.GetProperty().SetSpecular(0.5)
    actor.GetProperty().SetSpecularPower(30.0)
    actor.GetProperty().SetColor(0.2, 0.6, 0.9)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    if lights:
        vtkLightKit().AddLightsToRenderer(renderer)
    else:
        renderer.AutomaticLightCreationOff()
    return mapper, picture_of(renderer, 120, 120)


def textured_unlit():
    """PyVista's Texture.plot() and lighting=False: a textured plane whose actor has lighting
    off (drawn black through the switch on VTK 9.6 once). Returns the mapper and picture."""
    image = vtkImageCanvasSource2D()
    image.SetScalarTypeToUnsignedChar()
    image.SetNumberOfScalarComponents(3)
    image.SetExtent(0, 63, 0, 63, 0, 0)
    image.SetDrawColor(200, 40, 40)
    image.FillBox(0, 63, 0, 63)
    image.SetDrawColor(40, 200, 40)
    image.FillBox(0, 31, 0, 31)
    texture = vtkTexture()
    texture.SetInputConnection(image.GetOutputPort())
    plane = vtkPlaneSource()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(plane.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.SetTexture(texture)
    actor.GetProperty().LightingOff()
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    vtkLightKit().AddLightsToRenderer(renderer)
    return mapper, picture_of(renderer, 100, 100)


before = vtkPolyDataMapper()
checks.expect(before.GetClassName() == "vtkOpenGLPolyDataMapper",
              "without the switch VTK's own mapper: " + before.GetClassName())

import vtkphong.overrides  # noqa: E402 (the switch is the point of the test)

checks.expect(vtkphong.overrides.enabled(), "the import turns the switch on")
checks.expect(vtkPolyDataMapper().GetClassName() == "vtkPhongPolyDataMapper",
              "vtkPolyDataMapper() is vtkPhong's")
# Concrete OpenGL classes are made with `new` by their own New(); code that asks the
# factory for them by name (ParaView's proxies, vtkObjectFactory::CreateInstance) is
# answered.
for name, phong in (("vtkOpenGLPolyDataMapper", "vtkPhongPolyDataMapper"),
                    (COMPOSITE, "vtkPhongCompositePolyDataMapper")):
    made = vtkObjectFactory.CreateInstance(name)
    checks.expect(made is not None and made.GetClassName() == phong,
                  "asked for %s by name, the factory gives %s"
                  % (name, made.GetClassName() if made else None))
checks.expect(before.GetClassName() == "vtkOpenGLPolyDataMapper",
              "a mapper made before the switch keeps its class")

mapper, picture = unmodified_script()
brightest = int(picture.max())
checks.expect(mapper.GetClassName() == "vtkPhongPolyDataMapper",
              "the unmodified script's mapper is " + mapper.GetClassName())
signature = mapper.GetLastShaderSignature() if hasattr(mapper, "GetLastShaderSignature") else ""
checks.expect("DIRECTIONAL" in signature and "SPECULAR" in signature,
              "it drew with vtkPhong's shader, the light kit's lights directional: " + signature)
checks.expect(brightest > 100, "something lit is on screen (brightest %d)" % brightest)

# VTK's own composite mapper, made by name: from VTK 9.3 on its delegators come from the
# factory, so its blocks light with vtkPhong; VTK 9.1's never ask (documented).
composite, switched = composite_by_name()
checks.expect(composite.GetClassName() == COMPOSITE, "made by name, the class is VTK's")

# No light switched on: unlit, exactly as VTK draws it (not black, not emission and ambient).
mapper, unlit = unmodified_script(lights=False)
checks.expect(mapper.GetClassName() == "vtkPhongPolyDataMapper", "no lights: vtkPhong's mapper")

texture_mapper, textured = textured_unlit()
checks.expect(texture_mapper.GetClassName() == "vtkPhongPolyDataMapper",
              "textured, lighting off: vtkPhong's mapper")

vtkphong.overrides.disable()
_, stock_textured = textured_unlit()
texture_difference = int(abs(textured - stock_textured).max())
checks.expect(texture_difference <= 1 and int(textured.max()) >= 190,
              "textured, lighting off: the texture's colours as stock VTK draws them (largest "
              "difference %d, brightest %d)" % (texture_difference, int(textured.max())))
stock_mapper, stock_unlit = unmodified_script(lights=False)
checks.expect(stock_mapper.GetClassName() == "vtkOpenGLPolyDataMapper", "VTK's mapper to compare")
_, stock_composite = composite_by_name()
composite_difference = int(abs(switched - stock_composite).max())
if VTK_9_3:
    checks.expect(composite_difference > 8, "VTK's composite mapper lights its blocks with "
                  "vtkPhong through the switch (renderer ambient: %d levels)" % composite_difference)
else:
    checks.expect(composite_difference <= 1, "VTK 9.1: vtkCompositePolyDataMapper2() made by "
                  "name stays VTK's, as documented (%d levels)" % composite_difference)
difference = int(abs(unlit - stock_unlit).max())
checks.expect(difference <= 1 and int(unlit.max()) > 200,
              "no lights: the colours as stock VTK draws them (largest difference %d, "
              "brightest %d)" % (difference, int(unlit.max())))
checks.expect(not vtkphong.overrides.enabled() and
              vtkPolyDataMapper().GetClassName() == "vtkOpenGLPolyDataMapper",
              "switched off, VTK's mapper again")
vtkphong.overrides.enable()
checks.expect(vtkPolyDataMapper().GetClassName() == "vtkPhongPolyDataMapper",
              "and on again")
checks.expect(vtkPolyData() is not None, "other classes are untouched")


def budget_scene(kind):
    """A 48 x 48 sphere under the light kit, drawn the way a client draws it: `kind` is
    "polydata" (vedo, VTK's examples), "dataset" (PyVista: vtkDataSetMapper, whose polydata
    mapper the factory makes at the first render) or "composite" (PyVista's add_composite).
    Returns the mapper that lights (the dataset mapper's inner one) and the picture."""
    from vtkmodules.vtkRenderingCore import vtkDataSetMapper
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(48)
    if kind == "composite":
        from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
        sphere.Update()
        blocks = vtkMultiBlockDataSet()
        blocks.SetBlock(0, sphere.GetOutput())
        mapper = composite_mapper_class()()
        mapper.SetInputDataObject(blocks)
    else:
        mapper = vtkDataSetMapper() if kind == "dataset" else vtkPolyDataMapper()
        mapper.SetInputConnection(sphere.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetInterpolationToPhong()
    actor.GetProperty().SetSpecular(0.4)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    vtkLightKit().AddLightsToRenderer(renderer)
    picture = picture_of(renderer, 200, 200)
    return (mapper.GetPolyDataMapper() if kind == "dataset" else mapper), picture


def budget_hue(picture):
    """The BudgetUse view's hue over the drawn pixels: "vertex" (orange), "fragment" (blue)."""
    red, blue = picture[:, 0], picture[:, 2]
    orange, bluish = int((red > blue + 20).sum()), int((blue > red + 20).sum())
    return "vertex" if orange > 10 * max(bluish, 1) else "fragment" if bluish > 10 * max(
        orange, 1) else "mixed (%d orange, %d blue)" % (orange, bluish)


# Settings for code that never names vtkPhong's mappers: the factory defaults, copied into
# every mapper made through the switch after they are set, PyVista's and vedo's included. An
# error budget of 100 levels puts this coarse sphere's light sums per vertex (its bound under
# the light kit is about 53 levels); the BudgetUse view shows the mode as a hue (orange per
# vertex, blue per fragment).
made_before = vtkPolyDataMapper()
defaults = vtkphong.overrides.defaults()
checks.expect(defaults.GetClassName() == "vtkPhongLightingSettings" and
              defaults.GetErrorBudget() == 0.0, "the factory defaults start as VTK's defaults")
defaults.SetErrorBudget(100.0)
defaults.SetDebugView(defaults.BudgetUse)
kinds = ["polydata", "dataset"] + (["composite"] if VTK_9_3 else [])
for kind in kinds:
    mapper, picture = budget_scene(kind)
    checks.expect(mapper.GetClassName() == "vtkPhongPolyDataMapper" or kind == "composite",
                  "%s: the mapper that lights is vtkPhong's (%s)" % (kind, mapper.GetClassName()))
    hue = budget_hue(picture)
    checks.expect(hue == "vertex", "%s: the defaults' error budget reached the mapper, its sums "
                  "per vertex (BudgetUse: %s)" % (kind, hue))
try:  # PyVista itself where it is installed (Debian 13 on): its own Plotter and add_mesh
    import pyvista
except ImportError:
    pyvista = None
if pyvista is not None:
    plotter = pyvista.Plotter(off_screen=True, window_size=(200, 200))
    plotter.add_mesh(pyvista.Sphere(theta_resolution=48, phi_resolution=48),
                     smooth_shading=True, specular=0.4)
    shot = plotter.screenshot(return_img=True).reshape(-1, 3).astype(int)
    plotter.close()
    hue = budget_hue(shot)
    checks.expect(hue == "vertex", "PyVista's add_mesh: the defaults' error budget reached "
                  "its mapper (BudgetUse: %s)" % hue)
checks.expect(made_before.GetErrorBudget() == 0.0,
              "a mapper made before the defaults changed keeps its settings")
defaults.SetErrorBudget(0.0)
defaults.SetDebugView(defaults.Final)
_, exact = budget_scene("polydata")
checks.expect(int(abs(exact[:, 0] - exact[:, 2]).max()) < 60 and int(exact.max()) > 100,
              "defaults set back: the exact mode's shaded picture, not the BudgetUse view")

# The same budget from the environment, for a program that cannot call defaults() (one run
# with VTK_AUTOLOAD_PATH, pvbatch): VTKPHONG_ERROR_BUDGET, read when the defaults are made;
# anything but a number of levels in [0, 255] is reported and left out.
READ_BUDGET = ("import vtkphong.overrides as overrides\n"
               "print('budget', overrides.defaults().GetErrorBudget())\n")
for value, expected in (("1.5", 1.5), (" 2", 2.0), ("255", 255.0), ("", 0.0), ("abc", None),
                        ("-1", None), ("nan", None), ("300", None), ("1.5x", None)):
    run = subprocess.run([sys.executable, "-c", READ_BUDGET], capture_output=True, text=True,
                         timeout=120, env=dict(os.environ, VTKPHONG_ERROR_BUDGET=value))
    budget = [line.split()[1] for line in run.stdout.splitlines() if line.startswith("budget")]
    reported = "VTKPHONG_ERROR_BUDGET" in run.stderr
    checks.expect(run.returncode == 0 and budget == [repr(expected if expected is not None
                                                          else 0.0)] and
                  reported == (expected is None),
                  "VTKPHONG_ERROR_BUDGET=%r: budget %s, reported %s (%r)"
                  % (value, budget, reported, run.stderr[-300:]))

checks.exit()
