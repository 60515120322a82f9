// CGAL's fandisk read from its OFF file, without normals: the mapper computes
// them with vtkOpenMeshNormals, split at the 30 degree feature edges, so the
// curved patches are smooth and the creases stay sharp (stock VTK would draw
// every triangle flat). A second mapper with splitting off, beside it, smooths
// the creases away; the normals are computed once and reused by later frames.

#include "vtkPhongTestUtilities.h"

#include "vtkPhongOFFReader.h"

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
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
