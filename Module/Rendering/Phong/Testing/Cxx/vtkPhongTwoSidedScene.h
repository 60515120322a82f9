// The open shell of the two-sided lighting tests: a hemisphere opening towards
// the camera, so its inside (back faces) fills the middle of the picture.

#ifndef vtkPhongTwoSidedScene_h
#define vtkPhongTwoSidedScene_h

#include "vtkPhongTestUtilities.h"

namespace vtkPhongTest
{
inline vtkActor* BuildShellScene(Scene& scene)
{
  scene.Renderer->AutomaticLightCreationOff();
  const double key[3] = { 0.6, 0.8, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  AddLight(scene, key, origin, white, false, VTK_LIGHT_TYPE_CAMERA_LIGHT);

  vtkNew<vtkSphereSource> shell;
  shell->SetThetaResolution(96);
  shell->SetPhiResolution(96);
  shell->SetStartPhi(60.0); // cut a cap off the +z pole
  shell->Update();

  vtkNew<vtkPhongProperty> outside;
  outside->SetColor(0.85, 0.6, 0.3);
  outside->SetAmbient(0.15);
  outside->SetSpecular(0.5);
  outside->SetShininess(40.0);
  vtkActor* actor = AddActor(scene, shell->GetOutput(), outside);

  vtkNew<vtkPhongProperty> inside;
  inside->SetColor(0.3, 0.5, 0.9);
  inside->SetAmbient(0.15);
  inside->SetSpecular(0.8);
  inside->SetShininess(80.0);
  actor->SetBackfaceProperty(inside);

  scene.LookFromZ(2.4);
  scene.Renderer->GetActiveCamera()->Elevation(25.0);
  scene.Renderer->GetActiveCamera()->OrthogonalizeViewUp();
  scene.Renderer->ResetCameraClippingRange();
  return actor;
}
}

#endif
