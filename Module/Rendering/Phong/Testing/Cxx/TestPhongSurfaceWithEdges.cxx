// Per-vertex Gouraud through VTK's geometry shader: with edge visibility on,
// VTK draws surfaces through a geometry shader, and the per-vertex light sums
// must pass through it.

#include "vtkPhongTestUtilities.h"

int TestPhongSurfaceWithEdges(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  vtkNew<vtkPhongProperty> material;
  vtkPhongTest::BuildInterpolationScene(scene, material);
  material->SetInterpolationToPerVertexGouraud();
  material->EdgeVisibilityOn();
  material->SetEdgeColor(0.1, 0.1, 0.1);
  material->SetLineWidth(1.5);
  scene.Window->Render();

  vtkPhongTest::Checks checks;
  auto* mapper =
    vtkPhongPolyDataMapper::SafeDownCast(scene.Renderer->GetActors()->GetLastActor()->GetMapper());
  checks.Expect(
    std::string(mapper->GetLastGeometryShaderSource()).find("phongDiffuseLightGSOutput") !=
      std::string::npos,
    "the geometry shader passes the per-vertex light on");
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
