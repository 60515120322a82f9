// A spot light (cone 25 degrees, exponent 4) on a floor: a hard-edged disc
// whose brightness falls as pow(cos phi, 4) away from the axis.

#include "vtkPhongTestUtilities.h"

int TestPhongSpotLight(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  scene.Renderer->AutomaticLightCreationOff();
  const double source[3] = { -0.6, 0.3, 1.6 };
  const double target[3] = { 0.1, -0.1, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  vtkLight* spot = vtkPhongTest::AddLight(scene, source, target, white, true);
  spot->SetConeAngle(25.0);
  spot->SetExponent(4.0);

  vtkNew<vtkPhongProperty> floor;
  floor->SetColor(0.9, 0.9, 0.9);
  floor->SetAmbient(0.1);
  floor->SetSpecular(0.3);
  floor->SetShininess(40.0);
  vtkPhongTest::AddActor(scene, vtkPhongTest::MakePlane(1.5, 60), floor);
  scene.Renderer->SetAmbient(0.2, 0.2, 0.3);
  scene.LookFromZ(4.0);
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
