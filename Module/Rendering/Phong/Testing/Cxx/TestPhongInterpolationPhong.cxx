// Phong interpolation: the normal interpolated and renormalized, the equation
// per fragment: a round highlight on the coarse sphere. VTK's default Gouraud
// is shaded the same way by stock VTK, and so it is here: the pictures match.

#include "vtkPhongTestUtilities.h"

int TestPhongInterpolationPhong(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  vtkNew<vtkPhongProperty> material;
  vtkPhongTest::BuildInterpolationScene(scene, material);
  material->SetInterpolationToGouraud();
  scene.Window->Render();
  auto gouraud = vtkPhongTest::Snapshot(scene.Window);

  material->SetInterpolationToPhong();
  scene.Window->Render();
  auto phong = vtkPhongTest::Snapshot(scene.Window);

  vtkPhongTest::Checks checks;
  checks.Expect(vtkPhongTest::MaxDifference(gouraud, phong) == 0,
    "a plain Gouraud property shades per fragment, like stock VTK");
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
