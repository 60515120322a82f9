// Emission: an unlit-looking glowing sphere (emission only, no light reaches
// it: all coefficients 0) next to a lit sphere that also glows faintly.

#include "vtkPhongTestUtilities.h"

int TestPhongEmission(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  vtkNew<vtkPhongProperty> lamp;
  lamp->SetAmbient(0.0);
  lamp->SetDiffuse(0.0);
  lamp->SetEmission(1.0, 0.8, 0.3);
  vtkActor* left = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(64, 0.4), lamp);
  left->SetPosition(-0.5, 0.0, 0.0);

  vtkNew<vtkPhongProperty> glowing;
  glowing->SetColor(0.2, 0.3, 0.8);
  glowing->SetSpecular(0.5);
  glowing->SetShininess(40.0);
  glowing->SetEmission(0.25, 0.0, 0.0);
  vtkActor* right = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(64, 0.4), glowing);
  right->SetPosition(0.5, 0.0, 0.0);

  scene.LookFromZ(3.5);
  scene.Window->Render();

  // The lamp is exactly its emission colour (1, 0.8, 0.3) everywhere.
  vtkPhongTest::Checks checks;
  auto image = vtkPhongTest::Snapshot(scene.Window);
  const unsigned char* lampPixel = vtkPhongTest::PixelAt(image, 80, 130);
  checks.Near(lampPixel[0], 255, 1, "lamp red");
  checks.Near(lampPixel[1], 204, 1, "lamp green");
  checks.Near(lampPixel[2], 77, 1, "lamp blue");
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
