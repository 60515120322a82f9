// The spot of TestPhongSpotLight with the soft edge option: the disc fades out
// over the last 8 degrees inside its cone instead of ending in a hard edge.

#include "vtkPhongTestUtilities.h"

int TestPhongSoftSpotEdge(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  vtkPhongProperty* floor = vtkPhongTest::BuildSpotScene(scene);
  floor->SoftSpotEdgeOn();
  floor->SetSpotEdgeWidth(8.0);
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
