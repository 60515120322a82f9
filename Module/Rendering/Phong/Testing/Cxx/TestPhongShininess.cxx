// The extremes of the shininess n (docs/lighting-model.md):
// - n = 0: the lobe is 1 wherever the gate is open, even where the Phong
//   reflection points away from the eye (GLSL's pow(0, 0) is undefined). A
//   plane seen nearly edge-on, lit from the eye, has R.V < 0 and N.L > 0.
// - n = 1e6 (beyond vtkProperty's 128): a pin-point highlight, never NaN: a
//   sphere with ambient light shows no black (NaN) pixel anywhere.
// The picture: spheres with n = 0, 1, 1000 and 1e6.

#include "vtkPhongTestUtilities.h"

int TestPhongShininess(int argc, char* argv[])
{
  vtkPhongTest::Checks checks;
  {
    vtkPhongTest::Scene scene(64, 64);
    scene.Renderer->AutomaticLightCreationOff();
    const double eye[3] = { 0.0, 0.0, 1.0 };
    const double origin[3] = { 0.0, 0.0, 0.0 };
    const double white[3] = { 1.0, 1.0, 1.0 };
    vtkPhongTest::AddLight(scene, eye, origin, white, false, VTK_LIGHT_TYPE_HEADLIGHT);
    vtkNew<vtkPhongProperty> material;
    material->SetAmbient(0.0);
    material->SetDiffuse(0.0);
    material->SetSpecular(0.45);
    material->SetShininess(0.0);
    vtkActor* plane = vtkPhongTest::AddActor(scene, vtkPhongTest::MakePlane(3.0, 4), material);
    plane->RotateX(-78.0); // N.V = cos 78 = 0.21: R.V = 2 (0.21)^2 - 1 < 0
    scene.Renderer->GetActiveCamera()->ParallelProjectionOn();
    scene.Renderer->GetActiveCamera()->SetParallelScale(0.2);
    scene.LookFromZ(5.0);
    scene.Window->Render();
    auto image = vtkPhongTest::Snapshot(scene.Window);
    checks.Near(vtkPhongTest::PixelAt(image, 32, 32)[0], 0.45 * 255, 1.0,
      "n = 0, Phong lobe with R.V < 0: ks*Cs*I");
    material->SetLightingModelToBlinnPhong();
    scene.Window->Render();
    image = vtkPhongTest::Snapshot(scene.Window);
    checks.Near(vtkPhongTest::PixelAt(image, 32, 32)[0], 0.45 * 255, 1.0, "n = 0, Blinn lobe");
  }

  vtkPhongTest::Scene scene(400, 120);
  const double shininess[4] = { 0.0, 1.0, 1000.0, 1.0e6 };
  for (int i = 0; i < 4; ++i)
  {
    vtkNew<vtkPhongProperty> material;
    material->SetColor(0.5, 0.6, 0.8);
    material->SetAmbient(0.2);
    material->SetDiffuse(0.5);
    material->SetSpecular(0.6);
    material->SetShininess(shininess[i]);
    vtkActor* actor = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(128, 0.4), material);
    actor->SetPosition(-1.35 + 0.9 * i, 0.0, 0.0);
  }
  // Far and narrow, so the spheres at the sides are not stretched by perspective.
  scene.LookFromZ(16.0);
  scene.Renderer->GetActiveCamera()->SetViewAngle(3.9);
  scene.Renderer->ResetCameraClippingRange();
  scene.Window->Render();
  // Inside the n = 1e6 sphere every pixel is at least its ambient level.
  auto image = vtkPhongTest::Snapshot(scene.Window);
  int darkest = 255;
  for (int y = 45; y < 75; ++y)
  {
    for (int x = 335; x < 365; ++x)
    {
      darkest = std::min(darkest, int(vtkPhongTest::PixelAt(image, x, y)[2]));
    }
  }
  checks.Expect(darkest >= 0.2 * 0.8 * 255 - 1, "no NaN (black) pixel on the n = 1e6 sphere");
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
