// Eight lights of every kind at once: a headlight, a camera light, two
// directional scene lights, two attenuated point lights and two spots, in
// different colours, on a sphere above a floor.

#include "vtkPhongTestUtilities.h"

#include <cstring>

int TestPhongEightLights(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  scene.Renderer->AutomaticLightCreationOff();
  struct LightSpec
  {
    double Position[3];
    double FocalPoint[3];
    double Color[3];
    bool Positional;
    int Type;
    double Cone;
  };
  const LightSpec specs[8] = {
    { { 0, 0, 1 }, { 0, 0, 0 }, { 0.25, 0.25, 0.25 }, false, VTK_LIGHT_TYPE_HEADLIGHT, 30 },
    { { -1, 1, 1 }, { 0, 0, 0 }, { 0.3, 0.3, 0.2 }, false, VTK_LIGHT_TYPE_CAMERA_LIGHT, 30 },
    { { 1, 0.2, 0.5 }, { 0, 0, 0 }, { 0.5, 0.2, 0.2 }, false, VTK_LIGHT_TYPE_SCENE_LIGHT, 30 },
    { { -1, -1, 0.3 }, { 0, 0, 0 }, { 0.2, 0.2, 0.5 }, false, VTK_LIGHT_TYPE_SCENE_LIGHT, 30 },
    { { 0.8, 0.8, 0.6 }, { 0, 0, 0 }, { 1.0, 0.8, 0.2 }, true, VTK_LIGHT_TYPE_SCENE_LIGHT, 180 },
    { { -0.9, 0.5, 0.4 }, { 0, 0, 0 }, { 0.2, 1.0, 0.4 }, true, VTK_LIGHT_TYPE_SCENE_LIGHT, 180 },
    { { 0.6, -1.0, 1.2 }, { 0.6, -0.6, 0 }, { 1.0, 0.3, 1.0 }, true, VTK_LIGHT_TYPE_SCENE_LIGHT,
      20 },
    { { -0.7, -0.7, 1.4 }, { -0.5, -0.6, 0 }, { 0.3, 0.9, 1.0 }, true, VTK_LIGHT_TYPE_SCENE_LIGHT,
      15 },
  };
  for (const auto& spec : specs)
  {
    vtkLight* light = vtkPhongTest::AddLight(
      scene, spec.Position, spec.FocalPoint, spec.Color, spec.Positional, spec.Type);
    light->SetConeAngle(spec.Cone);
    if (spec.Positional)
    {
      light->SetAttenuationValues(1.0, 0.5, 1.5);
    }
  }

  vtkNew<vtkPhongProperty> floor;
  floor->SetColor(0.6, 0.6, 0.6);
  floor->SetAmbient(0.1);
  floor->SetSpecular(0.2);
  floor->SetShininess(20.0);
  vtkPhongTest::AddActor(scene, vtkPhongTest::MakePlane(1.5, 60), floor);

  vtkNew<vtkPhongProperty> ball;
  ball->SetColor(0.9, 0.9, 0.9);
  ball->SetSpecular(0.5);
  ball->SetShininess(50.0);
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(
    vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(96, 0.4), ball)->GetMapper());
  scene.Renderer->GetActors()->GetLastActor()->SetPosition(0.0, 0.0, 0.4);

  scene.LookFromZ(4.5);
  scene.Renderer->GetActiveCamera()->Elevation(-35.0);
  scene.Renderer->GetActiveCamera()->OrthogonalizeViewUp();
  scene.Renderer->ResetCameraClippingRange();
  scene.Window->Render();

  vtkPhongTest::Checks checks;
  const std::string signature = mapper->GetLastShaderSignature();
  checks.Expect(signature.find("directional 4 point 2 spot 2") != std::string::npos,
    "the shader has one loop per kind with 4 directional, 2 point, 2 spot lights: " + signature);
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
