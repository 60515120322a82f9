// Phong (left) and Blinn-Phong (right) lobes with the same shininess under a
// light at 60 degrees from the view: the Blinn highlight is wider and rounder.

#include "vtkPhongTestUtilities.h"

int TestPhongLobeBlinnPhong(int argc, char* argv[])
{
  vtkPhongTest::Scene scene(400, 240);
  scene.Renderer->AutomaticLightCreationOff();
  const double side[3] = { 1.7, 1.0, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  vtkPhongTest::AddLight(scene, side, origin, white, false);

  const int models[2] = { vtkPhongProperty::Phong, vtkPhongProperty::BlinnPhong };
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkPhongProperty> material;
    material->SetColor(0.6, 0.2, 0.6);
    material->SetAmbient(0.1);
    material->SetDiffuse(0.6);
    material->SetSpecular(0.7);
    material->SetShininess(40.0);
    material->SetLightingModel(models[i]);
    vtkActor* actor = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(96, 0.45), material);
    actor->SetPosition(i == 0 ? -0.55 : 0.55, 0.0, 0.0);
  }
  scene.LookFromZ(3.3);
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
