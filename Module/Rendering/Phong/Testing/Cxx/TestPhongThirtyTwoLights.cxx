// Thirty-two coloured point lights in a ring around a sphere: each makes its
// own highlight, and none is dropped (stock VTK's uniform-per-light scheme
// needs one declaration each; here they are arrays). The light loop is unrolled
// into one block per light (a rolled loop reads its uniform arrays per fragment
// on llvmpipe), up to 64 lights of a kind; beyond, it stays a loop.

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
  const std::string unrolled = mapper->GetLastFragmentShaderSource();
  checks.Expect(unrolled.find("const int i = 31;") != std::string::npos &&
      unrolled.find("for (int i = 0;") == std::string::npos,
    "32 lights: the light loop is unrolled");

  vtkPhongTest::Scene many(16, 16);
  many.Renderer->AutomaticLightCreationOff();
  const double white[3] = { 1.0, 1.0, 1.0 };
  for (int i = 0; i < 65; ++i)
  {
    const double position[3] = { std::cos(0.1 * i), std::sin(0.1 * i), 1.0 };
    vtkPhongTest::AddLight(many, position, origin, white, false)->SetIntensity(0.01);
  }
  auto* manyMapper = vtkPhongPolyDataMapper::SafeDownCast(
    vtkPhongTest::AddActor(many, vtkPhongTest::MakeSphere(8), material)->GetMapper());
  many.Window->Render();
  const std::string rolled = manyMapper->GetLastFragmentShaderSource();
  checks.Expect(rolled.find("for (int i = 0; i < 65; ++i)") != std::string::npos &&
      rolled.find("const int i = ") == std::string::npos,
    "65 lights: the light loop stays a loop");
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
