#include "vtkPhongClosedSurface.h"

#include "vtkActor.h"
#include "vtkArrayDispatch.h"
#include "vtkBoundingBox.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPhongBackgroundTask.h"
#include "vtkPhongBufferBlocks.h"
#include "vtkPhongOpenGL.h"
#include "vtkPhongShaderCode.h"
#include "vtkPhongVisibleClusters.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShaderProperty.h"
#include "vtkTexture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <utility>

namespace
{
// How far beyond the near plane (in normalized depth, -1 at the plane) every corner of the
// bounds must lie: well above the rounding of the GPU's clipping, well below any gap a
// camera leaves in practice (5e-5 of the near distance in perspective).
constexpr double NearPlaneMargin = 1e-4;

// A closed surface whose volume is below this share of its bounds' diagonal cubed is flat
// (a sheet modelled with both sides): its orientation says nothing.
constexpr double FlatVolumeShare = 1e-9;

// How many ray-triangle tests the check of cavities may take (about 0.1 s).
constexpr size_t MaximumEnclosureTests = size_t(16) << 20;

// An edge's other point, below 2^31, is packed with its direction in 32 bits.
constexpr std::uint64_t LargestPackedId = (std::uint64_t(1) << 31) - 1;

// The welding's mark of a point that is not finite.
constexpr std::uint32_t NotFinite = std::numeric_limits<std::uint32_t>::max();

// How many edges the closedness check gathers at a time: a quarter of them, at least 2^16
// and at most 2^24 (64 MB), a fraction of the index buffer's copy.
size_t EdgesPerRange(size_t edges)
{
  return std::min(std::max(edges / 4, size_t(1) << 16), size_t(1) << 24);
}

template <typename Position>
bool IsFinite(const Position& x)
{
  return vtkMath::IsFinite(x[0]) && vtkMath::IsFinite(x[1]) && vtkMath::IsFinite(x[2]);
}

// splitmix64's finalizer: a hash of 64 bits.
std::uint64_t Mix(std::uint64_t x)
{
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// How many indices the hashed sums read from the index buffer at a time (3 MB).
constexpr size_t IndicesPerBlock = size_t(3) << 18;

// A position's hash, by its bits as the welding compares them (-0 made 0 first), each
// coordinate's times an odd constant of its own, mixed once; 0 for one that is not finite.
template <typename Position>
std::uint64_t PositionHash(const Position& x)
{
  if (!IsFinite(x))
  {
    return 0;
  }
  static const std::uint64_t odd[3] = { 0x9e3779b97f4a7c15ull, 0xc2b2ae3d27d4eb4full,
    0x165667b19e3779f9ull };
  std::uint64_t h = 0x243f6a8885a308d3ull;
  for (int axis = 0; axis < 3; ++axis)
  {
    const double zeroed = static_cast<double>(x[axis]) + 0.0; // -0 and +0: one position
    std::uint64_t bits;
    std::memcpy(&bits, &zeroed, sizeof(bits));
    h ^= bits * odd[axis];
  }
  h = Mix(h);
  return h != 0 ? h : 1;
}

// A closed, consistently oriented surface uses each edge once in each direction, so over all
// its directed edges (a, b) the sum of f(a, b) - f(b, a) is exactly 0 (modulo 2^64) for any
// f of the two corners. With f(a, b) = h(a) g(h(b)), h a hash of a point and g a rotation
// (not a multiple: f must not be symmetric), an open surface leaves its boundary loops,
// whose sum is not 0 but with a chance of 2^-64: a sum not 0 means open (or inconsistent)
// for certain, in one pass and no memory, before the exact check (IsClosedAndConsistent).
// h hashes the point's id (closed by ids) or its position (closed once the points at one
// position are one). Degenerate triangles cancel themselves. The sum goes over blocks of
// indices. A corner hashed 0, or an index that names no point (the rest of the analysis
// reads every corner's position), rules the surface out.
class EdgeSums
{
public:
  void AddById(const std::vector<unsigned int>& indices, size_t points)
  {
    this->Add(indices, points, [](unsigned int p) { return Mix(p ^ 0x243f6a8885a308d3ull) | 1; });
  }
  template <typename Positions>
  void AddAtPositions(const std::vector<unsigned int>& indices, const Positions& positions)
  {
    this->Add(indices, static_cast<size_t>(positions.size()),
      [&positions](unsigned int p) { return PositionHash(positions[p]); });
  }
  bool MayPair() const { return this->Valid && this->Sum == 0; }
  bool RuledOut() const { return !this->Valid; } // a corner hashed 0 or naming no point

private:
  template <typename Hash>
  void Add(const std::vector<unsigned int>& indices, size_t points, const Hash& hash)
  {
    for (size_t i = 0; i + 2 < indices.size() && this->Valid; i += 3)
    {
      std::uint64_t h[3], g[3]; // f(a, b) = h(a) g(b)
      for (int k = 0; k < 3; ++k)
      {
        h[k] = indices[i + k] < points ? hash(indices[i + k]) : 0;
        this->Valid = this->Valid && h[k] != 0;
        g[k] = ((h[k] << 29) | (h[k] >> 35)) ^ 0x9e3779b97f4a7c15ull;
      }
      for (int k = 0; k < 3; ++k)
      {
        const int next = (k + 1) % 3;
        this->Sum += h[k] * g[next] - h[next] * g[k];
      }
    }
  }

  std::uint64_t Sum = 0;
  bool Valid = true;
};

// Calls `add(block)` with the indices of VTK's index buffer `triangles`, a block at a time
// (IndicesPerBlock), while `more()` (a sum is decided only at the end, unless ruled out).
template <typename Add, typename More>
void ForEachIndexBlock(vtkOpenGLIndexBufferObject* triangles, Add&& add, More&& more)
{
  const size_t count = triangles->IndexCount;
  std::vector<unsigned int> block;
  for (size_t first = 0; first < count && more(); first += block.size())
  {
    block.resize(std::min(IndicesPerBlock, count - first));
    vtkPhongVisibleClusters::ReadIndices(triangles, first, block);
    add(block);
  }
}

// Calls `visit(from, to)` for each directed edge of each triangle.
template <typename Visit>
void ForEachEdge(const std::vector<unsigned int>& triangles, Visit&& visit)
{
  for (size_t i = 0; i + 2 < triangles.size(); i += 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      visit(triangles[i + k], triangles[i + (k + 1) % 3]);
    }
  }
}

// Sorts [first, last): a point has a handful of edges, where insertion beats std::sort.
void SortFew(std::uint32_t* first, std::uint32_t* last)
{
  if (last - first > 16)
  {
    std::sort(first, last);
    return;
  }
  for (std::uint32_t* i = first + 1; i < last; ++i)
  {
    const std::uint32_t value = *i;
    std::uint32_t* j = i;
    for (; j > first && *(j - 1) > value; --j)
    {
      *j = *(j - 1);
    }
    *j = value;
  }
}

// Calls `work` with the input's positions as their own array type where it is one of
// vtkArrayDispatch's real arrays (as fast as a pointer), else as a vtkDataArray.
template <typename Work>
void WithPositions(vtkPolyData* input, Work&& work)
{
  vtkDataArray* positions = input->GetPoints()->GetData();
  if (!vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Reals>::Execute(positions, work))
  {
    work(positions);
  }
}

// Each point's representative, the lowest id at its position, or NotFinite: the points
// sorted by position where they are (no copy of the positions).
template <typename Positions>
std::vector<std::uint32_t> WeldPositions(const Positions& positions)
{
  const auto count = static_cast<std::uint32_t>(positions.size());
  std::vector<std::uint32_t> order;
  order.reserve(count);
  for (std::uint32_t p = 0; p < count; ++p)
  {
    if (IsFinite(positions[p]))
    {
      order.push_back(p);
    }
  }
  auto compare = [&positions](std::uint32_t a, std::uint32_t b)
  {
    const auto x = positions[a], y = positions[b];
    for (int axis = 0; axis < 3; ++axis)
    {
      if (x[axis] != y[axis])
      {
        return x[axis] < y[axis] ? -1 : 1;
      }
    }
    return 0;
  };
  std::sort(order.begin(), order.end(),
    [&compare](std::uint32_t a, std::uint32_t b)
    {
      const int position = compare(a, b);
      return position != 0 ? position < 0 : a < b;
    });
  std::vector<std::uint32_t> welded(count, NotFinite);
  for (size_t k = 0; k < order.size(); ++k)
  {
    const bool repeated = k > 0 && compare(order[k], order[k - 1]) == 0;
    welded[order[k]] = repeated ? welded[order[k - 1]] : order[k];
  }
  return welded;
}
}

//------------------------------------------------------------------------------
// The analysis on its own thread, and its answer.
struct vtkPhongClosedSurface::Background
{
  int Orientation = 0;
  std::unique_ptr<vtkPhongBackgroundTask> Task;
};

//------------------------------------------------------------------------------
vtkPhongClosedSurface::vtkPhongClosedSurface() = default;

//------------------------------------------------------------------------------
vtkPhongClosedSurface::~vtkPhongClosedSurface()
{
  this->CollectBackground(true);
}

//------------------------------------------------------------------------------
void vtkPhongClosedSurface::Update(vtkOpenGLIndexBufferObject* triangles,
  const std::vector<vtkPhongBufferBlock>& blocks, vtkMTimeType builtAt)
{
  if (builtAt == this->BuiltAt && triangles->IndexCount == this->IndexCount)
  {
    this->CollectBackground(false);
    return;
  }
  this->CollectBackground(true); // at most one analysis at a time
  this->BuiltAt = builtAt;
  this->IndexCount = triangles->IndexCount;
  this->Orientation = 0;
  for (const vtkPhongBufferBlock& block : blocks)
  {
    if (!block.Data || !block.Data->GetPoints() || HasConcavePolygons(block.Data))
    {
      return;
    }
  }
  vtkSmartPointer<vtkPolyData> points = vtkPhongBufferBlocks::Points(blocks);
  const Closure closure = points ? MayBeClosed(triangles, points) : Closure::None;
  std::vector<unsigned int> indices;
  if (closure == Closure::None || !vtkPhongVisibleClusters::ReadIndices(triangles, indices))
  {
    return;
  }
  if (indices.size() / 3 >= vtkPhongBackgroundTask::LargeTriangles)
  {
    // Points merges several blocks into a polydata of its own, which the thread may keep.
    const bool merged = points.GetPointer() != blocks.front().Data;
    this->AnalyseInBackground(std::move(indices), points, closure, merged);
    return;
  }
  this->Orientation = Analyse(indices, points, closure);
}

//------------------------------------------------------------------------------
bool vtkPhongClosedSurface::IsAnalysing() const
{
  return this->Pending != nullptr;
}

//------------------------------------------------------------------------------
// The thread works on its own copies: the input's points may change, or go, meanwhile.
// `owned`: the input is already a copy no one else holds.
void vtkPhongClosedSurface::AnalyseInBackground(
  std::vector<unsigned int> indices, vtkPolyData* input, Closure closure, bool owned)
{
  vtkSmartPointer<vtkPolyData> copy =
    owned ? vtkSmartPointer<vtkPolyData>(input) : vtkPhongBufferBlocks::CopyOfPoints(input);
  this->Pending = std::make_unique<Background>();
  Background* pending = this->Pending.get();
  pending->Task = std::make_unique<vtkPhongBackgroundTask>(
    [pending, copy, closure, indices = std::move(indices)]() mutable
    { pending->Orientation = Analyse(indices, copy, closure); });
}

//------------------------------------------------------------------------------
// Takes the background analysis's answer when it is in (or, with `wait`, once it is).
void vtkPhongClosedSurface::CollectBackground(bool wait)
{
  if (!this->Pending || (!wait && !this->Pending->Task->IsDone()))
  {
    return;
  }
  this->Pending->Task->Wait();
  this->Orientation = this->Pending->Orientation;
  this->Pending.reset();
}

//------------------------------------------------------------------------------
// What Analyse may find, from the hashed sums over VTK's index buffer, read a block at a time
// (no copy of the indices for a surface found open, the most common large one). By ids
// first: most closed meshes are, and that sum reads no position. AtPositions: not closed by
// ids, but may be once welded.
vtkPhongClosedSurface::Closure vtkPhongClosedSurface::MayBeClosed(
  vtkOpenGLIndexBufferObject* triangles, vtkPolyData* input)
{
  if (!vtkPhongVisibleClusters::HoldsTriangles(triangles))
  {
    return Closure::None;
  }
  if (HasOnlyFinitePoints(input))
  {
    EdgeSums byIds;
    const auto points = static_cast<size_t>(input->GetNumberOfPoints());
    ForEachIndexBlock(
      triangles, [&](const std::vector<unsigned int>& block) { byIds.AddById(block, points); },
      [&byIds] { return !byIds.RuledOut(); });
    if (byIds.MayPair())
    {
      return Closure::ByIds;
    }
  }
  EdgeSums atPositions;
  WithPositions(input,
    [&](auto* array)
    {
      const auto positions = vtk::DataArrayTupleRange<3>(array);
      ForEachIndexBlock(
        triangles,
        [&](const std::vector<unsigned int>& block)
        { atPositions.AddAtPositions(block, positions); },
        [&atPositions] { return !atPositions.RuledOut(); });
    });
  return atPositions.MayPair() ? Closure::AtPositions : Closure::None;
}

//------------------------------------------------------------------------------
// Most closed meshes are closed by their point ids already, and need no welding: its sort
// of the points is the analysis's longest step. A surface closed by ids is closed, whatever
// points share a position (two solids touching at a corner); the welding only finds more
// (split normals, per-face points). `closure`: MayBeClosed's answer for these triangles.
int vtkPhongClosedSurface::Analyse(
  std::vector<unsigned int>& indices, vtkPolyData* input, Closure closure)
{
  const bool closedByIds = closure == Closure::ByIds && IsClosedAndConsistent(indices);
  const bool mayWeld = closure == Closure::AtPositions ||
    (closure == Closure::ByIds && MayBeClosedAtPositions(indices, input));
  if (!closedByIds &&
    !(mayWeld && WeldTriangles(indices, WeldPoints(input)) && IsClosedAndConsistent(indices)))
  {
    return 0;
  }
  return Orient(indices, input);
}

//------------------------------------------------------------------------------
// VTK fans each polygon into triangles from its first point: a concave polygon's fan
// overlaps itself with triangles turned over, whose edges pair up as a closed surface's do.
bool vtkPhongClosedSurface::HasConcavePolygons(vtkPolyData* input)
{
  auto cells = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  std::vector<vtkIdType> ids;
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size = 0;
    const vtkIdType* cell = nullptr;
    cells->GetCurrentCell(size, cell);
    if (size > 3)
    {
      ids.assign(cell, cell + size);
      if (!vtkPolygon::IsConvex(input->GetPoints(), static_cast<int>(size), ids.data()))
      {
        return true;
      }
    }
  }
  return false;
}

//------------------------------------------------------------------------------
// Each point's representative: the lowest id at the same position (split normals and
// per-face attributes duplicate points, and the surface is closed across the copies);
// NotFinite for a point that is not finite.
std::vector<std::uint32_t> vtkPhongClosedSurface::WeldPoints(vtkPolyData* input)
{
  std::vector<std::uint32_t> welded;
  if (static_cast<std::uint64_t>(input->GetNumberOfPoints()) <= LargestPackedId + 1)
  {
    WithPositions(input,
      [&welded](auto* positions)
      { welded = WeldPositions(vtk::DataArrayTupleRange<3>(positions)); });
  }
  return welded;
}

//------------------------------------------------------------------------------
// The exact check by ids reads every corner's position: all must be finite.
bool vtkPhongClosedSurface::HasOnlyFinitePoints(vtkPolyData* input)
{
  bool finite = true;
  WithPositions(input,
    [&finite](auto* array)
    {
      for (const auto x : vtk::DataArrayTupleRange<3>(array))
      {
        finite = finite && IsFinite(x);
      }
    });
  return finite;
}

//------------------------------------------------------------------------------
// The sum by positions over indices already read (Analyse's, for a surface the sum by ids
// allowed: whether welding may close it when the exact check by ids fails).
bool vtkPhongClosedSurface::MayBeClosedAtPositions(
  const std::vector<unsigned int>& indices, vtkPolyData* input)
{
  EdgeSums atPositions;
  WithPositions(input,
    [&](auto* array) { atPositions.AddAtPositions(indices, vtk::DataArrayTupleRange<3>(array)); });
  return atPositions.MayPair();
}

//------------------------------------------------------------------------------
// The triangles with welded corners, those with two corners at one point (no area, no
// pixel) left out. False when a corner is not finite or an index names no point.
bool vtkPhongClosedSurface::WeldTriangles(
  std::vector<unsigned int>& indices, const std::vector<std::uint32_t>& welded)
{
  size_t kept = 0;
  for (size_t i = 0; i + 2 < indices.size(); i += 3)
  {
    std::uint32_t corners[3];
    for (int k = 0; k < 3; ++k)
    {
      const unsigned int index = indices[i + k];
      corners[k] = index < welded.size() ? welded[index] : NotFinite;
      if (corners[k] == NotFinite)
      {
        return false;
      }
    }
    if (corners[0] != corners[1] && corners[1] != corners[2] && corners[2] != corners[0])
    {
      std::copy_n(corners, 3, &indices[kept]);
      kept += 3;
    }
  }
  indices.resize(kept);
  return kept > 0;
}

//------------------------------------------------------------------------------
// Every edge is used exactly twice, once in each direction. Each edge is checked at its
// lower point, a range of points at a time (EdgesPerRange), so that the memory stays a
// fraction of the index buffer's; each range costs a pass over the triangles.
bool vtkPhongClosedSurface::IsClosedAndConsistent(const std::vector<unsigned int>& triangles)
{
  if (triangles.empty() || triangles.size() > std::numeric_limits<std::uint32_t>::max())
  {
    return false; // a point's edges are counted in 32 bits
  }
  const unsigned int largest = *std::max_element(triangles.begin(), triangles.end());
  if (largest > LargestPackedId)
  {
    return false; // an edge's other point and direction are packed in 32 bits
  }
  std::vector<std::uint32_t> edgesAt(size_t(largest) + 1, 0); // by their lower point
  ForEachEdge(
    triangles, [&edgesAt](unsigned int from, unsigned int to) { ++edgesAt[std::min(from, to)]; });
  const size_t perRange = EdgesPerRange(triangles.size());
  for (size_t first = 0; first < edgesAt.size();)
  {
    size_t last = first, edges = 0;
    while (last < edgesAt.size() && (last == first || edges + edgesAt[last] <= perRange))
    {
      edges += edgesAt[last++];
    }
    if (!ArePaired(triangles, edgesAt, static_cast<unsigned int>(first),
          static_cast<unsigned int>(last), edges))
    {
      return false;
    }
    first = last;
  }
  return true;
}

//------------------------------------------------------------------------------
// Whether the `edges` edges whose lower point is in [first, last) (`edgesAt` of each) each
// appear once in each direction. Gathered by their lower point, as the higher one with the
// direction in the lowest bit, and sorted, each point's edges must come as pairs (2 h, 2 h + 1)
// with no h twice.
bool vtkPhongClosedSurface::ArePaired(const std::vector<unsigned int>& triangles,
  const std::vector<std::uint32_t>& edgesAt, unsigned int first, unsigned int last, size_t edges)
{
  std::vector<std::uint32_t> ends(last - first); // where each point's next edge goes
  std::uint32_t start = 0;
  for (unsigned int p = first; p < last; ++p)
  {
    ends[p - first] = start;
    start += edgesAt[p];
  }
  std::vector<std::uint32_t> others(edges);
  ForEachEdge(triangles,
    [&](unsigned int from, unsigned int to)
    {
      const unsigned int low = std::min(from, to);
      if (low >= first && low < last)
      {
        others[ends[low - first]++] = (std::max(from, to) << 1) | (from < to ? 0u : 1u);
      }
    });
  std::uint32_t begin = 0;
  for (const std::uint32_t end : ends)
  {
    SortFew(others.data() + begin, others.data() + end);
    for (std::uint32_t e = begin; e < end; e += 2)
    {
      const bool paired = e + 1 < end && (others[e] & 1) == 0 && others[e + 1] == others[e] + 1;
      const bool once = e + 2 >= end || (others[e + 2] >> 1) != (others[e] >> 1);
      if (!paired || !once)
      {
        return false;
      }
    }
    begin = end;
  }
  return true;
}

//------------------------------------------------------------------------------
// The connected surfaces (triangles sharing a point), each triangle's surface in `owner`, with
// the volume each encloses (the divergence theorem: the sum of the tetrahedra its triangles
// span with a common origin), its bounds and one of its points.
std::vector<vtkPhongClosedSurface::Surface> vtkPhongClosedSurface::FindSurfaces(
  const std::vector<unsigned int>& triangles, vtkPolyData* input, std::vector<std::uint32_t>& owner)
{
  owner = vtkPhongVisibleClusters::ConnectedComponents(triangles, input);
  double origin[3];
  vtkBoundingBox(input->GetBounds()).GetCenter(origin);
  std::vector<Surface> surfaces;
  auto add = [&](auto* array)
  {
    const auto positions = vtk::DataArrayTupleRange<3>(array);
    for (size_t i = 0; i < triangles.size(); i += 3)
    {
      if (owner[i / 3] == surfaces.size()) // numbered in order of first appearance
      {
        surfaces.emplace_back();
        surfaces.back().Point = triangles[i];
      }
      Surface& surface = surfaces[owner[i / 3]];
      double corners[3][3];
      for (int k = 0; k < 3; ++k)
      {
        const auto corner = positions[triangles[i + k]];
        for (int axis = 0; axis < 3; ++axis)
        {
          surface.Lower[axis] = std::min<double>(surface.Lower[axis], corner[axis]);
          surface.Upper[axis] = std::max<double>(surface.Upper[axis], corner[axis]);
          corners[k][axis] = corner[axis] - origin[axis];
        }
      }
      double cross[3];
      vtkMath::Cross(corners[1], corners[2], cross);
      surface.Volume += vtkMath::Dot(corners[0], cross) / 6.0;
    }
  };
  WithPositions(input, add);
  return surfaces;
}

//------------------------------------------------------------------------------
// +1 or -1: the sign of the largest surface's volume, the solid's orientation. A surface of
// the other sign is a cavity (a contour around a minimum, a hollow solid's inner wall): it
// must lie inside the solid, or the region it bounds would be inside out. Flat surfaces
// (both sides of a sheet) bound no region and count for neither.
int vtkPhongClosedSurface::Orient(const std::vector<unsigned int>& triangles, vtkPolyData* input)
{
  std::vector<std::uint32_t> owner;
  const std::vector<Surface> surfaces = FindSurfaces(triangles, input, owner);
  auto isFlat = [](const Surface& surface)
  {
    const double diagonal =
      std::sqrt(vtkMath::Distance2BetweenPoints(surface.Lower, surface.Upper));
    return std::abs(surface.Volume) <= FlatVolumeShare * diagonal * diagonal * diagonal;
  };
  const auto largest = std::max_element(surfaces.begin(), surfaces.end(),
    [](const Surface& a, const Surface& b) { return std::abs(a.Volume) < std::abs(b.Volume); });
  if (largest == surfaces.end() || isFlat(*largest))
  {
    return 0;
  }
  const int orientation = largest->Volume > 0.0 ? 1 : -1;
  size_t tests = 0;
  for (size_t k = 0; k < surfaces.size(); ++k)
  {
    if (isFlat(surfaces[k]) || (surfaces[k].Volume > 0.0) == (orientation > 0))
    {
      continue;
    }
    tests += owner.size();
    if (tests > MaximumEnclosureTests ||
      orientation * WindingNumber(surfaces[k].Point, k, triangles, owner, input) < 1)
    {
      return 0;
    }
  }
  return orientation;
}

//------------------------------------------------------------------------------
// The winding number, at the point `point` of surface `skip`, of the other surfaces: how many
// times they enclose it, counted along a ray as the faces it leaves through (normal along the
// ray) less those it enters through. A ray that grazes an edge is tried again in another
// direction; 0 when every direction grazes one.
int vtkPhongClosedSurface::WindingNumber(vtkIdType point, size_t skip,
  const std::vector<unsigned int>& triangles, const std::vector<std::uint32_t>& owner,
  vtkPolyData* input)
{
  static const double directions[3][3] = { { 1.0, 0.3217, 0.1793 }, { -0.2711, 1.0, 0.4127 },
    { 0.3331, -0.5177, -1.0 } };
  vtkPoints* points = input->GetPoints();
  double origin[3];
  points->GetPoint(point, origin);
  for (const auto& direction : directions)
  {
    int winding = 0;
    bool grazed = false;
    for (size_t t = 0; t < owner.size() && !grazed; ++t)
    {
      if (owner[t] != skip)
      {
        double corners[3][3];
        for (int k = 0; k < 3; ++k)
        {
          points->GetPoint(triangles[3 * t + k], corners[k]);
        }
        winding += RayCrossing(origin, direction, corners, grazed);
      }
    }
    if (!grazed)
    {
      return winding;
    }
  }
  return 0;
}

//------------------------------------------------------------------------------
// Whether the ray from `origin` along `direction` crosses the triangle: +1 leaving through its
// front (its normal, by the right-hand rule, along the ray), -1 entering, 0 missing it (the
// Moller-Trumbore test); `grazed` set when it passes through an edge or a corner.
int vtkPhongClosedSurface::RayCrossing(
  const double origin[3], const double direction[3], const double corners[3][3], bool& grazed)
{
  double edge1[3], edge2[3], h[3], s[3], q[3];
  vtkMath::Subtract(corners[1], corners[0], edge1);
  vtkMath::Subtract(corners[2], corners[0], edge2);
  vtkMath::Cross(direction, edge2, h);
  const double determinant = vtkMath::Dot(edge1, h); // minus the normal's component along the ray
  if (determinant == 0.0)
  {
    return 0; // parallel
  }
  vtkMath::Subtract(origin, corners[0], s);
  const double u = vtkMath::Dot(s, h) / determinant;
  vtkMath::Cross(s, edge1, q);
  const double v = vtkMath::Dot(direction, q) / determinant;
  const double t = vtkMath::Dot(edge2, q) / determinant;
  if (u < 0.0 || v < 0.0 || u + v > 1.0 || t <= 0.0)
  {
    return 0;
  }
  const double tolerance = 1e-12;
  if (u < tolerance || v < tolerance || u + v > 1.0 - tolerance || t < tolerance)
  {
    grazed = true;
    return 0;
  }
  return determinant < 0.0 ? 1 : -1;
}

//------------------------------------------------------------------------------
// In clip coordinates of the projection VTK draws with (the camera's, this eye's in stereo,
// and the actor's matrix): every corner in front of the near plane means the camera is
// outside the bounds and the near plane opens nothing. The window's winding of an outward
// face is counter-clockwise (OpenGL's front) when the projection's determinant is negative,
// as a standard perspective or parallel projection's is.
unsigned int vtkPhongClosedSurface::HiddenFaces(
  vtkRenderer* ren, vtkActor* act, const double bounds[6]) const
{
  auto* camera = vtkOpenGLCamera::SafeDownCast(ren->GetActiveCamera());
  if (this->Orientation == 0 || !camera || !vtkMath::AreBoundsInitialized(bounds))
  {
    return 0;
  }
  vtkMatrix4x4* worldToView;
  vtkMatrix3x3* normalMatrix;
  vtkMatrix4x4* viewToClip;
  vtkMatrix4x4* worldToClipTransposed; // VTK keeps it transposed, as OpenGL reads it
  camera->GetKeyMatrices(ren, worldToView, normalMatrix, viewToClip, worldToClipTransposed);
  vtkNew<vtkMatrix4x4> worldToClip;
  vtkMatrix4x4::Transpose(worldToClipTransposed, worldToClip);
  vtkNew<vtkMatrix4x4> modelToClip;
  vtkMatrix4x4::Multiply4x4(worldToClip, act->GetMatrix(), modelToClip);
  const vtkBoundingBox box(bounds);
  for (int c = 0; c < 8; ++c)
  {
    double corner[4] = { 0.0, 0.0, 0.0, 1.0 };
    box.GetCorner(c, corner);
    double clip[4];
    modelToClip->MultiplyPoint(corner, clip);
    if (!(clip[3] > 0.0 && clip[2] > (NearPlaneMargin - 1.0) * clip[3]))
    {
      return 0;
    }
  }
  const double determinant = modelToClip->Determinant();
  if (!(determinant != 0.0))
  {
    return 0;
  }
  return (this->Orientation > 0) == (determinant < 0.0) ? GL_BACK : GL_FRONT;
}

//------------------------------------------------------------------------------
bool vtkPhongClosedSurface::DrawsOnlySurfaces(vtkRenderer* ren, vtkActor* act,
  const vtkOpenGLHelper* primitives, vtkShaderProperty* legacyShaders, int clippingPlanes)
{
  vtkProperty* property = act->GetProperty();
  vtkInformation* keys = act->GetPropertyKeys();
  const bool plainOpaqueSurface = property->GetRepresentation() == VTK_SURFACE &&
    property->GetOpacity() >= 1.0 && !property->GetBackfaceCulling() &&
    !property->GetFrontfaceCulling() && !property->GetEdgeVisibility() &&
    !property->GetVertexVisibility() && property->GetNumberOfTextures() == 0 &&
    !act->GetTexture() && !act->GetForceOpaque() && !act->IsRenderingTranslucentPolygonalGeometry();
  using Mapper = vtkOpenGLPolyDataMapper;
  const bool linesOfTriangles = primitives[Mapper::PrimitiveLines].IBO->IndexCount > 0 &&
    (property->GetLineWidth() > 1.0 || property->GetRenderLinesAsTubes());
  const bool pointsOfTriangles = primitives[Mapper::PrimitivePoints].IBO->IndexCount > 0 &&
    (property->GetPointSize() > 1.0 || property->GetRenderPointsAsSpheres());
  const bool onlyTriangles = primitives[Mapper::PrimitiveTris].IBO->IndexCount > 0 &&
    primitives[Mapper::PrimitiveTriStrips].IBO->IndexCount == 0 && !linesOfTriangles &&
    !pointsOfTriangles;
  return plainOpaqueSurface && onlyTriangles &&
    !vtkPhongShaderCode::HasUserCode(act, legacyShaders) && clippingPlanes == 0 &&
    !ren->GetSelector() && !(keys && keys->Has(vtkOpenGLRenderPass::RenderPasses()));
}
