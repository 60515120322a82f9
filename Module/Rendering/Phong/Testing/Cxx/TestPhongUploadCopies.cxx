// VTK packs an array for upload when the buffer's layout differs from the array's, and keeps
// the packed vector's memory after the upload (vtkPhongBufferBlocks::ReleasePackedCopies): a
// copy of a big mesh's points that nothing reads. The mapper frees it. A sphere with double
// points (packed into floats) and colours of three components (packed into four) drawn by
// vtkPhongPolyDataMapper keeps no packed copy after its first frame, nor after its points
// change and upload again; and that second upload draws what a new mapper draws of the
// changed points. A stock mapper beside it shows what VTK keeps (printed, not checked: a
// later VTK may free it itself).

#include "vtkPhongTestUtilities.h"

#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"

namespace
{
// The floats the mapper's position and colour buffers keep for their next upload.
size_t KeptFloats(vtkOpenGLPolyDataMapper* mapper)
{
  size_t kept = 0;
  for (const char* name : { "vertexMC", "normalMC", "scalarColor" })
  {
    if (vtkOpenGLVertexBufferObject* buffer = mapper->GetVBOs()->GetVBO(name))
    {
      kept += buffer->GetPackedVBO().capacity();
    }
  }
  return kept;
}

vtkSmartPointer<vtkPolyData> DoubleSphereWithColours()
{
  vtkSmartPointer<vtkPolyData> sphere = vtkPhongTest::MakeSphere(48);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(sphere->GetPoints());
  sphere->SetPoints(points);
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(sphere->GetNumberOfPoints());
  for (vtkIdType p = 0; p < sphere->GetNumberOfPoints(); ++p)
  {
    const unsigned char colour[3] = { static_cast<unsigned char>(p % 256), 128, 200 };
    colours->SetTypedTuple(p, colour);
  }
  sphere->GetPointData()->SetScalars(colours);
  return sphere;
}
}

int TestPhongUploadCopies(int, char*[])
{
  vtkPhongTest::Checks checks;
  vtkSmartPointer<vtkPolyData> sphere = DoubleSphereWithColours();
  vtkPhongTest::Scene scene(96, 96);
  vtkActor* actor = vtkPhongTest::AddActor(scene, sphere);
  auto* mapper = vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper());
  scene.LookFromZ(2.5);
  scene.Window->Render();
  checks.Expect(mapper->GetVBOs()->GetVBO("vertexMC") != nullptr, "the points were uploaded");
  checks.Expect(KeptFloats(mapper) == 0,
    "no packed copy kept after the first upload: " + std::to_string(KeptFloats(mapper)));

  // The points change in place: the mapper packs and uploads them again.
  vtkPoints* points = sphere->GetPoints();
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    double x[3];
    points->GetPoint(p, x);
    points->SetPoint(p, 1.3 * x[0], 0.8 * x[1], x[2]);
  }
  points->Modified();
  scene.Window->Render();
  vtkSmartPointer<vtkImageData> changed = vtkPhongTest::Snapshot(scene.Window);
  checks.Expect(KeptFloats(mapper) == 0,
    "no packed copy kept after the upload of the changed points: " +
      std::to_string(KeptFloats(mapper)));
  checks.Expect(vtkPhongTest::NoGLErrors(scene.Window, "upload"), "no GL error");

  vtkPhongTest::Scene fresh(96, 96);
  vtkNew<vtkPolyData> copy;
  copy->DeepCopy(sphere);
  vtkPhongTest::AddActor(fresh, copy);
  fresh.LookFromZ(2.5);
  fresh.Window->Render();
  checks.Expect(vtkPhongTest::MaxDifference(changed, vtkPhongTest::Snapshot(fresh.Window)) == 0,
    "the second upload draws what a new mapper draws of the changed points");

  vtkPhongTest::Scene stock(96, 96);
  vtkNew<vtkOpenGLPolyDataMapper> stockMapper;
  stockMapper->SetInputData(copy);
  vtkNew<vtkActor> stockActor;
  stockActor->SetMapper(stockMapper);
  stock.Renderer->AddActor(stockActor);
  stock.LookFromZ(2.5);
  stock.Window->Render();
  std::cout << "floats VTK's own mapper keeps packed for " << copy->GetNumberOfPoints()
            << " points: " << KeptFloats(stockMapper) << "\n";
  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
