// A light whose ambient, diffuse and specular colours differ (red, green,
// blue), each with its own meaning, where stock VTK uses the diffuse colour for
// everything: a red-tinted ambient floor, a green body, a blue highlight.

#include "vtkPhongTestUtilities.h"

int TestPhongLightColors(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  scene.Renderer->AutomaticLightCreationOff();
  scene.Renderer->SetAmbient(0.0, 0.0, 0.0);
  const double source[3] = { 1.0, 1.0, 2.0 };
  const double target[3] = { 0.0, 0.0, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  vtkLight* light = vtkPhongTest::AddLight(scene, source, target, white, true);
  light->SetConeAngle(180.0);
  light->SetAmbientColor(0.6, 0.0, 0.0);
  light->SetDiffuseColor(0.0, 0.8, 0.0);
  light->SetSpecularColor(0.3, 0.3, 1.0);

  vtkNew<vtkPhongProperty> material;
  material->SetColor(1.0, 1.0, 1.0);
  material->SetAmbient(0.5);
  material->SetDiffuse(0.7);
  material->SetSpecular(0.8);
  material->SetShininess(50.0);
  vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(96), material);
  scene.LookFromZ(2.5);
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
