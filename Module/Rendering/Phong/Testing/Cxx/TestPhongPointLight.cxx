// A point light close above a floor, with (c, l, q) = (1, 0.5, 0.5)
// attenuation: the pool of light fades with distance, and a sphere on the
// floor is lit from above with a highlight.

#include "vtkPhongTestUtilities.h"

int TestPhongPointLight(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  const double above[3] = { 0.3, 0.4, 0.8 };
  const double down[3] = { 0.3, 0.4, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  vtkLight* light = vtkPhongTest::AddLight(scene, above, down, white, true);
  light->SetConeAngle(180.0);
  light->SetAttenuationValues(1.0, 0.5, 0.5);
  light->SetIntensity(1.5);

  vtkNew<vtkPhongProperty> floor;
  floor->SetColor(0.8, 0.8, 0.7);
  floor->SetAmbient(0.05);
  floor->SetSpecular(0.2);
  floor->SetShininess(20.0);
  vtkPhongTest::AddActor(scene, vtkPhongTest::MakePlane(1.5, 60), floor);

  vtkNew<vtkPhongProperty> ball;
  ball->SetColor(0.9, 0.3, 0.2);
  ball->SetSpecular(0.6);
  ball->SetShininess(80.0);
  vtkActor* sphere = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(64, 0.25), ball);
  sphere->SetPosition(-0.2, -0.1, 0.25);

  scene.LookFromZ(4.0);
  scene.Renderer->GetActiveCamera()->Elevation(-35.0);
  scene.Renderer->GetActiveCamera()->OrthogonalizeViewUp();
  scene.Renderer->ResetCameraClippingRange();
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
