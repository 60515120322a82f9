"""The one switch: after `import vtkphong.overrides`, a script that never names vtkPhong
(a PyVista-style scene: a vtkPolyDataMapper it builds itself, SetInterpolationToPhong,
vtkLightKit) draws with vtkPhong's mapper; code asking the factory for VTK's OpenGL or
composite mapper by name gets vtkPhong's; the switch turns off and on at run time, and
objects made before it keep their class."""

from vtkmodules.vtkCommonCore import vtkObjectFactory, vtkVersion
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLightKit, vtkPolyDataMapper,
                                         vtkRenderWindow, vtkRenderer,
                                         vtkWindowToImageFilter)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkphong_testing import Checks

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (as any rendering script imports it)

# VTK 9.3 draws composite data with vtkCompositePolyDataMapper, before with ...2.
VTK_9_3 = (vtkVersion.GetVTKMajorVersion(), vtkVersion.GetVTKMinorVersion()) >= (9, 3)
COMPOSITE = "vtkCompositePolyDataMapper" if VTK_9_3 else "vtkCompositePolyDataMapper2"

checks = Checks()


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
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(120, 120)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    return mapper, vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(int)


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

# No light switched on: unlit, exactly as VTK draws it (not black, not emission and ambient).
mapper, unlit = unmodified_script(lights=False)
checks.expect(mapper.GetClassName() == "vtkPhongPolyDataMapper", "no lights: vtkPhong's mapper")

vtkphong.overrides.disable()
stock_mapper, stock_unlit = unmodified_script(lights=False)
checks.expect(stock_mapper.GetClassName() == "vtkOpenGLPolyDataMapper", "VTK's mapper to compare")
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
