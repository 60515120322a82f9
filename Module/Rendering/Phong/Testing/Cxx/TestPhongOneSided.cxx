// One-sided lighting (vtkRenderer::TwoSidedLightingOff): back faces keep their
// own normal, which faces away from the light here, and the front material;
// the inside of the shell shows only its ambient term. Stock VTK ignores the
// setting and always lights back faces.

#include "vtkPhongTwoSidedScene.h"

int TestPhongOneSided(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  vtkPhongTest::BuildShellScene(scene);
  scene.Renderer->TwoSidedLightingOff();
  scene.Window->Render();

  // Inside: the front material's ambient term only, ka*Ca*Ia = 0.15*(0.85, 0.6, 0.3).
  vtkPhongTest::Checks checks;
  auto image = vtkPhongTest::Snapshot(scene.Window);
  const unsigned char* inside = vtkPhongTest::PixelAt(image, 150, 140);
  checks.Near(inside[0], 0.15 * 0.85 * 255, 1.0, "inside red is ambient only");
  checks.Near(inside[1], 0.15 * 0.6 * 255, 1.0, "inside green is ambient only");
  checks.Near(inside[2], 0.15 * 0.3 * 255, 1.0, "inside blue is ambient only");
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
