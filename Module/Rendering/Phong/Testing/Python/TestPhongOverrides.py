"""The one switch: after `import vtkphong.overrides`, a script that never names vtkPhong
(a PyVista-style scene: a vtkPolyDataMapper it builds itself, SetInterpolationToPhong,
vtkLightKit) draws with vtkPhong's mapper; code asking the factory for VTK's OpenGL or
composite mapper by name gets vtkPhong's; the switch turns off and on at run time, and
objects made before it keep their class."""

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


def composite_by_name():
    """PyVista's add_composite: VTK's own composite mapper made by its class name, two blocks,
    a renderer ambient light stock VTK ignores and vtkPhong adds (docs/compatibility.md)."""
    import vtkmodules.vtkRenderingOpenGL2 as opengl2
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
    import vtkmodules.vtkRenderingCore as core
    mapper_class = getattr(core, COMPOSITE, None) or getattr(opengl2, COMPOSITE)
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

checks.exit()
