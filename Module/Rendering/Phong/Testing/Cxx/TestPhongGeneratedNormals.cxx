// CGAL's fandisk read from its OFF file, without normals: the mapper computes
// them with vtkOpenMeshNormals, split at the 30 degree feature edges, so the
// curved patches are smooth and the creases stay sharp (stock VTK would draw
// every triangle flat). A second mapper with splitting off, beside it, smooths
// the creases away; the normals are computed once and reused by later frames.

#include "vtkPhongTestUtilities.h"

#include "vtkPhongOFFReader.h"
#include "vtkUnsignedCharArray.h"

namespace
{
// Point colours on a mesh without normals: the normals' output has more points than the
// input (split at the creases), and the colours drawn must be its own, not the input's read
// past their end (VTK maps GetInput()'s scalars while it draws the normals' output). The
// picture equals that of the same output given as the input.
void CheckPointColours(vtkPhongTest::Checks& checks)
{
  auto sphere = vtkPhongTest::MakeSphere(8);
  sphere->GetPointData()->SetNormals(nullptr);
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(4);
  for (vtkIdType p = 0; p < sphere->GetNumberOfPoints(); ++p)
  {
    const unsigned char colour[4] = { static_cast<unsigned char>(60 + (37 * p) % 190),
      static_cast<unsigned char>(200 - (53 * p) % 150), 140, 255 };
    colours->InsertNextTypedTuple(colour);
  }
  sphere->GetPointData()->SetScalars(colours);
  vtkPhongTest::Scene scene(200, 200);
  vtkActor* actor = vtkPhongTest::AddActor(scene, sphere);
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper());
  scene.Renderer->ResetCamera();
  scene.Window->Render();
  const auto generated = vtkPhongTest::Snapshot(scene.Window);
  vtkNew<vtkPolyData> output;
  output->DeepCopy(mapper->GetNormalsGenerator()->GetOutput());
  checks.Expect(output->GetNumberOfPoints() > sphere->GetNumberOfPoints(),
    "point colours: the normals' output has split points");
  mapper->SetInputData(output);
  scene.Window->Render();
  const auto given = vtkPhongTest::Snapshot(scene.Window);
  const int differing = vtkPhongTest::CountDifferentPixels(generated, given, 0);
  checks.Expect(differing == 0,
    "point colours: drawn as the normals' output's own (" + std::to_string(differing) +
      " pixels differ)");
}
}

int TestPhongGeneratedNormals(int argc, char* argv[])
{
  if (argc < 2 || !vtkPhongOFFReader::CanReadFile(argv[1]))
  {
    std::cerr << "TestPhongGeneratedNormals needs fandisk.off as its first argument\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkPhongOFFReader> reader;
  reader->SetFileName(argv[1]);
  reader->Update();

  vtkPhongTest::Scene scene(400, 300);
  vtkPhongTest::Checks checks;
  vtkPhongPolyDataMapper* mappers[2];
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkPhongProperty> material;
    material->SetColor(0.75, 0.78, 0.85);
    material->SetAmbient(0.15);
    material->SetSpecular(0.4);
    material->SetShininess(40.0);
    vtkActor* actor = vtkPhongTest::AddActor(scene, reader->GetOutput(), material);
    actor->RotateY(35.0);
    actor->RotateX(25.0);
    actor->SetPosition(i == 0 ? -0.55 : 0.55, 0.0, 0.0);
    mappers[i] = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper());
    mappers[i]->SetNormalsSplitting(i == 0);
  }
  scene.LookFromZ(4.2);
  scene.Window->Render();

  vtkOpenMeshNormals* generator = mappers[0]->GetNormalsGenerator();
  checks.Expect(mappers[0]->GetUsedGeneratedNormals(), "the mapper generated normals");
  checks.Expect(generator->GetNumberOfSplitPoints() > 0, "split along the creases");
  checks.Expect(mappers[1]->GetNormalsGenerator()->GetNumberOfSplitPoints() == 0,
    "no split with NormalsSplitting off");
  const vtkMTimeType computed = generator->GetOutput()->GetMTime();
  scene.Window->Render();
  checks.Expect(
    generator->GetOutput()->GetMTime() == computed, "a second frame recomputes nothing");
  CheckPointColours(checks);
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
