// The final picture of the debug-view scene, for comparison with the views of
// each term. Also checks that the views add up: ambient + diffuse + specular +
// emission equals the final colour (8-bit rounding aside) wherever none of
// them saturates.

#include "vtkPhongTestUtilities.h"

int TestPhongDebugViewFinal(int argc, char* argv[])
{
  vtkPhongTest::Scene scene;
  vtkPhongTest::BuildDebugScene(scene);
  const int terms[4] = { vtkPhongPolyDataMapper::AmbientTerm, vtkPhongPolyDataMapper::DiffuseTerm,
    vtkPhongPolyDataMapper::SpecularTerm, vtkPhongPolyDataMapper::EmissionTerm };
  std::vector<vtkSmartPointer<vtkImageData>> views;
  for (int term : terms)
  {
    vtkPhongTest::SetDebugView(scene, term);
    scene.Window->Render();
    views.push_back(vtkPhongTest::Snapshot(scene.Window));
  }
  vtkPhongTest::SetDebugView(scene, vtkPhongPolyDataMapper::Final);
  scene.Window->Render();
  auto final = vtkPhongTest::Snapshot(scene.Window);

  int worst = 0;
  const vtkIdType values = final->GetNumberOfPoints() * 3;
  auto* total = static_cast<unsigned char*>(final->GetScalarPointer());
  for (vtkIdType i = 0; i < values; ++i)
  {
    int sum = 0;
    for (const auto& view : views)
    {
      sum += static_cast<unsigned char*>(view->GetScalarPointer())[i];
    }
    if (sum < 250 && total[i] < 250)
    {
      worst = std::max(worst, std::abs(sum - int(total[i])));
    }
  }
  vtkPhongTest::Checks checks;
  // Each of the four views rounds once: at most 2 levels apart.
  checks.Expect(
    worst <= 2, "terms add up to the final colour (worst " + std::to_string(worst) + ")");
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
