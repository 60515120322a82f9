// Flat interpolation: one normal per face, the equation evaluated per
// fragment with it; the coarse sphere shows its facets.

#include "vtkPhongTestUtilities.h"

int TestPhongInterpolationFlat(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  vtkNew<vtkPhongProperty> material;
  vtkPhongTest::BuildInterpolationScene(scene, material);
  material->SetInterpolationToFlat();
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
