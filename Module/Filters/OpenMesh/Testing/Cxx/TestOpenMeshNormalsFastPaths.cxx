// vtkOpenMeshNormals has two fast paths beside OpenMesh's halfedge mesh, and
// both must give exactly what the halfedge mesh gives (AlwaysHalfedgeMesh on):
// the same points in the same order (split points are numbered along the
// fans), the same polygons, point data and cell data, bit for bit.
// - Meshes whose faces are all regular skip the halfedge mesh and walk the
//   fans across the corners' twins (vtkOpenMeshNormalsDirectFans.cxx;
//   PointByPoint off here, so that smooth meshes take it too).
// - Smooth, consistent triangle meshes skip the topology altogether and are
//   computed point by point (vtkOpenMeshNormalsPointByPoint), which must give
//   up, for the topology, at the first point the topology would treat
//   otherwise: the test names which cases it must take and which it must not,
//   so that neither a path that never runs nor one that runs where it should
//   not passes.
// Checked on closed and open meshes, with sharp edges ending at the boundary,
// reversed faces, quads, strips, a cone's apex, non-manifold edges and
// vertices, repeated indices, faces without a normal (zero area, NaN), points
// no face uses, 32-bit cells and float points, a sphere of several ranges of
// points (one of them reversed in its last range), CGAL's fandisk (first
// argument), and with every setting that changes the fans' use. A fan read in
// another order or starting elsewhere numbers the split points differently,
// or sums a normal in another order, and fails here.
//
// The output polygons are the input's cell array, passed on, when nothing
// changes them; when faces are turned (Consistency, FlipNormals) they are
// written anew, each turned face as (p0, pn-1, ..., p1).

#include "vtkPhongTestUtilities.h"

#include "vtkCellData.h"
#include "vtkCylinderSource.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkOpenMeshNormals.h"
#include "vtkPhongOFFReader.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStripper.h"
#include "vtkTriangleFilter.h"

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
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

// An open, smooth terrain with float points and 32-bit cells (how readers of big
// data often store them), a vertex cell, a line and a point array to pass on.
vtkSmartPointer<vtkPolyData> Terrain()
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(30, 20);
  auto source = Copy(plane);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(source);
  auto mesh = Copy(triangles);
  vtkPoints* points = mesh->GetPoints();
  vtkNew<vtkPoints> floats;
  floats->SetDataTypeToFloat();
  vtkNew<vtkFloatArray> height;
  height->SetName("height");
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    double x[3];
    points->GetPoint(p, x);
    x[2] = 0.1 * std::sin(6.0 * x[0]) * std::cos(4.0 * x[1]);
    floats->InsertNextPoint(x);
    height->InsertNextValue(static_cast<float>(x[2]));
  }
  mesh->SetPoints(floats);
  mesh->GetPointData()->AddArray(height);
  vtkNew<vtkCellArray> polys;
  polys->Use32BitStorage();
  polys->DeepCopy(mesh->GetPolys());
  mesh->SetPolys(polys);
  vtkNew<vtkCellArray> verts, lines;
  const vtkIdType vertex = 5, line[2] = { 7, 40 };
  verts->InsertNextCell(1, &vertex);
  lines->InsertNextCell(2, line);
  mesh->SetVerts(verts);
  mesh->SetLines(lines);
  return mesh;
}

// A flat grid with faces that have no normal (one of zero area, two touching a NaN point)
// and a point no face uses.
vtkSmartPointer<vtkPolyData> GridWithoutSomeNormals()
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<vtkIdType>> faces;
  const int n = 6;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      points.push_back({ double(i), double(j), 0.0 });
    }
  }
  for (int j = 0; j + 1 < n; ++j)
  {
    for (int i = 0; i + 1 < n; ++i)
    {
      const vtkIdType a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      faces.push_back({ a, b, d });
      faces.push_back({ a, d, c });
    }
  }
  // Point 15, (3, 2), onto the diagonal from 14 (2, 2) to 21 (3, 3): face (14, 15, 21) has
  // zero area, and every other face around it still faces +z.
  points[15] = { 2.5, 2.5, 0.0 };
  points[30][2] = std::numeric_limits<double>::quiet_NaN();
  points.push_back({ 9.0, 9.0, 9.0 }); // used by no face
  return vtkPhongTest::MakeMesh(points, faces);
}

// A sphere of 130 048 triangles: several ranges of points (a quarter of the corners each).
// With reverseLate, one face among its last points is turned: the first ranges pass, and
// the last must send the whole mesh to the topology.
vtkSmartPointer<vtkPolyData> BigSphere(bool reverseLate)
{
  auto sphere = vtkPhongTest::MakeSphere(256);
  sphere->GetPointData()->SetNormals(nullptr);
  if (reverseLate)
  {
    vtkCellArray* polys = sphere->GetPolys();
    vtkNew<vtkIdList> ids;
    const vtkIdType last = polys->GetNumberOfCells() - 10;
    polys->GetCellAtId(last, ids);
    const vtkIdType turned[3] = { ids->GetId(0), ids->GetId(2), ids->GetId(1) };
    polys->ReplaceCellAtId(last, 3, turned);
    polys->Modified();
  }
  return sphere;
}

// An open cone of 24 sides whose faces lean 45 degrees: its apex is singular under a
// feature angle of 30 degrees, not under 60.
vtkSmartPointer<vtkPolyData> OpenCone()
{
  std::vector<std::array<double, 3>> points = { { 0.0, 0.0, 1.0 } };
  std::vector<std::vector<vtkIdType>> faces;
  for (int i = 0; i < 24; ++i)
  {
    const double angle = 2.0 * vtkMath::Pi() * i / 24.0;
    points.push_back({ std::cos(angle), std::sin(angle), 0.0 });
    faces.push_back({ 0, 1 + i, 1 + (i + 1) % 24 });
  }
  return vtkPhongTest::MakeMesh(points, faces);
}

// Three triangles on one edge (a fin): non-manifold, consistently oriented where it can be.
vtkSmartPointer<vtkPolyData> Fin()
{
  return vtkPhongTest::MakeMesh(
    { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 0.5, -1, 0.1 }, { 0.5, 0, 1 } },
    { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } });
}

// A smooth strip of triangles with one triangle naming a point twice.
vtkSmartPointer<vtkPolyData> RepeatedIndex()
{
  return vtkPhongTest::MakeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } },
    { { 0, 1, 2 }, { 1, 3, 2 }, { 2, 3, 3 } });
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

struct Agreement
{
  bool Equal;            // the three paths' outputs, bit for bit
  vtkIdType SplitPoints; // to check that the case bites
  bool PointByPoint;     // the default path computed point by point
};

// The default path (point by point where it may), the direct fans (PointByPoint off) and
// OpenMesh's halfedge mesh (AlwaysHalfedgeMesh on), on one mesh and setup.
Agreement ThreePaths(vtkPolyData* mesh, const Setup& setup)
{
  vtkNew<vtkOpenMeshNormals> fastest, direct, halfedge;
  vtkPhongTest::ErrorCollector quiet; // the two cones' and the fin's warnings are expected
  for (vtkOpenMeshNormals* filter : { fastest.Get(), direct.Get(), halfedge.Get() })
  {
    quiet.Observe(filter);
    filter->SetInputData(mesh);
    setup(filter);
  }
  direct->PointByPointOff();
  halfedge->AlwaysHalfedgeMeshOn();
  for (vtkOpenMeshNormals* filter : { fastest.Get(), direct.Get(), halfedge.Get() })
  {
    filter->Update();
  }
  return { OutputsEqual(fastest->GetOutput(), halfedge->GetOutput()) &&
      OutputsEqual(direct->GetOutput(), halfedge->GetOutput()),
    direct->GetNumberOfSplitPoints(), fastest->GetComputedPointByPoint() };
}

// The cases the point-by-point path must take; it must decline every other.
const std::set<std::string> PointByPointCases = {
  "sphere, defaults", "sphere, uniform weighting, no splitting",
  "sphere, area weighting, feature angle 60",
  "open cylinder, uniform weighting, no splitting",  // its 45-degree edges are not cut
  "open cylinder, area weighting, feature angle 60", // nor sharp at 60
  "fandisk, uniform weighting, no splitting",        // closed, consistent: only sharp
  "terrain, defaults", "terrain, uniform weighting, no splitting",
  "terrain, area weighting, feature angle 60", "grid without some normals, defaults",
  "grid without some normals, uniform weighting, no splitting",
  "grid without some normals, area weighting, feature angle 60",
  "sphere of 130k triangles, defaults", "sphere of 130k triangles, uniform weighting, no splitting",
  "sphere of 130k triangles, area weighting, feature angle 60",
  "open cone, uniform weighting, no splitting",  // an apex is cut only by splitting
  "open cone, area weighting, feature angle 60", // and not at 60 degrees
};
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
    { "terrain", Terrain() },
    { "grid without some normals", GridWithoutSomeNormals() },
    { "sphere of 130k triangles", BigSphere(false) },
    { "sphere of 130k triangles turned in its last range", BigSphere(true) },
    { "open cone", OpenCone() },
    { "fin", Fin() },
    { "repeated index", RepeatedIndex() },
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
    { "uniform weighting, no splitting",
      [](vtkOpenMeshNormals* f)
      {
        f->SetWeightingToUniform();
        f->SplittingOff();
      } },
    { "area weighting, feature angle 60",
      [](vtkOpenMeshNormals* f)
      {
        f->SetWeightingToArea();
        f->SetFeatureAngle(60.0);
      } },
  };
  vtkIdType splitOnOpenMeshes = 0;
  for (const auto& mesh : meshes)
  {
    for (const auto& setup : setups)
    {
      const std::string name = mesh.first + ", " + setup.first;
      const Agreement agreement = ThreePaths(mesh.second, setup.second);
      checks.Expect(agreement.Equal,
        name + ": the fast paths equal OpenMesh's (" + std::to_string(agreement.SplitPoints) +
          " split points" + (agreement.PointByPoint ? ", point by point)" : ")"));
      checks.Expect(agreement.PointByPoint == (PointByPointCases.count(name) > 0),
        name +
          (agreement.PointByPoint ? ": computed point by point where it must not be"
                                  : ": not computed point by point where it must be"));
      if (mesh.first == "open cylinder" || mesh.first == "fandisk")
      {
        splitOnOpenMeshes += agreement.SplitPoints;
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
