#include "vtkOpenMeshNormalsExecution.h"

#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenMeshNormals.h"
#include "vtkOpenMeshNormalsFanRules.h"
#include "vtkOpenMeshNormalsTopology.h"
#include "vtkOpenMeshNormalsWeightings.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <numeric>

using namespace vtkOpenMeshNormalsDetail;

namespace
{
vtkSmartPointer<vtkFloatArray> NewNormals(vtkIdType count)
{
  auto normals = vtkSmartPointer<vtkFloatArray>::New();
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(count);
  return normals;
}
}

//------------------------------------------------------------------------------
vtkOpenMeshNormalsExecution::vtkOpenMeshNormalsExecution(const Settings& settings,
  vtkOpenMeshNormalsTopology& topology, vtkOpenMeshNormalsWorkspace& workspace, vtkPolyData* input,
  vtkPolyData* output)
  : Options(settings)
  , CosFeatureAngle(std::cos(vtkMath::RadiansFromDegrees(settings.FeatureAngle)))
  , Topology(topology)
  , Workspace(workspace)
  , Input(input)
  , Output(output)
  , NumberOfPoints(input->GetNumberOfPoints())
  , NumberOfFaces(topology.NumberOfFaces())
  , NumberOfVertices(static_cast<vtkIdType>(topology.VertexPoint.size()))
  , NumberOfCorners(static_cast<vtkIdType>(topology.Faces.Points.size()))
  , NumberOfPolys(input->GetPolys()->GetNumberOfCells())
  , NumberOfStripFaces(static_cast<vtkIdType>(topology.StripFaces.size()))
  , Triangles(topology.Faces.AllTriangles)
  , CornerPoint(&topology.Faces.Points)
{
}

//------------------------------------------------------------------------------
inline const double* vtkOpenMeshNormalsExecution::Position(Index corner) const
{
  return this->Positions + 3 * this->Topology.FaceVertex[corner];
}

//------------------------------------------------------------------------------
// The output point of a vertex's wedge: a point's own vertex keeps the
// point's id for its first wedge; the other wedges, and all the wedges of
// copies, are new points, numbered in vertex order.
inline vtkOpenMeshNormalsExecution::Index vtkOpenMeshNormalsExecution::WedgeId(
  Index vertex, Index wedge) const
{
  if (!this->Topology.VertexIsCopy[vertex])
  {
    return wedge == 0 ? this->Topology.VertexPoint[vertex]
                      : this->Workspace.FirstNewId[vertex] + wedge - 1;
  }
  return this->Workspace.FirstNewId[vertex] + wedge;
}

//------------------------------------------------------------------------------
// Into OpenMesh's vertices, or the topology's own array where it has no
// halfedge mesh (docs/normals.md, step 4).
void vtkOpenMeshNormalsExecution::LoadPositions()
{
  vtkPoints* inputPoints = this->Input->GetPoints();
  vtkOpenMeshNormalsTopology& topology = this->Topology;
  if (!topology.HasHalfedgeMesh)
  {
    topology.VertexPositions.resize(3 * static_cast<size_t>(this->NumberOfVertices));
  }
  double* own = topology.VertexPositions.data();
  vtkSMPTools::For(0, this->NumberOfVertices,
    [&](vtkIdType begin, vtkIdType end)
    {
      double p[3];
      for (vtkIdType v = begin; v < end; ++v)
      {
        inputPoints->GetPoint(topology.VertexPoint[v], p);
        if (topology.HasHalfedgeMesh)
        {
          topology.Mesh.set_point(
            VertexHandle(static_cast<int>(v)), HalfedgeMesh::Point(p[0], p[1], p[2]));
        }
        else
        {
          std::copy(p, p + 3, own + 3 * v);
        }
      }
    });
  if (this->NumberOfVertices == 0)
  {
    this->Positions = nullptr;
  }
  else
  {
    this->Positions = topology.HasHalfedgeMesh ? topology.Mesh.points()[0].data() : own;
  }
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsExecution::ComputeFaceNormals()
{
  vtkOpenMeshNormalsWorkspace& workspace = this->Workspace;
  workspace.UnitNormal.resize(this->NumberOfFaces);
  workspace.FaceLength.resize(this->NumberOfFaces);
  workspace.FaceValid.resize(this->NumberOfFaces);
  workspace.CornerWeight.resize(this->Triangles ? this->NumberOfCorners : 0);
  WithWeighting(this->Options.Weighting,
    [this](auto weighting)
    {
      using Weighting = decltype(weighting);
      vtkSMPTools::For(0, this->NumberOfFaces,
        [this](vtkIdType begin, vtkIdType end)
        {
          for (Index f = static_cast<Index>(begin); f < end; ++f)
          {
            this->ComputeFaceNormal<Weighting>(f);
          }
        });
    });
}

//------------------------------------------------------------------------------
// Newell's method about the first corner: the sum is twice the area times the
// unit normal, for polygons of any size, planar or not.
template <typename Weighting>
void vtkOpenMeshNormalsExecution::ComputeFaceNormal(Index f)
{
  const FaceList& faces = this->Topology.Faces;
  vtkOpenMeshNormalsWorkspace& workspace = this->Workspace;
  const Index first = faces.Offsets[f], last = faces.Offsets[f + 1];
  const double* origin = this->Position(first);
  Vector sum = { 0.0, 0.0, 0.0 };
  bool finite = IsFinite(origin);
  for (Index c = first + 1; c + 1 < last; ++c)
  {
    const double* a = this->Position(c);
    const double* b = this->Position(c + 1);
    finite = finite && IsFinite(a) && IsFinite(b);
    const Vector n = Cross(Subtract(a, origin), Subtract(b, origin));
    sum[0] += n[0];
    sum[1] += n[1];
    sum[2] += n[2];
  }
  const FaceNormal face = MakeFaceNormal(sum, finite);
  workspace.FaceValid[f] = face.Valid;
  workspace.FaceLength[f] = face.Length;
  workspace.UnitNormal[f] = face.Unit;
  if (this->Triangles)
  {
    this->StoreTriangleCornerWeights<Weighting>(first, face);
  }
}

//------------------------------------------------------------------------------
template <typename Weighting>
void vtkOpenMeshNormalsExecution::StoreTriangleCornerWeights(Index first, const FaceNormal& face)
{
  const double* p[3] = { this->Position(first), this->Position(first + 1),
    this->Position(first + 2) };
  for (int k = 0; k < 3; ++k)
  {
    this->Workspace.CornerWeight[first + k] = TriangleCornerWeightAt<Weighting>(p, k, face);
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenMeshNormalsExecution::OrientComponents()
{
  this->ApplyFaceSigns(this->ComputeComponentSigns());
  vtkIdType reoriented = 0;
  for (vtkIdType f = 0; f < this->NumberOfFaces; ++f)
  {
    reoriented += (this->Workspace.FaceSign[f] < 0) != (this->Topology.FaceReversed[f] != 0);
  }
  return reoriented;
}

//------------------------------------------------------------------------------
// With AutoOrientNormals, -1 for the closed pieces of negative signed volume;
// +1 for the others.
vtkOpenMeshNormalsExecution::Buffer<signed char>
vtkOpenMeshNormalsExecution::ComputeComponentSigns() const
{
  const vtkOpenMeshNormalsTopology& topology = this->Topology;
  const vtkOpenMeshNormalsWorkspace& workspace = this->Workspace;
  const vtkIdType numberOfComponents = static_cast<vtkIdType>(topology.ComponentClosed.size());
  Buffer<signed char> componentSign(numberOfComponents, 1);
  if (!this->Options.AutoOrientNormals)
  {
    return componentSign;
  }
  std::vector<double> volume(numberOfComponents, 0.0);
  for (vtkIdType f = 0; f < this->NumberOfFaces; ++f)
  {
    const vtkIdType c = topology.FaceComponent[f];
    if (topology.ComponentClosed[c] && workspace.FaceValid[f])
    {
      // The cone from the origin over a planar face has volume N.p0 / 6;
      // these add up to the piece's signed volume.
      const double* p = this->Position(topology.Faces.Offsets[f]);
      const Vector& n = workspace.UnitNormal[f];
      volume[c] += workspace.FaceLength[f] * (n[0] * p[0] + n[1] * p[1] + n[2] * p[2]) / 6.0;
    }
  }
  for (vtkIdType c = 0; c < numberOfComponents; ++c)
  {
    componentSign[c] = (topology.ComponentClosed[c] && volume[c] < 0.0) ? -1 : 1;
  }
  return componentSign;
}

//------------------------------------------------------------------------------
// Each face's sign (its piece's, reversed by FlipNormals), applied to its
// unit normal.
void vtkOpenMeshNormalsExecution::ApplyFaceSigns(const Buffer<signed char>& componentSign)
{
  const signed char flip = this->Options.FlipNormals ? -1 : 1;
  const Buffer<Index>& faceComponent = this->Topology.FaceComponent;
  Buffer<signed char>& faceSign = this->Workspace.FaceSign;
  Buffer<Vector>& unitNormal = this->Workspace.UnitNormal;
  faceSign.resize(this->NumberOfFaces);
  vtkSMPTools::For(0, this->NumberOfFaces,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        const signed char sign = componentSign[faceComponent[f]] * flip;
        faceSign[f] = sign;
        if (sign < 0)
        {
          unitNormal[f] = { -unitNormal[f][0], -unitNormal[f][1], -unitNormal[f][2] };
        }
      }
    });
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsExecution::ComputeSharedPointNormals()
{
  this->PointNormals = NewNormals(this->NumberOfPoints);
  WithWeighting(this->Options.Weighting,
    [this](auto weighting)
    {
      this->SumSharedPointNormals(
        CornerContribution(weighting, this->Topology, this->Workspace, this->Positions));
    });
}

//------------------------------------------------------------------------------
// Serial, in corner order, so that each point's sum adds up in a fixed order.
template <typename Contribution>
void vtkOpenMeshNormalsExecution::SumSharedPointNormals(const Contribution& contribution)
{
  const FaceList& faces = this->Topology.Faces;
  Buffer<Vector> sums(this->NumberOfPoints, Vector{ 0.0, 0.0, 0.0 });
  for (vtkIdType c = 0; c < this->NumberOfCorners; ++c)
  {
    contribution(c, sums[faces.Points[c]]);
  }
  float* normals = this->PointNormals->GetPointer(0);
  vtkSMPTools::For(0, this->NumberOfPoints,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType p = begin; p < end; ++p)
      {
        StoreNormal(sums[p], normals + 3 * p);
      }
    });
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsExecution::CutFans()
{
  vtkOpenMeshNormalsWorkspace& workspace = this->Workspace;
  workspace.Cuts.resize(this->Topology.FanCorners.size());
  workspace.WedgeCount.resize(this->NumberOfVertices);
  workspace.SingleNormal.resize(3 * static_cast<size_t>(this->NumberOfVertices));
  workspace.SplitCornerPoint.resize(this->NumberOfCorners);
  WithWeighting(this->Options.Weighting,
    [this](auto weighting)
    {
      const CornerContribution contribution(
        weighting, this->Topology, this->Workspace, this->Positions);
      vtkSMPTools::For(0, this->NumberOfVertices,
        [&](vtkIdType begin, vtkIdType end)
        {
          for (Index v = static_cast<Index>(begin); v < end; ++v)
          {
            this->CutFan(v, contribution);
          }
        });
    });
}

//------------------------------------------------------------------------------
// Cuts the fan of vertex v after each entry at a gap or a sharp edge (the
// same test as vtkPolyDataNormals: the unit normals' dot product at most
// cos(FeatureAngle)). A fan cut once or never is one wedge.
template <typename Contribution>
void vtkOpenMeshNormalsExecution::CutFan(Index v, const Contribution& contribution)
{
  const vtkOpenMeshNormalsTopology& topology = this->Topology;
  vtkOpenMeshNormalsWorkspace& workspace = this->Workspace;
  const Index first = topology.FanOffsets[v], last = topology.FanOffsets[v + 1];
  Index count = 0;
  for (Index here = first; here < last; ++here)
  {
    const Index next = here + 1 < last ? here + 1 : first;
    bool cut = !topology.FanLinked[here];
    if (!cut)
    {
      const Index f = topology.FanFaces[here], g = topology.FanFaces[next];
      cut = IsSharpEdge(workspace.FaceValid[f] != 0, workspace.UnitNormal[f],
        workspace.FaceValid[g] != 0, workspace.UnitNormal[g], this->CosFeatureAngle);
    }
    workspace.Cuts[here] = cut;
    count += cut;
  }
  if (count <= 1 && this->IsSingularFan(first, last))
  {
    // No normal suits all the faces (a cone's apex): each face keeps its own there, or the
    // averaged normal would shade the cone towards its tip as if it were flat.
    std::fill(workspace.Cuts.begin() + first, workspace.Cuts.begin() + last, true);
    count = last - first;
  }
  workspace.WedgeCount[v] = first == last ? 0 : std::max<Index>(count, 1);
  if (workspace.WedgeCount[v] == 1 && !topology.VertexIsCopy[v])
  {
    this->StoreSingleWedgeNormal(v, contribution);
  }
}

//------------------------------------------------------------------------------
bool vtkOpenMeshNormalsExecution::IsSingularFan(Index first, Index last) const
{
  const vtkOpenMeshNormalsWorkspace& workspace = this->Workspace;
  const Buffer<Index>& fanFaces = this->Topology.FanFaces;
  return vtkOpenMeshNormalsDetail::IsSingularFan(
    last - first,
    [&](Index i)
    {
      const Index f = fanFaces[first + i];
      return std::make_pair(workspace.FaceValid[f] != 0, &workspace.UnitNormal[f]);
    },
    this->CosFeatureAngle);
}

//------------------------------------------------------------------------------
// A vertex of one wedge (most of them) is done in the pass that cuts: its
// normal, and its point's id for its corners.
template <typename Contribution>
void vtkOpenMeshNormalsExecution::StoreSingleWedgeNormal(Index v, const Contribution& contribution)
{
  const vtkOpenMeshNormalsTopology& topology = this->Topology;
  vtkOpenMeshNormalsWorkspace& workspace = this->Workspace;
  Vector sum = { 0.0, 0.0, 0.0 };
  for (Index entry = topology.FanOffsets[v]; entry < topology.FanOffsets[v + 1]; ++entry)
  {
    const Index corner = topology.FanCorners[entry];
    contribution(corner, sum);
    workspace.SplitCornerPoint[corner] = topology.VertexPoint[v];
  }
  StoreNormal(sum, workspace.SingleNormal.data() + 3 * static_cast<size_t>(v));
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenMeshNormalsExecution::NumberWedges()
{
  const vtkOpenMeshNormalsTopology& topology = this->Topology;
  vtkOpenMeshNormalsWorkspace& workspace = this->Workspace;
  workspace.FirstNewId.resize(this->NumberOfVertices);
  Index nextId = static_cast<Index>(this->NumberOfPoints);
  for (Index v = 0; v < this->NumberOfVertices; ++v)
  {
    workspace.FirstNewId[v] = nextId;
    const Index wedges = workspace.WedgeCount[v];
    const bool copy = topology.VertexIsCopy[v] != 0;
    nextId += wedges - (wedges > 0 && !copy ? 1 : 0);
    if (wedges > 1 || (copy && wedges > 0))
    {
      this->MultiWedge.push_back(v);
    }
  }
  this->NumberOfOutputPoints = nextId;
  return this->NumberOfOutputPoints - this->NumberOfPoints;
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsExecution::StoreWedgeNormals()
{
  this->PointNormals = NewNormals(this->NumberOfOutputPoints);
  float* normals = this->PointNormals->GetPointer(0);
  // Points no face uses (isolated, or only in degenerate faces, verts, lines): +z.
  vtkSMPTools::For(0, this->NumberOfPoints,
    [normals](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType p = begin; p < end; ++p)
      {
        normals[3 * p] = 0.f;
        normals[3 * p + 1] = 0.f;
        normals[3 * p + 2] = 1.f;
      }
    });
  this->CopySingleWedgeNormals(normals);
  WithWeighting(this->Options.Weighting,
    [this, normals](auto weighting)
    {
      const CornerContribution contribution(
        weighting, this->Topology, this->Workspace, this->Positions);
      vtkSMPTools::For(0, static_cast<vtkIdType>(this->MultiWedge.size()),
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType i = begin; i < end; ++i)
          {
            this->StoreWedgeNormalsOf(this->MultiWedge[i], contribution, normals);
          }
        });
    });
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsExecution::CopySingleWedgeNormals(float* normals) const
{
  const vtkOpenMeshNormalsTopology& topology = this->Topology;
  const vtkOpenMeshNormalsWorkspace& workspace = this->Workspace;
  vtkSMPTools::For(0, this->NumberOfVertices,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (Index v = static_cast<Index>(begin); v < end; ++v)
      {
        if (workspace.WedgeCount[v] == 1 && !topology.VertexIsCopy[v])
        {
          std::copy_n(workspace.SingleNormal.data() + 3 * static_cast<size_t>(v), 3,
            normals + 3 * static_cast<size_t>(topology.VertexPoint[v]));
        }
      }
    });
}

//------------------------------------------------------------------------------
// A vertex cut into several wedges, or a copy: each wedge its normal and
// output point. The walk starts right after a cut, so that every wedge is one
// run of the fan.
template <typename Contribution>
void vtkOpenMeshNormalsExecution::StoreWedgeNormalsOf(
  Index v, const Contribution& contribution, float* normals)
{
  const vtkOpenMeshNormalsTopology& topology = this->Topology;
  const Buffer<char>& cuts = this->Workspace.Cuts;
  const Index first = topology.FanOffsets[v], last = topology.FanOffsets[v + 1];
  Index start = first;
  for (Index e = first; e < last; ++e)
  {
    if (cuts[e])
    {
      start = e + 1 < last ? e + 1 : first;
      break;
    }
  }
  Index wedge = 0, runStart = start, entry = start;
  Vector sum = { 0.0, 0.0, 0.0 };
  for (Index step = 0; step < last - first; ++step)
  {
    contribution(topology.FanCorners[entry], sum);
    const Index following = entry + 1 < last ? entry + 1 : first;
    if (cuts[entry] || step == last - first - 1)
    {
      const Index id = this->WedgeId(v, wedge);
      StoreNormal(sum, normals + 3 * static_cast<size_t>(id));
      this->AssignWedgeCorners(v, runStart, entry, id);
      ++wedge;
      sum = { 0.0, 0.0, 0.0 };
      runStart = following;
    }
    entry = following;
  }
}

//------------------------------------------------------------------------------
// The corners of the run [runStart, runEnd] of vertex v's fan (wrapping
// around) get the output point id.
void vtkOpenMeshNormalsExecution::AssignWedgeCorners(
  Index v, Index runStart, Index runEnd, Index id)
{
  const vtkOpenMeshNormalsTopology& topology = this->Topology;
  const Index first = topology.FanOffsets[v], last = topology.FanOffsets[v + 1];
  for (Index e = runStart;; e = e + 1 < last ? e + 1 : first)
  {
    this->Workspace.SplitCornerPoint[topology.FanCorners[e]] = id;
    if (e == runEnd)
    {
      break;
    }
  }
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsExecution::FindSplitSources()
{
  vtkOpenMeshNormalsWorkspace& workspace = this->Workspace;
  // The same cuts and orientation as last time: the same output connectivity.
  this->SameConnectivity = workspace.LastPolys && workspace.LastCuts == workspace.Cuts &&
    workspace.LastCornerPoint.size() == static_cast<size_t>(this->NumberOfCorners);
  if (this->SameConnectivity)
  {
    this->CornerPoint = &workspace.LastCornerPoint;
    this->SplitSource = workspace.LastSplitSource;
  }
  else
  {
    this->SplitSource.resize(this->NumberOfOutputPoints - this->NumberOfPoints);
    for (Index v : this->MultiWedge)
    {
      const Index end = this->WedgeId(v, workspace.WedgeCount[v] - 1) + 1;
      for (Index id = workspace.FirstNewId[v]; id < end; ++id)
      {
        this->SplitSource[id - this->NumberOfPoints] = this->Topology.VertexPoint[v];
      }
    }
    this->CornerPoint = &workspace.SplitCornerPoint;
  }
  workspace.LastCuts = workspace.Cuts;
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsExecution::BuildOutputPolys()
{
  vtkOpenMeshNormalsWorkspace& workspace = this->Workspace;
  const bool signsUnchanged = std::all_of(workspace.FaceSign.begin(), workspace.FaceSign.end(),
                                [](signed char sign) { return sign > 0; }) &&
    !this->Options.AutoOrientNormals && !this->Options.FlipNormals;
  if (this->SameConnectivity && signsUnchanged)
  {
    this->OutputPolys = workspace.LastPolys;
    return;
  }
  if (this->OutputPolysAreInputPolys(signsUnchanged))
  {
    this->OutputPolys = this->Input->GetPolys();
    workspace.LastPolys = nullptr;
    return;
  }
  this->OutputPolys = this->NewOutputPolys();
  if (this->Options.Splitting && signsUnchanged)
  {
    workspace.LastPolys = this->OutputPolys;
    workspace.LastSplitSource = this->SplitSource;
    workspace.LastCornerPoint = *this->CornerPoint;
  }
  else
  {
    workspace.LastPolys = nullptr;
  }
}

//------------------------------------------------------------------------------
// Whether the output polygons would be the input's, id for id: only polygons,
// each a face as it came (no repeated point removed, none reversed), and
// every corner keeping its input point (nothing split or copied). Then the
// input's cell array is passed on, as the points are, instead of writing
// (and first-touching) a copy: the common case of a smooth, consistent mesh.
bool vtkOpenMeshNormalsExecution::OutputPolysAreInputPolys(bool signsUnchanged) const
{
  const vtkOpenMeshNormalsTopology& topology = this->Topology;
  if (!signsUnchanged || this->NumberOfStripFaces > 0 || this->Input->GetNumberOfStrips() > 0 ||
    !this->SplitSource.empty() || topology.RepeatedPointFaces > 0 || topology.DegenerateFaces > 0 ||
    topology.NumberOfFaces() != this->NumberOfPolys ||
    std::any_of(topology.FaceReversed.begin(), topology.FaceReversed.end(),
      [](char reversed) { return reversed != 0; }))
  {
    return false;
  }
  // Without split points every corner's output point is its input point;
  // checked rather than assumed, in parallel.
  const Buffer<Index>& cornerPoint = *this->CornerPoint;
  const Buffer<Index>& points = topology.Faces.Points;
  if (&cornerPoint == &points)
  {
    return true;
  }
  std::atomic<bool> same(cornerPoint.size() == points.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(points.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      if (same &&
        !std::equal(points.begin() + begin, points.begin() + end, cornerPoint.begin() + begin))
      {
        same = false;
      }
    });
  return same;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkCellArray> vtkOpenMeshNormalsExecution::NewOutputPolys() const
{
  const vtkOpenMeshNormalsTopology& topology = this->Topology;
  const FaceList& faces = topology.Faces;
  const vtkIdType numberOfPolys = this->NumberOfPolys;
  auto polyOffsets = vtkSmartPointer<vtkIdTypeArray>::New();
  polyOffsets->SetNumberOfTuples(numberOfPolys + this->NumberOfStripFaces + 1);
  vtkIdType* offsets = polyOffsets->GetPointer(0);
  offsets[0] = 0;
  std::vector<vtkIdType> degenerateIds;
  std::vector<vtkIdType> degenerateFirst(numberOfPolys, 0);
  this->CountPolygonSizes(offsets, degenerateIds, degenerateFirst);
  for (vtkIdType i = 0; i < this->NumberOfStripFaces; ++i)
  {
    const vtkIdType f = topology.StripFaces[i];
    offsets[numberOfPolys + i + 1] =
      offsets[numberOfPolys + i] + faces.Offsets[f + 1] - faces.Offsets[f];
  }
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  connectivity->SetNumberOfTuples(offsets[numberOfPolys + this->NumberOfStripFaces]);
  vtkIdType* ids = connectivity->GetPointer(0);
  vtkSMPTools::For(0, numberOfPolys,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType poly = begin; poly < end; ++poly)
      {
        const vtkIdType f = topology.PolyFace[poly];
        if (f >= 0)
        {
          this->WriteFace(f, ids + offsets[poly]);
        }
        else
        {
          const vtkIdType* original = degenerateIds.data() + degenerateFirst[poly];
          std::copy(original, original + (offsets[poly + 1] - offsets[poly]), ids + offsets[poly]);
        }
      }
    });
  vtkSMPTools::For(0, this->NumberOfStripFaces,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        this->WriteFace(topology.StripFaces[i], ids + offsets[numberOfPolys + i]);
      }
    });
  auto outputPolys = vtkSmartPointer<vtkCellArray>::New();
  outputPolys->SetData(polyOffsets, connectivity);
  return outputPolys;
}

//------------------------------------------------------------------------------
// The offsets of the output polygons: a face's size, or a degenerate
// polygon's original size. A degenerate polygon's original points are copied to
// degenerateIds from degenerateFirst[poly] on: the iterator's cell pointer is into its own
// scratch list for cell arrays of 32-bit ids, overwritten by the next cell.
void vtkOpenMeshNormalsExecution::CountPolygonSizes(vtkIdType* offsets,
  std::vector<vtkIdType>& degenerateIds, std::vector<vtkIdType>& degenerateFirst) const
{
  const Buffer<Index>& polyFace = this->Topology.PolyFace;
  const FaceList& faces = this->Topology.Faces;
  const bool everyPolygonIsAFace =
    std::none_of(polyFace.begin(), polyFace.end(), [](Index face) { return face < 0; });
  if (everyPolygonIsAFace)
  {
    for (vtkIdType poly = 0; poly < this->NumberOfPolys; ++poly)
    {
      const Index f = polyFace[poly];
      offsets[poly + 1] = offsets[poly] + (faces.Offsets[f + 1] - faces.Offsets[f]);
    }
    return;
  }
  auto iterator = vtk::TakeSmartPointer(this->Input->GetPolys()->NewIterator());
  vtkIdType poly = 0;
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal();
       iterator->GoToNextCell(), ++poly)
  {
    const vtkIdType f = polyFace[poly];
    vtkIdType size = 0;
    if (f >= 0)
    {
      size = faces.Offsets[f + 1] - faces.Offsets[f];
    }
    else
    {
      const vtkIdType* points;
      iterator->GetCurrentCell(size, points);
      degenerateFirst[poly] = static_cast<vtkIdType>(degenerateIds.size());
      degenerateIds.insert(degenerateIds.end(), points, points + size);
    }
    offsets[poly + 1] = offsets[poly] + size;
  }
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsExecution::WriteFace(vtkIdType f, vtkIdType* out) const
{
  const FaceList& faces = this->Topology.Faces;
  const Buffer<Index>& pointOfCorner = *this->CornerPoint;
  const vtkIdType first = faces.Offsets[f], size = faces.Offsets[f + 1] - first;
  const bool kept = this->Workspace.FaceSign[f] > 0;
  for (vtkIdType k = 0; k < size; ++k)
  {
    // A reversed face: (p0, p1, ..., pn-1) written as (p0, pn-1, ..., p1).
    const vtkIdType i = kept ? k : (k == 0 ? 0 : size - k);
    out[k] = pointOfCorner[first + i];
  }
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsExecution::WritePoints()
{
  vtkNew<vtkIdList> copies;
  copies->SetNumberOfIds(static_cast<vtkIdType>(this->SplitSource.size()));
  std::copy(this->SplitSource.begin(), this->SplitSource.end(), copies->begin());
  vtkOpenMeshNormalsExecution::WritePointsWithCopies(this->Input, copies, this->Output);
  if (this->PointNormals)
  {
    this->PointNormals->SetName("Normals");
    this->Output->GetPointData()->SetNormals(this->PointNormals);
  }
  if (this->Options.Splitting)
  {
    vtkOpenMeshNormalsExecution::StoreOriginalPointIds(
      this->Output, this->Options.OriginalPointIdsArrayName, this->NumberOfPoints, copies);
  }
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsExecution::WritePointsWithCopies(
  vtkPolyData* input, vtkIdList* copies, vtkPolyData* output)
{
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  outPD->Initialize();
  const vtkIdType added = copies->GetNumberOfIds();
  if (added == 0)
  {
    output->SetPoints(input->GetPoints());
    outPD->CopyNormalsOff();
    outPD->PassData(inPD);
    return;
  }
  vtkNew<vtkIdList> destinations;
  destinations->SetNumberOfIds(added);
  const vtkIdType first = input->GetNumberOfPoints();
  for (vtkIdType i = 0; i < added; ++i)
  {
    destinations->SetId(i, first + i);
  }
  vtkPoints* inputPoints = input->GetPoints();
  vtkNew<vtkPoints> points;
  points->SetDataType(inputPoints->GetDataType());
  points->DeepCopy(inputPoints);
  points->GetData()->InsertTuples(destinations, copies, inputPoints->GetData());
  output->SetPoints(points);
  for (int a = 0; a < inPD->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* source = inPD->GetAbstractArray(a);
    if (source == inPD->GetNormals())
    {
      continue;
    }
    auto copy = vtk::TakeSmartPointer(source->NewInstance());
    copy->DeepCopy(source);
    copy->InsertTuples(destinations, copies, source);
    const int index = outPD->AddArray(copy);
    for (int attribute = 0; attribute < vtkDataSetAttributes::NUM_ATTRIBUTES; ++attribute)
    {
      if (attribute != vtkDataSetAttributes::NORMALS &&
        inPD->GetAbstractAttribute(attribute) == source)
      {
        outPD->SetActiveAttribute(index, attribute);
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsExecution::StoreOriginalPointIds(
  vtkPolyData* output, const char* idsName, vtkIdType inputPoints, vtkIdList* copies)
{
  vtkNew<vtkIdTypeArray> originalIds;
  originalIds->SetName(idsName);
  originalIds->SetNumberOfTuples(inputPoints + copies->GetNumberOfIds());
  vtkIdType* original = originalIds->GetPointer(0);
  std::iota(original, original + inputPoints, vtkIdType(0));
  std::copy(copies->begin(), copies->end(), original + inputPoints);
  output->GetPointData()->AddArray(originalIds);
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsExecution::WriteCells()
{
  // Vertices and lines as they were, then the polygons.
  this->Output->SetVerts(this->Input->GetVerts());
  this->Output->SetLines(this->Input->GetLines());
  this->Output->SetPolys(this->OutputPolys);
  this->CopyCellData();
  if (this->Options.ComputeCellNormals)
  {
    this->StoreCellNormals();
  }
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsExecution::CopyCellData()
{
  vtkCellData* inCD = this->Input->GetCellData();
  vtkCellData* outCD = this->Output->GetCellData();
  if (this->Input->GetNumberOfStrips() == 0)
  {
    outCD->CopyNormalsOff();
    outCD->PassData(inCD);
    return;
  }
  // Strips became triangles: each carries its strip's cell data.
  const vtkIdType before = this->Input->GetNumberOfVerts() + this->Input->GetNumberOfLines();
  const vtkIdType total = before + this->NumberOfPolys + this->NumberOfStripFaces;
  vtkNew<vtkIdList> sources;
  vtkNew<vtkIdList> destinations;
  sources->SetNumberOfIds(total);
  destinations->SetNumberOfIds(total);
  for (vtkIdType c = 0; c < before + this->NumberOfPolys; ++c)
  {
    sources->SetId(c, c);
  }
  for (vtkIdType i = 0; i < this->NumberOfStripFaces; ++i)
  {
    sources->SetId(
      before + this->NumberOfPolys + i, this->Topology.FaceCell[this->Topology.StripFaces[i]]);
  }
  for (vtkIdType c = 0; c < total; ++c)
  {
    destinations->SetId(c, c);
  }
  outCD->CopyNormalsOff();
  outCD->CopyAllocate(inCD, total);
  outCD->CopyData(inCD, sources, destinations);
}

//------------------------------------------------------------------------------
// The faces' unit normals; (0, 0, 1) for vertices, lines and degenerate
// polygons.
void vtkOpenMeshNormalsExecution::StoreCellNormals()
{
  const vtkOpenMeshNormalsTopology& topology = this->Topology;
  const Buffer<Vector>& unitNormal = this->Workspace.UnitNormal;
  const vtkIdType before = this->Input->GetNumberOfVerts() + this->Input->GetNumberOfLines();
  vtkNew<vtkFloatArray> cellNormals;
  cellNormals->SetName("Normals");
  cellNormals->SetNumberOfComponents(3);
  const vtkIdType total = this->Output->GetNumberOfCells();
  cellNormals->SetNumberOfTuples(total);
  const Vector up = { 0.0, 0.0, 1.0 };
  for (vtkIdType c = 0; c < total; ++c)
  {
    StoreNormal(up, cellNormals->GetPointer(3 * c));
  }
  for (vtkIdType poly = 0; poly < this->NumberOfPolys; ++poly)
  {
    const vtkIdType f = topology.PolyFace[poly];
    if (f >= 0)
    {
      StoreNormal(unitNormal[f], cellNormals->GetPointer(3 * (before + poly)));
    }
  }
  for (vtkIdType i = 0; i < this->NumberOfStripFaces; ++i)
  {
    StoreNormal(unitNormal[topology.StripFaces[i]],
      cellNormals->GetPointer(3 * (before + this->NumberOfPolys + i)));
  }
  this->Output->GetCellData()->SetNormals(cellNormals);
}
