// vtkOpenMeshNormals by value:
// - each weighting against its textbook definition, computed here directly,
//   at an interior and a boundary vertex of a small irregular mesh;
// - Max exact at every vertex of a sphere (double-precision points);
// - splitting: the two faces of every sharp edge use different points;
// - orientation: the majority wins (cell 0 reversed is not followed), closed
//   pieces turn outward on request, flipping reverses;
// - input people have: polygons, strips, verts and lines, non-manifold edges
//   and points, repeated indices, zero-area faces, NaN points, isolated points,
//   empty input: always finite unit normals, the promised counts and warnings;
// - positions-only updates equal a recomputation; the direct and the
//   add_face constructions give the same normals; progress and abort.

#include "vtkPhongTestUtilities.h"

#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkOpenMeshNormals.h"
#include "vtkPhongOFFReader.h"
#include "vtkPolyDataNormals.h"
#include "vtkStripper.h"
#include "vtkTriangleFilter.h"

#include <array>
#include <functional>
#include <limits>
#include <map>

namespace
{
using Vec = std::array<double, 3>;

Vec Sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
Vec CrossOf(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
double DotOf(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec Normalized(const Vec& a)
{
  const double length = std::sqrt(DotOf(a, a));
  return { a[0] / length, a[1] / length, a[2] / length };
}
double AngleDegrees(const Vec& a, const Vec& b)
{
  const double c = DotOf(Normalized(a), Normalized(b));
  return vtkMath::DegreesFromRadians(std::acos(std::min(1.0, std::max(-1.0, c))));
}

Vec PointNormal(vtkPolyData* output, vtkIdType id)
{
  Vec n;
  output->GetPointData()->GetNormals()->GetTuple(id, n.data());
  return n;
}

// Every point normal finite and of unit length.
bool AllUnit(vtkPolyData* output)
{
  vtkDataArray* normals = output->GetPointData()->GetNormals();
  if (!normals || normals->GetNumberOfTuples() != output->GetNumberOfPoints())
  {
    return false;
  }
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
  {
    Vec n;
    normals->GetTuple(i, n.data());
    if (!std::isfinite(n[0] + n[1] + n[2]) || std::abs(DotOf(n, n) - 1.0) > 1e-5)
    {
      return false;
    }
  }
  return true;
}

// The textbook vertex normal at corner point v of the given faces.
Vec Textbook(int weighting, const std::vector<Vec>& points,
  const std::vector<std::vector<vtkIdType>>& faces, vtkIdType v)
{
  Vec sum = { 0, 0, 0 };
  for (const auto& face : faces)
  {
    const size_t n = face.size();
    for (size_t k = 0; k < n; ++k)
    {
      if (face[k] != v)
      {
        continue;
      }
      const Vec& p = points[v];
      const Vec e1 = Sub(points[face[(k + 1) % n]], p);
      const Vec e2 = Sub(points[face[(k + n - 1) % n]], p);
      // Triangles only here: the face normal is e1 x e2, twice the area.
      const Vec faceVector = CrossOf(e1, e2);
      const double area2 = std::sqrt(DotOf(faceVector, faceVector));
      const Vec unit = { faceVector[0] / area2, faceVector[1] / area2, faceVector[2] / area2 };
      double w = 1.0;
      Vec term = unit;
      switch (weighting)
      {
        case vtkOpenMeshNormals::Uniform: // Gouraud 1971
          break;
        case vtkOpenMeshNormals::Area:
          w = 0.5 * area2;
          break;
        case vtkOpenMeshNormals::Angle: // Thurmer & Wuthrich 1998
          w = std::acos(DotOf(e1, e2) / std::sqrt(DotOf(e1, e1) * DotOf(e2, e2)));
          break;
        case vtkOpenMeshNormals::Max: // Max 1999
          w = 1.0 / (DotOf(e1, e1) * DotOf(e2, e2));
          term = faceVector;
          break;
      }
      for (int i = 0; i < 3; ++i)
      {
        sum[i] += w * term[i];
      }
    }
  }
  return Normalized(sum);
}
}

int TestOpenMeshNormals(int argc, char* argv[])
{
  vtkPhongTest::Checks checks;

  { // Each weighting is its definition, at an interior and a boundary vertex.
    const std::vector<Vec> points = { { 0.02, -0.01, 0.05 }, { 1.0, 0.1, 0.2 }, { 0.3, 0.9, -0.1 },
      { -0.7, 0.6, 0.25 }, { -0.9, -0.4, -0.2 }, { 0.2, -1.1, 0.3 }, { 1.4, 1.2, 0.6 } };
    const std::vector<std::vector<vtkIdType>> faces = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 4 },
      { 0, 4, 5 }, { 0, 5, 1 }, { 1, 6, 2 } };
    auto mesh = vtkPhongTest::MakeMesh(points, faces);
    for (int weighting = vtkOpenMeshNormals::Uniform; weighting <= vtkOpenMeshNormals::Max;
         ++weighting)
    {
      vtkNew<vtkOpenMeshNormals> normals;
      normals->SetInputData(mesh);
      normals->SetWeighting(weighting);
      normals->SplittingOff();
      normals->Update();
      vtkPolyData* out = normals->GetOutput();
      for (vtkIdType v : { vtkIdType(0), vtkIdType(1), vtkIdType(2) })
      {
        const double error =
          AngleDegrees(PointNormal(out, v), Textbook(weighting, points, faces, v));
        checks.Expect(error < 1e-5,
          std::string(normals->GetWeightingAsString()) + " at point " + std::to_string(v) +
            " is the textbook normal (off by " + std::to_string(error) + " degrees)");
      }
    }
  }

  { // Max is exact where the one-ring lies on a sphere: every vertex of one.
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(40);
    sphere->SetPhiResolution(23);
    sphere->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    sphere->Update();
    vtkPolyData* mesh = sphere->GetOutput();
    mesh->GetPointData()->SetNormals(nullptr);
    double worst[2] = { 0, 0 };
    for (int i = 0; i < 2; ++i)
    {
      vtkNew<vtkOpenMeshNormals> normals;
      normals->SetInputData(mesh);
      normals->SetWeighting(i == 0 ? vtkOpenMeshNormals::Max : vtkOpenMeshNormals::Uniform);
      normals->Update();
      vtkPolyData* out = normals->GetOutput();
      for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
      {
        Vec x;
        out->GetPoint(p, x.data());
        worst[i] = std::max(worst[i], AngleDegrees(PointNormal(out, p), x));
      }
    }
    checks.Expect(
      worst[0] < 1e-4, "Max is exact on a sphere (worst " + std::to_string(worst[0]) + " degrees)");
    checks.Expect(worst[1] > 0.1,
      "Uniform is not (worst " + std::to_string(worst[1]) + " degrees): the check can fail");
  }

  { // Splitting on CGAL's fandisk: the faces on each side of a sharp edge use
    // different points; the ids map back; nothing else is split.
    if (argc < 2 || !vtkPhongOFFReader::CanReadFile(argv[1]))
    {
      std::cerr << "TestOpenMeshNormals needs fandisk.off as its first argument\n";
      return EXIT_FAILURE;
    }
    vtkNew<vtkPhongOFFReader> reader;
    reader->SetFileName(argv[1]);
    reader->Update();
    vtkPolyData* mesh = reader->GetOutput();
    vtkNew<vtkOpenMeshNormals> normals;
    normals->SetInputData(mesh);
    normals->SetFeatureAngle(30.0);
    normals->Update();
    vtkPolyData* out = normals->GetOutput();
    checks.Expect(AllUnit(out), "fandisk: unit normals");
    checks.Expect(normals->GetNumberOfSplitPoints() > 0 &&
        out->GetNumberOfPoints() == mesh->GetNumberOfPoints() + normals->GetNumberOfSplitPoints(),
      "fandisk: " + std::to_string(normals->GetNumberOfSplitPoints()) + " points added");
    auto* original =
      vtkIdTypeArray::SafeDownCast(out->GetPointData()->GetArray("vtkOriginalPointIds"));
    bool mapsBack = original != nullptr;
    for (vtkIdType p = 0; mapsBack && p < out->GetNumberOfPoints(); ++p)
    {
      Vec a, b;
      out->GetPoint(p, a.data());
      mesh->GetPoint(original->GetValue(p), b.data());
      mapsBack = a == b;
    }
    checks.Expect(mapsBack, "fandisk: vtkOriginalPointIds maps every point back");
    // For every edge shared by two faces: split iff the dihedral angle is sharp.
    std::map<std::pair<vtkIdType, vtkIdType>, std::vector<vtkIdType>> edgeFaces;
    vtkCellArray* inPolys = mesh->GetPolys();
    const vtkIdType* ids;
    vtkIdType size;
    std::vector<Vec> faceNormal(inPolys->GetNumberOfCells());
    for (vtkIdType f = 0; f < inPolys->GetNumberOfCells(); ++f)
    {
      inPolys->GetCellAtId(f, size, ids);
      Vec p0, p1, p2;
      mesh->GetPoint(ids[0], p0.data());
      mesh->GetPoint(ids[1], p1.data());
      mesh->GetPoint(ids[2], p2.data());
      faceNormal[f] = Normalized(CrossOf(Sub(p1, p0), Sub(p2, p0)));
      for (vtkIdType k = 0; k < size; ++k)
      {
        const vtkIdType a = ids[k], b = ids[(k + 1) % size];
        edgeFaces[{ std::min(a, b), std::max(a, b) }].push_back(f);
      }
    }
    vtkCellArray* outPolys = out->GetPolys();
    auto outputPointOf = [&](vtkIdType face, vtkIdType inputPoint)
    {
      const vtkIdType* in;
      const vtkIdType* outIds;
      vtkIdType n, m;
      inPolys->GetCellAtId(face, n, in);
      outPolys->GetCellAtId(face, m, outIds);
      for (vtkIdType k = 0; k < n; ++k)
      {
        if (original->GetValue(outIds[k]) == inputPoint)
        {
          return outIds[k];
        }
      }
      return vtkIdType(-1);
    };
    // A fan is cut in two only where at least two sharp (or boundary) edges
    // meet; at the end of a crease the faces stay joined the other way round.
    const double cosFeature = std::cos(vtkMath::RadiansFromDegrees(30.0));
    std::map<vtkIdType, int> cutsAtPoint;
    for (const auto& edge : edgeFaces)
    {
      const bool cut = edge.second.size() != 2 ||
        DotOf(faceNormal[edge.second[0]], faceNormal[edge.second[1]]) <= cosFeature;
      cutsAtPoint[edge.first.first] += cut;
      cutsAtPoint[edge.first.second] += cut;
    }
    int wrong = 0, sharp = 0, creaseEnds = 0;
    for (const auto& edge : edgeFaces)
    {
      if (edge.second.size() != 2)
      {
        continue;
      }
      const vtkIdType f = edge.second[0], g = edge.second[1];
      const bool isSharp = DotOf(faceNormal[f], faceNormal[g]) <= cosFeature;
      sharp += isSharp;
      for (vtkIdType p : { edge.first.first, edge.first.second })
      {
        const bool split = outputPointOf(f, p) != outputPointOf(g, p);
        if (isSharp && cutsAtPoint[p] >= 2)
        {
          wrong += !split;
        }
        creaseEnds += isSharp && cutsAtPoint[p] < 2 && !split;
      }
    }
    checks.Expect(sharp > 100 && wrong == 0,
      "fandisk: both sides of all " + std::to_string(sharp) + " sharp edges are split (" +
        std::to_string(wrong) + " not; " + std::to_string(creaseEnds) + " crease ends joined)");
    vtkNew<vtkOpenMeshNormals> incremental;
    incremental->SetInputData(mesh);
    incremental->IncrementalConstructionOn();
    incremental->Update();
    checks.Expect(vtkPhongTest::ArraysEqual(out->GetPointData()->GetNormals(),
                    incremental->GetOutput()->GetPointData()->GetNormals()),
      "fandisk: direct and add_face constructions give the same normals");
  }

  { // Orientation: the majority wins; cell 0 reversed is not followed.
    auto sphere = vtkPhongTest::MakeSphere(24);
    sphere->GetPointData()->SetNormals(nullptr);
    vtkCellArray* polys = sphere->GetPolys();
    vtkNew<vtkCellArray> reversedSome;
    const vtkIdType* ids;
    vtkIdType size;
    int reversed = 0;
    for (vtkIdType f = 0; f < polys->GetNumberOfCells(); ++f)
    {
      polys->GetCellAtId(f, size, ids);
      std::vector<vtkIdType> cell(ids, ids + size);
      if (f == 0 || f % 7 == 3)
      {
        std::reverse(cell.begin(), cell.end());
        ++reversed;
      }
      reversedSome->InsertNextCell(size, cell.data());
    }
    sphere->SetPolys(reversedSome);
    vtkNew<vtkOpenMeshNormals> normals;
    normals->SetInputData(sphere);
    normals->Update();
    vtkPolyData* out = normals->GetOutput();
    int outward = 0;
    for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
    {
      Vec x;
      out->GetPoint(p, x.data());
      outward += DotOf(PointNormal(out, p), x) > 0.0;
    }
    checks.Expect(outward == out->GetNumberOfPoints(),
      "orientation follows the majority, not cell 0 (" + std::to_string(outward) + " of " +
        std::to_string(out->GetNumberOfPoints()) + " outward)");
    checks.Expect(normals->GetNumberOfReorientedFaces() == reversed,
      "the reversed faces are reported (" + std::to_string(normals->GetNumberOfReorientedFaces()) +
        " of " + std::to_string(reversed) + ")");

    // Entirely inward: AutoOrientNormals turns it out, FlipNormals back in.
    vtkNew<vtkPolyDataNormals> inward;
    inward->SetInputData(vtkPhongTest::MakeSphere(24));
    inward->FlipNormalsOn();
    inward->Update();
    vtkNew<vtkPolyData> inside;
    inside->CopyStructure(inward->GetOutput());
    for (int flip = 0; flip < 2; ++flip)
    {
      vtkNew<vtkOpenMeshNormals> auto_;
      auto_->SetInputData(inside);
      auto_->AutoOrientNormalsOn();
      auto_->SetFlipNormals(flip);
      auto_->Update();
      Vec x;
      auto_->GetOutput()->GetPoint(10, x.data());
      const bool out10 = DotOf(PointNormal(auto_->GetOutput(), 10), x) > 0.0;
      checks.Expect(out10 == (flip == 0),
        flip ? "FlipNormals turns the oriented sphere inward"
             : "AutoOrientNormals turns it outward");
    }
  }

  { // Input people have.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // 0-5: a quad pyramid base; 6: a repeated-index face; 7-9: a third face on
    // edge 0-1 (non-manifold); 10: isolated; 11: NaN point; 12, 13 zero-area.
    std::vector<Vec> points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0.1 }, { 0, 1, 0 },
      { 0.5, 0.5, 1 }, { 2, 0, 0 }, { 2, 1, 0 }, { 0.5, -0.5, 0.7 }, { 3, 0, 0 }, { 3, 1, 0 },
      { 5, 5, 5 }, { nan, 0, 0 }, { 4, 0, 0 }, { 4, 0, 0 } };
    std::vector<std::vector<vtkIdType>> faces = {
      { 0, 1, 2, 3 },           // a non-planar quad (Newell normal)
      { 0, 1, 4 },              // sides of the pyramid
      { 1, 2, 4 }, { 0, 1, 7 }, // a third face on edge 0-1: non-manifold
      { 1, 5, 6, 5, 2 },        // a repeated index
      { 8, 9, 11 },             // touches the NaN point
      { 8, 12, 9 },             // its neighbour, valid
      { 9, 12, 13 },            // zero area (12 and 13 coincide)
      { 2, 2, 4 },              // degenerate: two distinct points only
    };
    auto mesh = vtkPhongTest::MakeMesh(points, faces);
    vtkNew<vtkCellArray> verts;
    vtkIdType vertex = 10;
    verts->InsertNextCell(1, &vertex);
    mesh->SetVerts(verts);
    vtkNew<vtkCellArray> lines;
    const vtkIdType line[2] = { 3, 10 };
    lines->InsertNextCell(2, line);
    mesh->SetLines(lines);
    vtkNew<vtkCellArray> strips;
    const vtkIdType strip[5] = { 5, 8, 6, 9, 12 };
    strips->InsertNextCell(5, strip);
    mesh->SetStrips(strips);
    vtkNew<vtkIdTypeArray> cellIds;
    cellIds->SetName("cellId");
    for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
    {
      cellIds->InsertNextValue(c);
    }
    mesh->GetCellData()->AddArray(cellIds);

    vtkNew<vtkOpenMeshNormals> normals;
    vtkPhongTest::ErrorCollector messages;
    messages.Observe(normals);
    normals->SetInputData(mesh);
    normals->ComputeCellNormalsOn();
    normals->Update();
    vtkPolyData* out = normals->GetOutput();
    checks.Expect(AllUnit(out), "bad input: every point normal finite and unit");
    checks.Expect(
      out->GetNumberOfVerts() == 1 && out->GetNumberOfLines() == 1, "verts and lines pass through");
    checks.Expect(
      out->GetNumberOfPolys() == 9 + 3, "all 9 polygons kept, the strip's 3 triangles added");
    checks.Expect(normals->GetNumberOfNonManifoldFaces() >= 1 && messages.Contains("non-manifold"),
      "the non-manifold face is counted and reported");
    checks.Expect(normals->GetNumberOfFacesWithRepeatedPoints() == 2,
      "faces with repeated indices: " +
        std::to_string(normals->GetNumberOfFacesWithRepeatedPoints()));
    checks.Expect(normals->GetNumberOfDegenerateFaces() == 1, "one face left degenerate");
    const Vec isolated = PointNormal(out, 10);
    checks.Expect(isolated == Vec{ 0, 0, 1 }, "an isolated point gets +z");
    // Point 8 touches the NaN face and valid faces in the plane z = 0: its
    // normal is theirs (up or down, as the majority orients the piece).
    const double off = std::min(AngleDegrees(PointNormal(out, 8), Vec{ 0, 0, 1 }),
      AngleDegrees(PointNormal(out, 8), Vec{ 0, 0, -1 }));
    checks.Expect(off < 1e-6, "a NaN neighbour poisons nothing (" + std::to_string(off) + ")");
    vtkDataArray* cellNormals = out->GetCellData()->GetNormals();
    checks.Expect(cellNormals && cellNormals->GetNumberOfTuples() == out->GetNumberOfCells(),
      "a cell normal for every cell");
    auto* ids = vtkIdTypeArray::SafeDownCast(out->GetCellData()->GetArray("cellId"));
    checks.Expect(ids && ids->GetValue(out->GetNumberOfCells() - 1) == mesh->GetNumberOfCells() - 1,
      "the strip's triangles carry its cell data");

    vtkNew<vtkPolyData> empty;
    vtkNew<vtkOpenMeshNormals> nothing;
    nothing->SetInputData(empty);
    nothing->Update();
    checks.Expect(nothing->GetOutput()->GetNumberOfPoints() == 0, "empty input, empty output");
  }

  { // Two cones sharing their apex (a non-manifold point) and direct vs add_face.
    std::vector<Vec> points = { { 0, 0, 0 } };
    std::vector<std::vector<vtkIdType>> faces;
    for (int cone = 0; cone < 2; ++cone)
    {
      const double z = cone == 0 ? 1.0 : -1.0;
      const vtkIdType base = static_cast<vtkIdType>(points.size());
      for (int i = 0; i < 6; ++i)
      {
        const double a = 2.0 * vtkMath::Pi() * i / 6.0;
        points.push_back({ std::cos(a), std::sin(a), z });
      }
      for (int i = 0; i < 6; ++i)
      {
        const vtkIdType a = base + i, b = base + (i + 1) % 6;
        faces.push_back(
          cone == 0 ? std::vector<vtkIdType>{ 0, b, a } : std::vector<vtkIdType>{ 0, a, b });
      }
    }
    auto mesh = vtkPhongTest::MakeMesh(points, faces);
    vtkNew<vtkOpenMeshNormals> direct, incremental;
    vtkPhongTest::ErrorCollector quiet;
    quiet.Observe(direct);
    quiet.Observe(incremental);
    direct->SetInputData(mesh);
    incremental->SetInputData(mesh);
    incremental->IncrementalConstructionOn();
    direct->Update();
    incremental->Update();
    checks.Expect(AllUnit(direct->GetOutput()), "two cones: unit normals");
    checks.Expect(vtkPhongTest::ArraysEqual(direct->GetOutput()->GetPointData()->GetNormals(),
                    incremental->GetOutput()->GetPointData()->GetNormals()),
      "two cones: direct and add_face constructions agree");
  }

  { // A smooth mesh is computed point by point; when its points move (an animation) the
    // topology is built, then reused; every update equals a recomputation; progress is
    // reported and abort is honoured.
    auto mesh = vtkPhongTest::MakeSphere(48);
    mesh->GetPointData()->SetNormals(nullptr);
    vtkNew<vtkOpenMeshNormals> normals;
    normals->SetInputData(mesh);
    int progressEvents = 0;
    vtkNew<vtkCallbackCommand> onProgress;
    onProgress->SetClientData(&progressEvents);
    onProgress->SetCallback(
      [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
    normals->AddObserver(vtkCommand::ProgressEvent, onProgress);
    normals->Update();
    checks.Expect(normals->GetComputedPointByPoint(), "a smooth sphere is computed point by point");
    checks.Expect(progressEvents >= 3, "progress is reported point by point");
    const char* const updates[] = { "the first positions-only update builds the topology",
      "the next one reuses it" };
    for (int update = 0; update < 2; ++update)
    {
      vtkPoints* points = mesh->GetPoints();
      for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
      {
        double x[3];
        points->GetPoint(p, x);
        points->SetPoint(p, x[0] * (1.0 + 0.3 * x[2]), x[1], x[2] * 0.7);
      }
      points->Modified();
      progressEvents = 0;
      normals->Update();
      checks.Expect(
        !normals->GetComputedPointByPoint() && normals->GetTopologyReused() == (update == 1),
        updates[update]);
      checks.Expect(update == 1 || progressEvents >= 5, "progress is reported by the topology");
      vtkNew<vtkOpenMeshNormals> fresh;
      fresh->SetInputData(mesh);
      fresh->Update();
      checks.Expect(fresh->GetComputedPointByPoint(), "the recomputation is point by point");
      checks.Expect(vtkPhongTest::ArraysEqual(normals->GetOutput()->GetPointData()->GetNormals(),
                      fresh->GetOutput()->GetPointData()->GetNormals()),
        std::string(updates[update]) + ": equals a recomputation");
    }

    for (const bool pointByPoint : { true, false })
    {
      vtkNew<vtkOpenMeshNormals> aborted;
      aborted->SetInputData(mesh);
      aborted->SetPointByPoint(pointByPoint);
      vtkNew<vtkCallbackCommand> abort;
      abort->SetCallback([](vtkObject* caller, unsigned long, void*, void*)
        { static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1); });
      aborted->AddObserver(vtkCommand::ProgressEvent, abort);
      aborted->Update();
      checks.Expect(aborted->GetOutput()->GetNumberOfPoints() == 0,
        std::string("abort gives an empty output") +
          (pointByPoint ? " (point by point)" : " (topology)"));
    }
  }

  { // Degenerate polygons come out as they came in, also from cell arrays of 32-bit ids
    // (whose iterator hands out a scratch copy that the next cell overwrites).
    for (const bool use32 : { false, true })
    {
      vtkNew<vtkPoints> points;
      for (int i = 0; i < 5; ++i)
      {
        points->InsertNextPoint(i % 2, i / 2, 0.0);
      }
      vtkNew<vtkCellArray> polys;
      if (use32)
      {
        polys->Use32BitStorage();
      }
      const std::vector<std::vector<vtkIdType>> cells = { { 0, 1, 2 }, { 3, 3, 4 }, { 1, 3, 2 },
        { 4, 4, 0 } };
      for (const auto& cell : cells)
      {
        polys->InsertNextCell(static_cast<vtkIdType>(cell.size()), cell.data());
      }
      vtkNew<vtkPolyData> mesh;
      mesh->SetPoints(points);
      mesh->SetPolys(polys);
      vtkNew<vtkOpenMeshNormals> normals;
      normals->SetInputData(mesh);
      normals->SplittingOff();
      normals->Update();
      std::vector<std::vector<vtkIdType>> out;
      auto iterator = vtk::TakeSmartPointer(normals->GetOutput()->GetPolys()->NewIterator());
      for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
      {
        vtkIdType size;
        const vtkIdType* ids;
        iterator->GetCurrentCell(size, ids);
        out.emplace_back(ids, ids + size);
      }
      checks.Expect(out == cells,
        std::string(use32 ? "32" : "64") + "-bit ids: degenerate polygons keep their points");
    }
  }

  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
