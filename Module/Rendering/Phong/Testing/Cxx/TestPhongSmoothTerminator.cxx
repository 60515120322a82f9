// The smooth terminator option: a broad highlight from a light behind and to
// the side is cut off sharply where N.L crosses 0 with the step gate (left);
// with max(N.L, 0) as the gate (right) it fades out at the shadow line.

#include "vtkPhongTestUtilities.h"

int TestPhongSmoothTerminator(int argc, char* argv[])
{
  vtkPhongTest::Scene scene(400, 240);
  scene.Renderer->AutomaticLightCreationOff();
  const double behind[3] = { 1.0, 0.3, -0.4 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  vtkPhongTest::AddLight(scene, behind, origin, white, false);
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkPhongProperty> material;
    material->SetColor(0.7, 0.7, 0.75);
    material->SetAmbient(0.1);
    material->SetDiffuse(0.4);
    material->SetSpecular(0.9);
    material->SetShininess(3.0);
    material->SetSmoothTerminator(i == 1);
    vtkActor* actor = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(128, 0.45), material);
    actor->SetPosition(i == 0 ? -0.55 : 0.55, 0.0, 0.0);
  }
  scene.LookFromZ(3.3);
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
