// Cells that name points the polydata does not have: vtkPhongCellValidator finds and collapses
// them, vtkOpenMeshNormals, vtkPhongPolyDataMapper and vtkPhongCompositePolyDataMapper
// survive them (no out-of-bounds access:
// run under the sanitizer stage too) and say so once, and the clamped double settings refuse
// NaN instead of storing it.

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkOpenMeshNormals.h"
#include "vtkPhongCellValidator.h"
#include "vtkPhongCompositePolyDataMapper.h"
#include "vtkPhongPolyDataMapper.h"
#include "vtkPhongProperty.h"
#include "vtkPhongTestUtilities.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <limits>

namespace
{
// Two good triangles and, in every cell kind, cells naming missing points: 4 bad cells.
vtkSmartPointer<vtkPolyData> MakeBrokenMesh()
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.0, 0.0, 0.0);
  points->InsertNextPoint(1.0, 0.0, 0.0);
  points->InsertNextPoint(0.0, 1.0, 0.0);
  points->InsertNextPoint(1.0, 1.0, 0.0);
  vtkNew<vtkCellArray> verts;
  verts->InsertNextCell({ 0 });
  verts->InsertNextCell({ 7 }); // bad
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell({ 0, -1 }); // bad
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell({ 0, 1, 2 });
  polys->InsertNextCell({ 0, 1, 1000 }); // bad: the case that corrupted memory
  polys->InsertNextCell({ 1, 3, 2 });
  vtkNew<vtkCellArray> strips;
  strips->InsertNextCell({ 0, 1, 2, 4 }); // bad: one past the end
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetVerts(verts);
  mesh->SetLines(lines);
  mesh->SetPolys(polys);
  mesh->SetStrips(strips);
  vtkNew<vtkIntArray> cellIds;
  cellIds->SetName("cellId");
  for (int cell = 0; cell < 7; ++cell)
  {
    cellIds->InsertNextValue(cell);
  }
  mesh->GetCellData()->AddArray(cellIds);
  return mesh;
}

void CheckValidator(vtkPhongTest::Checks& checks)
{
  vtkSmartPointer<vtkPolyData> mesh = MakeBrokenMesh();
  checks.Expect(vtkPhongCellValidator::CountInvalidCells(mesh) == 4, "4 invalid cells counted");
  vtkSmartPointer<vtkPolyData> valid = vtkPhongCellValidator::CollapseInvalidCells(mesh);
  checks.Expect(valid != mesh && vtkPhongCellValidator::CountInvalidCells(valid) == 0,
    "the copy has no invalid cell");
  checks.Expect(valid->GetNumberOfCells() == 7 && valid->GetPolys()->GetNumberOfCells() == 3,
    "cells are collapsed, not removed: every cell keeps its id");
  vtkNew<vtkIdList> ids;
  valid->BuildCells(); // VTK's cell map accepts the collapsed cells
  valid->GetCellPoints(4, ids);
  checks.Expect(ids->GetNumberOfIds() == 3 && ids->GetId(0) == 0 && ids->GetId(2) == 0,
    "a bad triangle collapses onto its first existing point");
  valid->GetCellPoints(3, ids);
  checks.Expect(ids->GetNumberOfIds() == 3 && ids->GetId(1) == 1 && ids->GetId(2) == 2,
    "a good triangle is unchanged");
  valid->GetCellPoints(1, ids);
  checks.Expect(ids->GetNumberOfIds() == 1 && ids->GetId(0) == 0,
    "a vertex with no existing point collapses onto point 0");
  checks.Expect(mesh->GetPolys()->GetNumberOfConnectivityIds() == 9, "the input is untouched");
  vtkSmartPointer<vtkPolyData> sphere = vtkPhongTest::MakeSphere(8);
  checks.Expect(vtkPhongCellValidator::CollapseInvalidCells(sphere) == sphere,
    "valid data is passed through, not copied");
}

void CheckNormalsFilter(vtkPhongTest::Checks& checks)
{
  vtkNew<vtkOpenMeshNormals> normals;
  vtkPhongTest::ErrorCollector messages;
  messages.Observe(normals);
  normals->SetInputData(MakeBrokenMesh());
  normals->ComputeCellNormalsOn();
  normals->Update();
  vtkPolyData* output = normals->GetOutput();
  checks.Expect(normals->GetNumberOfInvalidCells() == 4, "the filter counts 4 invalid cells");
  checks.Expect(messages.Messages.size() == 1 && messages.Contains("4 cells name point ids"),
    "the filter warns once");
  // Strips come out as their triangles; the collapsed strip has none with an area.
  checks.Expect(output->GetNumberOfVerts() == 2 && output->GetNumberOfLines() == 1 &&
      output->GetNumberOfPolys() == 3,
    "the output keeps every vertex, line and polygon");
  vtkDataArray* pointNormals = output->GetPointData()->GetNormals();
  bool unit = pointNormals != nullptr;
  for (vtkIdType p = 0; unit && p < pointNormals->GetNumberOfTuples(); ++p)
  {
    double n[3];
    pointNormals->GetTuple(p, n);
    unit = std::abs(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0) < 1e-6;
  }
  checks.Expect(unit, "every point normal is a unit vector");
  checks.Expect(vtkPhongCellValidator::CountInvalidCells(output) == 0, "the output is valid");
}

void CheckMapper(vtkPhongTest::Checks& checks)
{
  vtkPhongTest::Scene scene(100, 100);
  vtkActor* actor = vtkPhongTest::AddActor(scene, MakeBrokenMesh());
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper());
  vtkPhongTest::ErrorCollector messages;
  messages.Observe(mapper);
  scene.Renderer->ResetCamera(); // VTK's cell bounds read every cell's points
  scene.Window->Render();
  scene.Window->Render();
  const double* bounds = mapper->GetBounds();
  checks.Expect(bounds[0] == 0.0 && bounds[1] == 1.0 && bounds[3] == 1.0,
    "the bounds are those of the valid cells");
  checks.Expect(messages.Messages.size() == 1 && messages.Contains("they are not drawn"),
    "the mapper warns once, not every frame");
  checks.Expect(vtkPhongTest::NoGLErrors(scene.Window, "broken mesh"), "no GL error");
  vtkSmartPointer<vtkImageData> image = vtkPhongTest::Snapshot(scene.Window);
  checks.Expect(vtkPhongTest::PixelAt(image, 50, 50)[0] > 0, "the valid triangles are drawn");
}

// A broken block beside a valid one, drawn by the composite mapper (VTK's bounds and upload
// of each block would read the missing points).
void CheckCompositeMapper(vtkPhongTest::Checks& checks)
{
  vtkNew<vtkPolyData> shifted;
  shifted->DeepCopy(MakeBrokenMesh());
  for (vtkIdType p = 0; p < shifted->GetNumberOfPoints(); ++p)
  {
    double x[3];
    shifted->GetPoint(p, x);
    shifted->GetPoints()->SetPoint(p, x[0] - 1.5, x[1], x[2]);
  }
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, MakeBrokenMesh());
  blocks->SetBlock(1, shifted);
  vtkPhongTest::Scene scene(100, 100);
  vtkNew<vtkPhongCompositePolyDataMapper> mapper;
  mapper->SetInputDataObject(blocks);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  scene.Renderer->AddActor(actor);
  vtkPhongTest::ErrorCollector messages;
  messages.Observe(mapper);
  scene.Renderer->ResetCamera();
  scene.Window->Render();
  scene.Window->Render();
  const double* bounds = mapper->GetBounds();
  checks.Expect(bounds[0] == -1.5 && bounds[1] == 1.0 && bounds[3] == 1.0,
    "the composite bounds are those of the valid cells");
  checks.Expect(messages.Messages.size() == 2 && messages.Contains("they are not drawn"),
    "the composite mapper warns once per broken block (" +
      std::to_string(messages.Messages.size()) + ")");
  checks.Expect(vtkPhongTest::NoGLErrors(scene.Window, "broken blocks"), "no GL error");
  vtkSmartPointer<vtkImageData> image = vtkPhongTest::Snapshot(scene.Window);
  int drawn = 0;
  for (int x = 0; x < 100; ++x)
  {
    drawn += vtkPhongTest::PixelAt(image, x, 50)[0] > 0 ? 1 : 0;
  }
  checks.Expect(drawn > 30,
    "both blocks' valid triangles are drawn (" + std::to_string(drawn) +
      " pixels of the middle row)");
}

void CheckNaNSetters(vtkPhongTest::Checks& checks)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vtkPhongTest::ErrorCollector messages;
  vtkNew<vtkOpenMeshNormals> normals;
  vtkNew<vtkPhongPolyDataMapper> mapper;
  vtkNew<vtkPhongProperty> property;
  messages.Observe(normals);
  messages.Observe(mapper);
  messages.Observe(property);
  normals->SetFeatureAngle(nan);
  mapper->SetNormalsFeatureAngle(nan);
  property->SetSpotEdgeWidth(nan);
  checks.Expect(normals->GetFeatureAngle() == 30.0 && mapper->GetNormalsFeatureAngle() == 30.0 &&
      property->GetSpotEdgeWidth() == 5.0,
    "NaN is refused, the value kept");
  checks.Expect(messages.Messages.size() == 3 && messages.Contains("NaN refused"),
    "each refusal is an error message");
  normals->SetFeatureAngle(400.0);
  property->SetSpotEdgeWidth(-3.0);
  checks.Expect(normals->GetFeatureAngle() == 180.0 && property->GetSpotEdgeWidth() == 0.0,
    "other values are clamped as vtkSetClampMacro does");
}
}

int TestPhongCellValidator(int, char*[])
{
  vtkPhongTest::Checks checks;
  CheckValidator(checks);
  CheckNormalsFilter(checks);
  CheckMapper(checks);
  CheckCompositeMapper(checks);
  CheckNaNSetters(checks);
  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
