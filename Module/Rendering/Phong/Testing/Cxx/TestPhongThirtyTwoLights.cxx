// Thirty-two coloured point lights in a ring around a sphere: each makes its
// own highlight, and none is dropped (stock VTK's uniform-per-light scheme
// needs one declaration each; here they are arrays).

#include "vtkPhongTestUtilities.h"

#include "vtkMath.h"

int TestPhongThirtyTwoLights(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  scene.Renderer->AutomaticLightCreationOff();
  const double origin[3] = { 0.0, 0.0, 0.0 };
  for (int i = 0; i < 32; ++i)
  {
    const double angle = 2.0 * vtkMath::Pi() * i / 32.0;
    const double position[3] = { 1.2 * std::cos(angle), 1.2 * std::sin(angle), 0.9 };
    double hsv[3] = { i / 32.0, 0.8, 1.0 };
    double rgb[3];
    vtkMath::HSVToRGB(hsv, rgb);
    vtkLight* light = vtkPhongTest::AddLight(scene, position, origin, rgb, true);
    light->SetConeAngle(180.0);
    light->SetIntensity(0.18);
  }
  vtkNew<vtkPhongProperty> material;
  material->SetColor(1.0, 1.0, 1.0);
  material->SetAmbient(0.0);
  material->SetDiffuse(0.6);
  material->SetSpecular(1.0);
  material->SetShininess(400.0);
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(
    vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(160), material)->GetMapper());
  scene.LookFromZ(2.2);
  scene.Window->Render();

  vtkPhongTest::Checks checks;
  const std::string signature = mapper->GetLastShaderSignature();
  checks.Expect(signature.find("point 32") != std::string::npos, "32 point lights: " + signature);
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
