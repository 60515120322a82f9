// Two-sided lighting (VTK's default): the inside of the open shell is lit with
// the reversed normal and the actor's BackfaceProperty (blue, with its own
// sharper highlight); the outside uses the front material.

#include "vtkPhongTwoSidedScene.h"

int TestPhongTwoSided(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  vtkPhongTest::BuildShellScene(scene);
  scene.Window->Render();

  // Inside, the back material (blue) is lit: blue dominates and is bright.
  vtkPhongTest::Checks checks;
  auto image = vtkPhongTest::Snapshot(scene.Window);
  const unsigned char* inside = vtkPhongTest::PixelAt(image, 150, 140);
  checks.Expect(
    inside[2] > inside[0] && inside[2] > 100, "the inside is lit with the back material");
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
