// The mapper keeps at most MaximumNumberOfShaderPrograms lighting programs compiled: a sweep
// over 1..12 directional lights (each count a variant of its own) with a limit of 4 leaves 4
// compiled and releases the rest, least recently used first. Going back to a released
// variant compiles it again (counted) and draws the same picture as the first time; a
// variant still held compiles nothing.

#include "vtkPhongTestUtilities.h"

int TestPhongShaderProgramLimit(int, char*[])
{
  vtkPhongTest::Scene scene(64, 64);
  scene.Renderer->AutomaticLightCreationOff();
  vtkNew<vtkPhongProperty> material;
  material->SetSpecular(0.4);
  vtkActor* actor = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(24), material);
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper());
  mapper->SetMaximumNumberOfShaderPrograms(4);
  scene.LookFromZ(2.5);

  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double dim[3] = { 0.15, 0.15, 0.15 };
  auto setLightCount = [&](int count)
  {
    scene.Renderer->RemoveAllLights();
    for (int i = 0; i < count; ++i)
    {
      const double position[3] = { 0.3 * i - 1.0, 0.5, 1.0 };
      vtkPhongTest::AddLight(scene, position, origin, dim, false);
    }
    scene.Window->Render();
    return vtkPhongTest::Snapshot(scene.Window);
  };

  vtkPhongTest::Checks checks;
  vtkSmartPointer<vtkImageData> oneLight = setLightCount(1);
  for (int count = 2; count <= 12; ++count)
  {
    setLightCount(count);
  }
  checks.Expect(mapper->GetNumberOfCompiledShaderPrograms() == 4,
    "4 programs compiled after 12 variants: " +
      std::to_string(mapper->GetNumberOfCompiledShaderPrograms()));
  checks.Expect(mapper->GetNumberOfReleasedShaderPrograms() == 8,
    "8 released: " + std::to_string(mapper->GetNumberOfReleasedShaderPrograms()));
  checks.Expect(vtkPhongTest::NoGLErrors(scene.Window, "sweep"), "no GL error in the sweep");

  const int compiles = mapper->GetShaderCompileCount();
  vtkSmartPointer<vtkImageData> again = setLightCount(1);
  checks.Expect(mapper->GetShaderCompileCount() == compiles + 1,
    "a released variant used again is compiled again");
  checks.Expect(vtkPhongTest::MaxDifference(oneLight, again) == 0,
    "and draws the same picture as the first time");
  setLightCount(12);
  const int held = mapper->GetShaderCompileCount();
  setLightCount(12);
  checks.Expect(mapper->GetShaderCompileCount() == held, "a held variant compiles nothing");

  mapper->SetMaximumNumberOfShaderPrograms(0);
  for (int count = 1; count <= 6; ++count)
  {
    setLightCount(count);
  }
  checks.Expect(mapper->GetNumberOfCompiledShaderPrograms() >= 6, "0 keeps every program");
  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
