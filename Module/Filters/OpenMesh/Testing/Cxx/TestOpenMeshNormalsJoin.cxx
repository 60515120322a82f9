// vtkOpenMeshNormals' JoinCoincidentPoints, on the pieces people have:
// - a sphere made of vtkSphereSource's own pieces (each with its copies of the points on its
//   cuts, those on one cut a float step apart): without joining a seam, joined the whole
//   sphere's normals, by position and by global ids; global ids, where present, decide;
// - every copy keeps its own point data;
// - a cube whose faces each have their own points: joined, each keeps its face's normal with
//   splitting (also with OriginalPointIdsArrayName unset), and gets the corner's shared normal
//   without;
// - a cube of shared points cut into two pieces: points whose corners fall on different
//   sides of a sharp edge are copied, and every corner carries its face's normal.

#include "vtkPhongTestUtilities.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArrayIterator.h"
#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkOpenMeshNormals.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"

#include <array>
#include <cmath>
#include <map>
#include <string>

namespace
{
// The largest angle, in degrees, between a point's normal and its direction from the origin.
double LargestRadialError(vtkPolyData* output)
{
  vtkDataArray* normals = output->GetPointData()->GetNormals();
  double largest = 0.0;
  for (vtkIdType p = 0; p < output->GetNumberOfPoints(); ++p)
  {
    double x[3], n[3];
    output->GetPoint(p, x);
    normals->GetTuple(p, n);
    vtkMath::Normalize(x);
    const double c = std::max(-1.0, std::min(1.0, vtkMath::Dot(x, n)));
    largest = std::max(largest, vtkMath::DegreesFromRadians(std::acos(c)));
  }
  return largest;
}

// A sphere of `pieces` pieces of vtkSphereSource, normals removed, each point carrying its
// piece's number (array "Piece").
vtkSmartPointer<vtkPolyData> SphereOfPieces(int pieces)
{
  vtkNew<vtkAppendPolyData> append;
  for (int piece = 0; piece < pieces; ++piece)
  {
    vtkNew<vtkSphereSource> source;
    source->SetThetaResolution(24);
    source->SetPhiResolution(24);
    source->UpdatePiece(piece, pieces, 0);
    auto part = vtkSmartPointer<vtkPolyData>::New();
    part->DeepCopy(source->GetOutput());
    part->GetPointData()->RemoveArray("Normals");
    vtkNew<vtkFloatArray> tag;
    tag->SetName("Piece");
    tag->SetNumberOfTuples(part->GetNumberOfPoints());
    tag->FillValue(static_cast<float>(piece));
    part->GetPointData()->AddArray(tag);
    append->AddInputData(part);
  }
  append->Update();
  return append->GetOutput();
}

vtkSmartPointer<vtkPolyData> NormalsOf(
  vtkPolyData* mesh, bool join, bool splitting = true, vtkIdType* joined = nullptr)
{
  vtkNew<vtkOpenMeshNormals> normals;
  normals->SetInputData(mesh);
  normals->SetJoinCoincidentPoints(join);
  normals->SetSplitting(splitting);
  normals->Update();
  if (joined)
  {
    *joined = normals->GetNumberOfJoinedPoints();
  }
  return normals->GetOutput();
}

// Whether the output's first points carry the input's array `name` unchanged.
bool KeepsPointData(vtkPolyData* input, vtkPolyData* output, const char* name)
{
  vtkDataArray* in = input->GetPointData()->GetArray(name);
  vtkDataArray* out = output->GetPointData()->GetArray(name);
  if (!in || !out || out->GetNumberOfTuples() < in->GetNumberOfTuples())
  {
    return false;
  }
  for (vtkIdType p = 0; p < in->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < in->GetNumberOfComponents(); ++c)
    {
      if (in->GetComponent(p, c) != out->GetComponent(p, c))
      {
        return false;
      }
    }
  }
  return true;
}

// Every polygon corner's normal within `degrees` of its face's (planar faces).
bool CornersCarryFaceNormals(vtkPolyData* output, double degrees)
{
  vtkDataArray* normals = output->GetPointData()->GetNormals();
  auto polys = vtk::TakeSmartPointer(output->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    polys->GetCurrentCell(size, ids);
    double a[3], b[3], c[3], e1[3], e2[3], face[3], n[3];
    output->GetPoint(ids[0], a);
    output->GetPoint(ids[1], b);
    output->GetPoint(ids[2], c);
    vtkMath::Subtract(b, a, e1);
    vtkMath::Subtract(c, a, e2);
    vtkMath::Cross(e1, e2, face);
    vtkMath::Normalize(face);
    for (vtkIdType k = 0; k < size; ++k)
    {
      normals->GetTuple(ids[k], n);
      if (vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(face, n)) > degrees)
      {
        return false;
      }
    }
  }
  return true;
}

void CheckSphereOfPieces(vtkPhongTest::Checks& checks)
{
  vtkNew<vtkSphereSource> whole;
  whole->SetThetaResolution(24);
  whole->SetPhiResolution(24);
  whole->Update();
  vtkNew<vtkPolyData> wholeMesh;
  wholeMesh->DeepCopy(whole->GetOutput());
  wholeMesh->GetPointData()->RemoveArray("Normals");
  const double exact = LargestRadialError(NormalsOf(wholeMesh, false));

  auto pieces = SphereOfPieces(4);
  const double seam = LargestRadialError(NormalsOf(pieces, false));
  checks.Expect(seam > 5.0, "four pieces, not joined: a seam (" + std::to_string(seam) + " deg)");

  vtkIdType joined = 0;
  auto output = NormalsOf(pieces, true, true, &joined);
  const double error = LargestRadialError(output);
  checks.Near(error, exact, 1e-4, "four pieces joined by position: the whole sphere's normals");
  // 4 cuts of 22 points, and each pole's 3 extra copies.
  checks.Expect(joined == 4 * 22 + 2 * 3, "joined points: " + std::to_string(joined));
  checks.Expect(
    output->GetNumberOfPoints() == pieces->GetNumberOfPoints(), "a smooth surface needs no copies");
  checks.Expect(KeepsPointData(pieces, output, "Piece"), "each copy keeps its own point data");

  // Global ids decide where they exist: all distinct, nothing is joined (the seam stays).
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("GlobalIds");
  ids->SetNumberOfTuples(pieces->GetNumberOfPoints());
  for (vtkIdType p = 0; p < pieces->GetNumberOfPoints(); ++p)
  {
    ids->SetValue(p, p);
  }
  pieces->GetPointData()->SetGlobalIds(ids);
  checks.Expect(LargestRadialError(NormalsOf(pieces, true)) > 5.0,
    "distinct global ids: nothing joined, whatever the positions");
  // The ids of the joined output's representatives: joined by id alone.
  vtkDataArray* originalIds = output->GetPointData()->GetArray("vtkOriginalPointIds");
  checks.Expect(originalIds != nullptr, "original point ids written");
  std::map<std::array<double, 3>, vtkIdType> first;
  for (vtkIdType p = 0; p < pieces->GetNumberOfPoints(); ++p)
  {
    double x[3];
    pieces->GetPoint(p, x);
    // Positions rounded to 1e-5: the copies a float step apart meet.
    const std::array<double, 3> key = { std::round(x[0] * 1e5), std::round(x[1] * 1e5),
      std::round(x[2] * 1e5) };
    ids->SetValue(p, first.emplace(key, p).first->second);
  }
  ids->Modified();
  checks.Near(LargestRadialError(NormalsOf(pieces, true)), exact, 1e-4,
    "four pieces joined by global ids: the whole sphere's normals");
}

void CheckCubes(vtkPhongTest::Checks& checks)
{
  // vtkCubeSource: each face its own four points, with texture coordinates.
  vtkNew<vtkCubeSource> cube;
  cube->Update();
  vtkNew<vtkPolyData> faces;
  faces->DeepCopy(cube->GetOutput());
  faces->GetPointData()->RemoveArray("Normals");
  auto split = NormalsOf(faces, true, true);
  checks.Expect(split->GetNumberOfPoints() == 24, "cube of own points, joined, split: 24 points");
  checks.Expect(CornersCarryFaceNormals(split, 1e-6), "joined and split: face normals");
  checks.Expect(KeepsPointData(faces, split, "TCoords"), "texture coordinates kept");
  // Without a name for the original ids the filter's default still maps the split points
  // back (a null name made the joined normals index past the input's points).
  vtkNew<vtkOpenMeshNormals> unnamed;
  unnamed->SetInputData(faces);
  unnamed->JoinCoincidentPointsOn();
  unnamed->SetOriginalPointIdsArrayName(nullptr);
  unnamed->Update();
  checks.Expect(CornersCarryFaceNormals(unnamed->GetOutput(), 1e-6) &&
      unnamed->GetOutput()->GetPointData()->GetArray("vtkOriginalPointIds"),
    "joined and split, original ids unnamed: face normals, vtkOriginalPointIds written");
  auto shared = NormalsOf(faces, true, false);
  checks.Expect(LargestRadialError(shared) < 0.05, "joined, not split: the corner's normal");

  // A cube of 8 shared points cut in two: faces 0-2 on points 0-7, faces 3-5 on copies.
  vtkNew<vtkPoints> points;
  for (int copy = 0; copy < 2; ++copy)
  {
    for (int i = 0; i < 8; ++i)
    {
      points->InsertNextPoint(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5);
    }
  }
  const vtkIdType quads[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  vtkNew<vtkCellArray> polys;
  for (int f = 0; f < 6; ++f)
  {
    vtkIdType ids[4];
    for (int k = 0; k < 4; ++k)
    {
      ids[k] = quads[f][k] + (f < 3 ? 0 : 8);
    }
    polys->InsertNextCell(4, ids);
  }
  vtkNew<vtkPolyData> halves;
  halves->SetPoints(points);
  halves->SetPolys(polys);
  auto output = NormalsOf(halves, true, true);
  checks.Expect(CornersCarryFaceNormals(output, 1e-6),
    "two halves of a cube, joined and split: every corner its face's normal");
  // Each of the 24 corners needs its own point: 16 input points, 8 copies.
  checks.Expect(output->GetNumberOfPoints() == 24,
    "copies where a point's corners got different normals: " +
      std::to_string(output->GetNumberOfPoints()));
}
}

int TestOpenMeshNormalsJoin(int, char*[])
{
  vtkPhongTest::Checks checks;
  CheckSphereOfPieces(checks);
  CheckCubes(checks);
  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
