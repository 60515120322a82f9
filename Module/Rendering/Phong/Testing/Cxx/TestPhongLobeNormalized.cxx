// Energy-normalized lobes: rows of spheres with shininess 10, 100 and 1000,
// normalized Phong (top) and normalized Blinn-Phong (bottom). The highlight
// sharpens and brightens as n grows, instead of fading as the plain lobe does.

#include "vtkPhongTestUtilities.h"

int TestPhongLobeNormalized(int argc, char* argv[])
{
  vtkPhongTest::Scene scene(360, 240);
  scene.Renderer->AutomaticLightCreationOff();
  const double key[3] = { 0.8, 0.8, 2.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  vtkPhongTest::AddLight(scene, key, origin, white, false);

  const int models[2] = { vtkPhongProperty::NormalizedPhong,
    vtkPhongProperty::NormalizedBlinnPhong };
  const double shininess[3] = { 10.0, 100.0, 1000.0 };
  for (int row = 0; row < 2; ++row)
  {
    for (int column = 0; column < 3; ++column)
    {
      vtkNew<vtkPhongProperty> material;
      material->SetColor(0.25, 0.35, 0.6);
      material->SetAmbient(0.1);
      material->SetDiffuse(0.6);
      material->SetSpecular(0.08);
      material->SetShininess(shininess[column]);
      material->SetLightingModel(models[row]);
      vtkActor* actor = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(128, 0.4), material);
      actor->SetPosition(-0.9 + 0.9 * column, row == 0 ? 0.45 : -0.45, 0.0);
    }
  }
  scene.LookFromZ(4.2);
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
