// A camera light (position in camera coordinates) above and left of the view:
// it moves with the camera, so orbiting the camera around the sphere must leave
// the picture unchanged (but for a few silhouette pixels), where a scene light
// would not.

#include "vtkPhongTestUtilities.h"

int TestPhongCameraLight(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  scene.Renderer->AutomaticLightCreationOff();
  const double upperLeft[3] = { -1.0, 1.0, 1.0 };
  const double lookAt[3] = { 0.0, 0.0, 0.0 };
  const double warm[3] = { 1.0, 0.9, 0.8 };
  vtkPhongTest::AddLight(scene, upperLeft, lookAt, warm, false, VTK_LIGHT_TYPE_CAMERA_LIGHT);

  vtkNew<vtkPhongProperty> material;
  material->SetColor(0.3, 0.6, 0.9);
  material->SetAmbient(0.15);
  material->SetSpecular(0.6);
  material->SetShininess(60.0);
  // A fine sphere so the tessellation barely changes the picture between views.
  vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(256), material);
  scene.LookFromZ(2.5);
  scene.Window->Render();
  auto before = vtkPhongTest::Snapshot(scene.Window);

  scene.Renderer->GetActiveCamera()->Azimuth(70.0);
  scene.Renderer->GetActiveCamera()->Elevation(30.0);
  scene.Renderer->GetActiveCamera()->OrthogonalizeViewUp();
  scene.Renderer->ResetCameraClippingRange();
  scene.Window->Render();
  auto after = vtkPhongTest::Snapshot(scene.Window);

  vtkPhongTest::Checks checks;
  // Only a few silhouette pixels may change (the sphere is rasterized anew).
  const int changed = vtkPhongTest::CountDifferentPixels(before, after, 8);
  checks.Expect(changed < 30,
    "the camera light follows the camera (" + std::to_string(changed) + " pixels changed)");
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
