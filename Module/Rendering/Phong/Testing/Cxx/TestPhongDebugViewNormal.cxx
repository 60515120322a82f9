// Debug view: the shading normal, (N + 1) / 2 in view coordinates, on the scene shared by the
// debug-view tests.

#include "vtkPhongTestUtilities.h"

int TestPhongDebugViewNormal(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  vtkPhongTest::BuildDebugScene(scene);
  vtkPhongTest::SetDebugView(scene, vtkPhongPolyDataMapper::ShadingNormal, 0);
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
