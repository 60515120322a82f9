"""A ParaView-style script: a sphere under a headlight, a camera light and a
spot, with the Blinn-Phong lobe and a sharp highlight, rendered offscreen and
compared with its baseline; the shader signature names the three kinds."""

import vtkphong
from vtkmodules.vtkFiltersSources import vtkSphereSource, vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkRenderWindow, vtkRenderer
from vtkphong_testing import Checks, arguments, compare_with_baseline

args = arguments()
checks = Checks()

renderer = vtkRenderer()
renderer.AutomaticLightCreationOff()
renderer.SetAmbient(0.3, 0.3, 0.35)

sphere = vtkSphereSource()
sphere.SetThetaResolution(96)
sphere.SetPhiResolution(96)
sphere.SetCenter(0.0, 0.0, 0.5)
floor = vtkPlaneSource()
floor.SetOrigin(-1.5, -1.5, 0.0)
floor.SetPoint1(1.5, -1.5, 0.0)
floor.SetPoint2(-1.5, 1.5, 0.0)
floor.SetResolution(60, 60)

mappers = []
for source, color in ((sphere, (0.2, 0.55, 0.85)), (floor, (0.8, 0.78, 0.7))):
    mapper = vtkphong.vtkPhongPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    material = vtkphong.vtkPhongProperty()
    material.SetColor(*color)
    material.SetAmbient(0.15)
    material.SetSpecular(0.5)
    material.SetLightingModelToBlinnPhong()
    material.SetShininess(300.0)  # beyond vtkProperty's 128
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.SetProperty(material)
    renderer.AddActor(actor)
    mappers.append(mapper)

headlight = vtkLight()
headlight.SetLightTypeToHeadlight()
headlight.SetIntensity(0.4)
camera_light = vtkLight()
camera_light.SetLightTypeToCameraLight()
camera_light.SetPosition(1.0, 1.0, 1.0)
camera_light.SetIntensity(0.5)
spot = vtkLight()
spot.SetPositional(True)
spot.SetPosition(-0.8, 0.6, 2.0)
spot.SetFocalPoint(0.0, 0.0, 0.0)
spot.SetConeAngle(30.0)
spot.SetColor(1.0, 0.85, 0.6)
for light in (headlight, camera_light, spot):
    renderer.AddLight(light)

window = vtkRenderWindow()
window.SetOffScreenRendering(True)
window.SetMultiSamples(0)
window.SetSize(300, 300)
window.AddRenderer(renderer)
camera = renderer.GetActiveCamera()
camera.SetPosition(0.0, -3.2, 2.6)
camera.SetFocalPoint(0.0, 0.0, 0.3)
camera.SetViewUp(0.0, 0.0, 1.0)
renderer.ResetCameraClippingRange()
window.Render()

signature = mappers[0].GetLastShaderSignature()
checks.expect("directional 2 point 0 spot 1" in signature, "two directional, one spot: " + signature)
checks.expect("LOBE_BLINN" in signature, "Blinn-Phong lobe in the signature")
checks.expect(compare_with_baseline(window, "TestPhongPythonRender", args), "matches the baseline")

# Under an error budget the mapper reports what it spent it on: a spot light keeps the sums per
# fragment (positional lights have no per-vertex bound), and the whole shininess 300 is squared.
mappers[0].SetErrorBudget(2.0)
window.Render()
checks.expect(mappers[0].GetBudgetMode() == vtkphong.vtkPhongPolyDataMapper.BudgetPerFragment and
              mappers[0].GetBudgetModeAsString() == "per fragment",
              "budget 2: per fragment, not " + mappers[0].GetBudgetModeAsString())
checks.expect(mappers[0].GetSquaredShininess() == 300 and 0.0 < mappers[0].GetErrorBound() <= 2.0,
              "budget 2: shininess 300 squared (%d), bound %g within it"
              % (mappers[0].GetSquaredShininess(), mappers[0].GetErrorBound()))
mappers[0].SetErrorBudget(0.0)
window.Render()
checks.expect(mappers[0].GetSquaredShininess() == 0 and mappers[0].GetErrorBound() == 0.0,
              "the exact mode squares nothing and spends nothing")
checks.exit()
