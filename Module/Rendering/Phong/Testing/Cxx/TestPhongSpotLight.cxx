// A spot light (cone 25 degrees, exponent 4) on a floor: a hard-edged disc
// whose brightness falls as pow(cos phi, 4) away from the axis.

#include "vtkPhongTestUtilities.h"

int TestPhongSpotLight(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  vtkPhongTest::BuildSpotScene(scene);
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
