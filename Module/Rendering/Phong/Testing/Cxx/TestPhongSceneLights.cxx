// Two coloured directional scene lights (key and fill) on a sphere: the lights'
// diffuse colours tint their sides, each makes its own Phong highlight.

#include "vtkPhongTestUtilities.h"

int TestPhongSceneLights(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double key[3] = { 1.0, 1.0, 1.0 };
  const double fill[3] = { -1.0, -0.3, 0.6 };
  const double warm[3] = { 1.0, 0.75, 0.5 };
  const double cool[3] = { 0.35, 0.55, 1.0 };
  vtkPhongTest::AddLight(scene, key, origin, warm, false);
  vtkPhongTest::AddLight(scene, fill, origin, cool, false)->SetIntensity(0.7);

  vtkNew<vtkPhongProperty> material;
  material->SetColor(0.85, 0.85, 0.85);
  material->SetAmbient(0.05);
  material->SetDiffuse(0.8);
  material->SetSpecular(0.4);
  material->SetShininess(30.0);
  vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(96), material);
  scene.LookFromZ(2.5);
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
