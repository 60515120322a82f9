// vtkOpenMeshNormals skips OpenMesh's halfedge mesh for meshes whose faces are
// all regular and walks the fans across the corners' twins instead
// (vtkOpenMeshNormalsDirectFans.cxx). That path must give exactly what the
// halfedge mesh gives (AlwaysHalfedgeMesh on): the same points in the same
// order (split points are numbered along the fans), the same polygons, point
// data and cell data, bit for bit. Checked on closed and open meshes, with
// sharp edges ending at the boundary, reversed faces, quads, strips, CGAL's
// fandisk (first argument), and with every setting that changes the fans'
// use. A fan read in another order or starting elsewhere numbers the split
// points differently and fails here.
//
// The output polygons are the input's cell array, passed on, when nothing
// changes them; when faces are turned (Consistency, FlipNormals) they are
// written anew, each turned face as (p0, pn-1, ..., p1).

#include "vtkPhongTestUtilities.h"

#include "vtkCellData.h"
#include "vtkCylinderSource.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkOpenMeshNormals.h"
#include "vtkPhongOFFReader.h"
#include "vtkPlaneSource.h"
#include "vtkStripper.h"
#include "vtkTriangleFilter.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace
{
bool CellArraysEqual(vtkCellArray* a, vtkCellArray* b)
{
  return vtkPhongTest::ArraysEqual(a->GetOffsetsArray(), b->GetOffsetsArray()) &&
    vtkPhongTest::ArraysEqual(a->GetConnectivityArray(), b->GetConnectivityArray());
}

bool FieldsEqual(vtkFieldData* a, vtkFieldData* b)
{
  if (a->GetNumberOfArrays() != b->GetNumberOfArrays())
  {
    return false;
  }
  for (int i = 0; i < a->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = a->GetArray(i);
    if (array && !vtkPhongTest::ArraysEqual(array, b->GetArray(array->GetName())))
    {
      return false;
    }
  }
  return true;
}

// Everything the filter writes, bit for bit.
bool OutputsEqual(vtkPolyData* a, vtkPolyData* b)
{
  return a->GetNumberOfPoints() == b->GetNumberOfPoints() &&
    vtkPhongTest::ArraysEqual(a->GetPoints()->GetData(), b->GetPoints()->GetData()) &&
    CellArraysEqual(a->GetPolys(), b->GetPolys()) &&
    FieldsEqual(a->GetPointData(), b->GetPointData()) &&
    FieldsEqual(a->GetCellData(), b->GetCellData());
}

vtkSmartPointer<vtkPolyData> Copy(vtkAlgorithm* source)
{
  source->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(vtkPolyData::SafeDownCast(source->GetOutputDataObject(0)));
  mesh->GetPointData()->SetNormals(nullptr);
  mesh->GetPointData()->SetTCoords(nullptr);
  return mesh;
}

// A cylinder of 8 facets (45 degree edges: all sharp) without caps: every
// sharp edge ends at a boundary vertex.
vtkSmartPointer<vtkPolyData> OpenCylinder()
{
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetResolution(8);
  cylinder->CappingOff();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cylinder->GetOutputPort());
  return Copy(triangles);
}

// A sphere with every fifth triangle reversed (Consistency turns them back).
vtkSmartPointer<vtkPolyData> PartlyReversedSphere()
{
  auto sphere = vtkPhongTest::MakeSphere(20);
  sphere->GetPointData()->SetNormals(nullptr);
  vtkNew<vtkCellArray> polys;
  const vtkIdType* ids;
  vtkIdType size;
  for (vtkIdType f = 0; f < sphere->GetPolys()->GetNumberOfCells(); ++f)
  {
    sphere->GetPolys()->GetCellAtId(f, size, ids);
    std::vector<vtkIdType> cell(ids, ids + size);
    if (f % 5 == 2)
    {
      std::swap(cell[1], cell[2]);
    }
    polys->InsertNextCell(size, cell.data());
  }
  sphere->SetPolys(polys);
  return sphere;
}

vtkSmartPointer<vtkPolyData> WavyQuads()
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(9, 7);
  auto mesh = Copy(plane);
  vtkPoints* points = mesh->GetPoints();
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    double x[3];
    points->GetPoint(p, x);
    points->SetPoint(p, x[0], x[1], (static_cast<int>(8 * x[0] + 8) % 2) * 0.15);
  }
  return mesh;
}

vtkSmartPointer<vtkPolyData> Strips()
{
  vtkNew<vtkStripper> stripper;
  auto sphere = vtkPhongTest::MakeSphere(16);
  sphere->GetPointData()->SetNormals(nullptr);
  stripper->SetInputData(sphere);
  return Copy(stripper);
}

// Two closed cones touching at their apex: every edge regular, but the apex
// has two fans, so this mesh must take the halfedge path after all.
vtkSmartPointer<vtkPolyData> TwoConesAtTheirApex()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  points->InsertNextPoint(0.0, 0.0, 0.0);
  for (const double z : { 1.0, -1.0 })
  {
    const vtkIdType center = points->InsertNextPoint(0.0, 0.0, z);
    for (int i = 0; i < 6; ++i)
    {
      const double angle = 2.0 * vtkMath::Pi() * i / 6.0;
      points->InsertNextPoint(std::cos(angle), std::sin(angle), z);
    }
    for (vtkIdType i = 0; i < 6; ++i)
    {
      const vtkIdType a = center + 1 + i, b = center + 1 + (i + 1) % 6;
      const vtkIdType side[3] = { 0, z > 0 ? a : b, z > 0 ? b : a };
      const vtkIdType cap[3] = { center, z > 0 ? b : a, z > 0 ? a : b };
      polys->InsertNextCell(3, side);
      polys->InsertNextCell(3, cap);
    }
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

// Whether output cell i is input cell i, turned where turned(i).
bool PolysAre(
  vtkCellArray* input, vtkCellArray* output, const std::function<bool(vtkIdType)>& turned)
{
  if (input->GetNumberOfCells() != output->GetNumberOfCells())
  {
    return false;
  }
  vtkNew<vtkIdList> in, out;
  for (vtkIdType i = 0; i < input->GetNumberOfCells(); ++i)
  {
    input->GetCellAtId(i, in);
    output->GetCellAtId(i, out);
    const vtkIdType n = in->GetNumberOfIds();
    if (out->GetNumberOfIds() != n)
    {
      return false;
    }
    for (vtkIdType k = 0; k < n; ++k)
    {
      if (out->GetId(k) != in->GetId(turned(i) ? (n - k) % n : k))
      {
        return false;
      }
    }
  }
  return true;
}

void CheckPolygonsPassedOn(vtkPhongTest::Checks& checks, vtkPolyData* sphere, vtkPolyData* reversed)
{
  vtkNew<vtkOpenMeshNormals> plain, flipped, turned;
  plain->SetInputData(sphere);
  flipped->SetInputData(sphere);
  flipped->FlipNormalsOn();
  turned->SetInputData(reversed);
  for (vtkOpenMeshNormals* filter : { plain.Get(), flipped.Get(), turned.Get() })
  {
    filter->Update();
  }
  checks.Expect(plain->GetOutput()->GetPolys() == sphere->GetPolys(),
    "sphere: nothing changes its polygons, they are passed on");
  checks.Expect(
    PolysAre(sphere->GetPolys(), flipped->GetOutput()->GetPolys(), [](vtkIdType) { return true; }),
    "sphere, flipped: every polygon written turned");
  checks.Expect(PolysAre(reversed->GetPolys(), turned->GetOutput()->GetPolys(),
                  [](vtkIdType i) { return i % 5 == 2; }),
    "partly reversed sphere: the reversed polygons written turned back, the others as they were");
}

using Setup = std::function<void(vtkOpenMeshNormals*)>;

// Returns whether both paths agree; direct's split count to check the case bites.
bool BothPathsAgree(vtkPolyData* mesh, const Setup& setup, vtkIdType& splitPoints)
{
  vtkNew<vtkOpenMeshNormals> direct, halfedge;
  vtkPhongTest::ErrorCollector quiet; // the two cones' warning is expected
  for (vtkOpenMeshNormals* filter : { direct.Get(), halfedge.Get() })
  {
    quiet.Observe(filter);
    filter->SetInputData(mesh);
    setup(filter);
  }
  halfedge->AlwaysHalfedgeMeshOn();
  direct->Update();
  halfedge->Update();
  splitPoints = direct->GetNumberOfSplitPoints();
  return OutputsEqual(direct->GetOutput(), halfedge->GetOutput());
}
}

int TestOpenMeshNormalsFastPaths(int argc, char* argv[])
{
  vtkPhongTest::Checks checks;
  std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> meshes = {
    { "sphere", vtkPhongTest::MakeSphere(24) },
    { "open cylinder", OpenCylinder() },
    { "partly reversed sphere", PartlyReversedSphere() },
    { "wavy quads", WavyQuads() },
    { "strips", Strips() },
    { "two cones at their apex", TwoConesAtTheirApex() },
  };
  meshes[0].second->GetPointData()->SetNormals(nullptr);
  if (argc >= 2 && vtkPhongOFFReader::CanReadFile(argv[1]))
  {
    vtkNew<vtkPhongOFFReader> reader;
    reader->SetFileName(argv[1]);
    meshes.emplace_back("fandisk", Copy(reader));
  }
  else
  {
    checks.Expect(false, "fandisk.off is the first argument");
  }

  const std::vector<std::pair<std::string, Setup>> setups = {
    { "defaults", [](vtkOpenMeshNormals*) {} },
    { "feature angle 10, cell normals",
      [](vtkOpenMeshNormals* f)
      {
        f->SetFeatureAngle(10.0);
        f->ComputeCellNormalsOn();
      } },
    { "auto-orient, angle weighting",
      [](vtkOpenMeshNormals* f)
      {
        f->AutoOrientNormalsOn();
        f->SetWeightingToAngle();
      } },
    { "no splitting, flipped",
      [](vtkOpenMeshNormals* f)
      {
        f->SplittingOff();
        f->FlipNormalsOn();
      } },
  };
  vtkIdType splitOnOpenMeshes = 0;
  for (const auto& mesh : meshes)
  {
    for (const auto& setup : setups)
    {
      vtkIdType splitPoints = 0;
      checks.Expect(BothPathsAgree(mesh.second, setup.second, splitPoints),
        mesh.first + ", " + setup.first + ": the direct fans equal OpenMesh's (" +
          std::to_string(splitPoints) + " split points)");
      if (mesh.first == "open cylinder" || mesh.first == "fandisk")
      {
        splitOnOpenMeshes += splitPoints;
      }
    }
  }
  checks.Expect(splitOnOpenMeshes > 0, "split points were numbered along the fans");
  CheckPolygonsPassedOn(checks, meshes[0].second, meshes[2].second);
  { // The apex of the two cones is left to OpenMesh's add_face.
    vtkNew<vtkOpenMeshNormals> cones;
    vtkPhongTest::ErrorCollector quiet;
    quiet.Observe(cones);
    cones->SetInputData(meshes[5].second);
    cones->Update();
    checks.Expect(cones->GetNumberOfNonManifoldFaces() == 6,
      "two cones: the apex of two fans went through OpenMesh (6 faces got copies, " +
        std::to_string(cones->GetNumberOfNonManifoldFaces()) + ")");
  }
  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
