// True per-vertex Gouraud: the equation evaluated at the vertices and the
// light interpolated, so the sharp highlight is smeared along the coarse
// sphere's triangles. It must differ from per-fragment shading (what stock VTK
// calls Gouraud), which stays the default for a Gouraud property.

#include "vtkPhongTestUtilities.h"

int TestPhongInterpolationGouraud(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  vtkNew<vtkPhongProperty> material;
  vtkPhongTest::BuildInterpolationScene(scene, material);
  material->SetInterpolationToGouraud();
  scene.Window->Render();
  auto perFragment = vtkPhongTest::Snapshot(scene.Window);

  material->SetInterpolationToPerVertexGouraud();
  scene.Window->Render();
  auto perVertex = vtkPhongTest::Snapshot(scene.Window);

  vtkPhongTest::Checks checks;
  const int difference = vtkPhongTest::MaxDifference(perFragment, perVertex);
  checks.Expect(difference > 40,
    "per-vertex Gouraud differs from per-fragment shading (max " + std::to_string(difference) +
      ")");
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
