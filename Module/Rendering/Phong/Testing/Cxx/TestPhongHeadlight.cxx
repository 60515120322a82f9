// The default scene of every VTK user: one headlight (the light VTK creates)
// on a sphere with a Phong highlight.

#include "vtkPhongTestUtilities.h"

int TestPhongHeadlight(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  vtkNew<vtkPhongProperty> material;
  material->SetColor(0.9, 0.45, 0.2);
  material->SetAmbient(0.1);
  material->SetDiffuse(0.7);
  material->SetSpecular(0.5);
  material->SetShininess(40.0);
  vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(64), material);
  scene.LookFromZ(2.5);
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
