// A textured floor under a point light: the texture multiplies the ambient
// and diffuse colour, the specular highlight is added after it (OpenGL's
// separate specular colour), so the highlight stays white on dark squares.
// Stock VTK multiplies the highlight by the texture too.

#include "vtkPhongTestUtilities.h"

#include "vtkTextureMapToPlane.h"

int TestPhongTexture(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  scene.Renderer->AutomaticLightCreationOff();
  const double above[3] = { 0.0, 0.0, 1.0 };
  const double down[3] = { 0.0, 0.0, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  vtkPhongTest::AddLight(scene, above, down, white, true)->SetConeAngle(180.0);

  vtkNew<vtkTextureMapToPlane> mapToPlane;
  mapToPlane->SetInputData(vtkPhongTest::MakePlane(1.0, 40));
  mapToPlane->Update();

  vtkNew<vtkPhongProperty> material;
  material->SetColor(1.0, 1.0, 1.0);
  material->SetAmbient(0.1);
  material->SetDiffuse(0.9);
  material->SetSpecular(0.9);
  material->SetShininess(30.0);
  vtkActor* actor =
    vtkPhongTest::AddActor(scene, vtkPolyData::SafeDownCast(mapToPlane->GetOutput()), material);
  scene.LookFromZ(3.5);

  // An all-black texture: what remains is the specular highlight alone.
  vtkPhongTest::Checks checks;
  const unsigned char black[3] = { 0, 0, 0 };
  actor->SetTexture(vtkPhongTest::MakeCheckerTexture(black, black));
  scene.Window->Render();
  auto image = vtkPhongTest::Snapshot(scene.Window);
  const unsigned char* middle = vtkPhongTest::PixelAt(image, 150, 150);
  checks.Expect(middle[0] > 200 && middle[1] > 200 && middle[2] > 200,
    "the highlight is added after the (black) texture");
  const unsigned char* away = vtkPhongTest::PixelAt(image, 60, 60);
  checks.Expect(away[0] < 3, "away from the highlight a black texture stays black");

  const unsigned char dark[3] = { 40, 60, 120 };
  const unsigned char light[3] = { 230, 200, 120 };
  actor->SetTexture(vtkPhongTest::MakeCheckerTexture(dark, light));
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
