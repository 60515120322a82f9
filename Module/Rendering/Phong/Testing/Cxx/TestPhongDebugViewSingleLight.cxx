// Debug view: the whole contribution of light 1 (the green point light) alone, on the scene shared
// by the debug-view tests.

#include "vtkPhongTestUtilities.h"

int TestPhongDebugViewSingleLight(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  vtkPhongTest::BuildDebugScene(scene);
  vtkPhongTest::SetDebugView(scene, vtkPhongPolyDataMapper::SingleLight, 1);
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
