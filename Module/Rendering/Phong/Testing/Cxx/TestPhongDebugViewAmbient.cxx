// Debug view: the Ambient term alone, on the scene shared by the debug-view tests.

#include "vtkPhongTestUtilities.h"

int TestPhongDebugViewAmbient(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  vtkPhongTest::BuildDebugScene(scene);
  vtkPhongTest::SetDebugView(scene, vtkPhongPolyDataMapper::AmbientTerm, 0);
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
