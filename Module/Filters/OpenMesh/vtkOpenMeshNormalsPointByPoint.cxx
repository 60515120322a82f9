#include "vtkOpenMeshNormalsPointByPoint.h"

#include "vtkAlgorithm.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenMeshNormalsExecution.h"
#include "vtkOpenMeshNormalsFanRules.h"
#include "vtkOpenMeshNormalsWeightings.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <limits>

using namespace vtkOpenMeshNormalsDetail;

namespace
{
using Result = vtkOpenMeshNormalsPointByPoint::Result;

// A corner at the point being computed: its face's unit normal and the corner's weight, as
// vtkOpenMeshNormalsExecution computes them, and its neighbours in the face.
struct FanEntry
{
  Index Corner;
  vtkIdType Next;     // the point after this corner's in its face
  vtkIdType Previous; // the point before it
  Vector Unit;
  float Weight;
  bool Valid;
  Index Successor; // the entry across the edge to Previous: the fan's next entry, or -1
  bool Reached;    // some entry's Successor
};

// What one thread reuses from point to point.
struct Scratch
{
  std::vector<FanEntry> Entries;
  std::vector<Index> ByNext;
  std::vector<Index> Order;
};

// The point normals of a triangle mesh of IdType connectivity and PointType coordinates,
// with vertex weighting Weighting.
template <typename IdType, typename PointType, typename Weighting>
class PointFans
{
public:
  PointFans(const vtkOpenMeshNormalsPointByPoint::Settings& settings, const IdType* connectivity,
    Index numberOfCorners, const PointType* coordinates, vtkIdType numberOfPoints)
    : Splitting(settings.Splitting)
    , CosFeatureAngle(std::cos(vtkMath::RadiansFromDegrees(settings.FeatureAngle)))
    , Connectivity(connectivity)
    , NumberOfCorners(numberOfCorners)
    , Coordinates(coordinates)
    , NumberOfPoints(numberOfPoints)
  {
  }

  Result Compute(float* normals, vtkAlgorithm* filter)
  {
    this->CountCorners();
    filter->UpdateProgress(0.1);
    const Index chunk =
      std::min<Index>(1 << 24, std::max<Index>(1 << 16, this->NumberOfCorners / 4));
    vtkIdType begin = 0;
    while (begin < this->NumberOfPoints)
    {
      vtkIdType end = begin + 1;
      while (end < this->NumberOfPoints && this->Offsets[end + 1] - this->Offsets[begin] <= chunk)
      {
        ++end;
      }
      if (!this->ComputeRange(begin, end, normals))
      {
        return Result::NeedsTopology;
      }
      filter->UpdateProgress(0.1 + 0.8 * static_cast<double>(end) / this->NumberOfPoints);
      if (filter->GetAbortExecute())
      {
        return Result::Aborted;
      }
      begin = end;
    }
    return Result::Computed;
  }

private:
  void CountCorners()
  {
    this->Offsets.assign(this->NumberOfPoints + 1, 0);
    for (Index c = 0; c < this->NumberOfCorners; ++c)
    {
      ++this->Offsets[this->Connectivity[c] + 1];
    }
    for (vtkIdType p = 0; p < this->NumberOfPoints; ++p)
    {
      this->Offsets[p + 1] += this->Offsets[p];
    }
  }

  // The corners at points [begin, end), in corner order (the topology's
  // point-to-corner index), then each point's normal; false where a point needs the topology.
  bool ComputeRange(vtkIdType begin, vtkIdType end, float* normals)
  {
    const Index base = this->Offsets[begin];
    this->Corners.resize(this->Offsets[end] - base);
    Buffer<Index> fill(end - begin);
    for (vtkIdType p = begin; p < end; ++p)
    {
      fill[p - begin] = this->Offsets[p] - base;
    }
    for (Index c = 0; c < this->NumberOfCorners; ++c)
    {
      const vtkIdType p = this->Connectivity[c];
      if (p >= begin && p < end)
      {
        this->Corners[fill[p - begin]++] = c;
      }
    }
    std::atomic<bool> regular(true);
    vtkSMPTools::For(begin, end,
      [&](vtkIdType first, vtkIdType last)
      {
        Scratch& scratch = this->Local.Local();
        for (vtkIdType p = first; p < last && regular; ++p)
        {
          if (!this->ComputePoint(p, base, scratch, normals + 3 * p))
          {
            regular = false;
          }
        }
      });
    return regular;
  }

  bool ComputePoint(vtkIdType p, Index base, Scratch& scratch, float* normal) const
  {
    const Index first = this->Offsets[p] - base, last = this->Offsets[p + 1] - base;
    if (first == last)
    {
      StoreNormal({ 0.0, 0.0, 0.0 }, normal); // no face: +z, as the topology's path
      return true;
    }
    std::vector<FanEntry>& entries = scratch.Entries;
    entries.resize(last - first);
    for (Index i = first; i < last; ++i)
    {
      if (!this->ReadCorner(this->Corners[i], p, entries[i - first]))
      {
        return false; // a repeated vertex index
      }
    }
    if (!LinkFan(scratch) || !WalkFan(scratch) || (this->Splitting && this->IsCut(scratch)))
    {
      return false;
    }
    Vector sum = { 0.0, 0.0, 0.0 };
    if (this->Splitting)
    {
      for (Index i : scratch.Order) // the fan's order, as the topology sums a wedge
      {
        AddScaled(entries[i].Weight, entries[i].Unit, sum);
      }
    }
    else
    {
      for (const FanEntry& entry : entries) // corner order, as the shared sums
      {
        AddScaled(entry.Weight, entry.Unit, sum);
      }
    }
    StoreNormal(sum, normal);
    return true;
  }

  // Corner c of point p: its face's normal (Newell about the face's first corner) and its
  // weight, as vtkOpenMeshNormalsExecution::ComputeFaceNormal computes them.
  bool ReadCorner(Index c, vtkIdType p, FanEntry& entry) const
  {
    const Index first = c - c % 3, k = c % 3; // the face's first corner, and c's place
    const vtkIdType ids[3] = { static_cast<vtkIdType>(this->Connectivity[first]),
      static_cast<vtkIdType>(this->Connectivity[first + 1]),
      static_cast<vtkIdType>(this->Connectivity[first + 2]) };
    entry.Corner = c;
    entry.Next = ids[(k + 1) % 3];
    entry.Previous = ids[(k + 2) % 3];
    if (entry.Next == p || entry.Previous == p || entry.Next == entry.Previous)
    {
      return false;
    }
    double x[3][3];
    for (int v = 0; v < 3; ++v)
    {
      for (int a = 0; a < 3; ++a)
      {
        x[v][a] = static_cast<double>(this->Coordinates[3 * ids[v] + a]);
      }
    }
    const FaceNormal face = MakeFaceNormal(Cross(Subtract(x[1], x[0]), Subtract(x[2], x[0])),
      IsFinite(x[0]) && IsFinite(x[1]) && IsFinite(x[2]));
    entry.Valid = face.Valid;
    entry.Unit = face.Unit;
    const double* const corners[3] = { x[0], x[1], x[2] };
    entry.Weight = TriangleCornerWeightAt<Weighting>(corners, static_cast<int>(k), face);
    return true;
  }

  // Each entry's successor: the entry whose face holds the edge to its Previous point the
  // other way. False where an edge is held twice the same way (a face to turn, or a
  // non-manifold edge): the topology's twins would not be regular.
  static bool LinkFan(Scratch& scratch)
  {
    std::vector<FanEntry>& entries = scratch.Entries;
    const Index count = static_cast<Index>(entries.size());
    std::vector<Index>& byNext = scratch.ByNext;
    byNext.resize(count);
    for (Index i = 0; i < count; ++i)
    {
      byNext[i] = i;
      entries[i].Reached = false;
    }
    const auto nextOf = [&](Index i) { return entries[i].Next; };
    std::sort(
      byNext.begin(), byNext.end(), [&](Index a, Index b) { return nextOf(a) < nextOf(b); });
    for (Index i = 1; i < count; ++i)
    {
      if (nextOf(byNext[i]) == nextOf(byNext[i - 1]))
      {
        return false;
      }
    }
    for (FanEntry& entry : entries)
    {
      const auto found = std::lower_bound(byNext.begin(), byNext.end(), entry.Previous,
        [&](Index i, vtkIdType point) { return nextOf(i) < point; });
      entry.Successor = found != byNext.end() && nextOf(*found) == entry.Previous ? *found : -1;
      if (entry.Successor >= 0)
      {
        if (entries[entry.Successor].Reached)
        {
          return false; // two faces run the same way into the point
        }
        entries[entry.Successor].Reached = true;
      }
    }
    return true;
  }

  // The fan in circulation order, from where vtkOpenMeshNormalsTopology starts it: the first
  // corner whose outgoing edge is on the boundary (no entry reaches it), else the last
  // corner. False if the walk misses some corner (several fans at the point).
  static bool WalkFan(Scratch& scratch)
  {
    const std::vector<FanEntry>& entries = scratch.Entries;
    const Index count = static_cast<Index>(entries.size());
    Index start = count - 1;
    for (Index i = 0; i < count; ++i)
    {
      if (!entries[i].Reached)
      {
        start = i;
        break;
      }
    }
    scratch.Order.clear();
    Index e = start;
    while (e >= 0 && static_cast<Index>(scratch.Order.size()) < count)
    {
      scratch.Order.push_back(e);
      e = entries[e].Successor;
      if (e == start)
      {
        break;
      }
    }
    return static_cast<Index>(scratch.Order.size()) == count && (e < 0 || e == start);
  }

  // Whether splitting would cut the fan into several wedges (vtkOpenMeshNormalsExecution::
  // CutFan): sharp edges, or, for a fan cut once or never, a cone's apex.
  bool IsCut(const Scratch& scratch) const
  {
    const std::vector<FanEntry>& entries = scratch.Entries;
    const std::vector<Index>& order = scratch.Order;
    const Index count = static_cast<Index>(order.size());
    const bool open = entries[order.back()].Successor < 0;
    Index cuts = open ? 1 : 0;
    for (Index i = 0; i + 1 < count || (!open && i < count); ++i)
    {
      const FanEntry& here = entries[order[i]];
      const FanEntry& next = entries[order[(i + 1) % count]];
      cuts += IsSharpEdge(here.Valid, here.Unit, next.Valid, next.Unit, this->CosFeatureAngle);
    }
    if (cuts <= 1 &&
      IsSingularFan(
        count,
        [&](Index i) { return std::make_pair(entries[order[i]].Valid, &entries[order[i]].Unit); },
        this->CosFeatureAngle))
    {
      cuts = count;
    }
    return cuts > 1;
  }

  const bool Splitting;
  const double CosFeatureAngle;
  const IdType* const Connectivity;
  const Index NumberOfCorners;
  const PointType* const Coordinates;
  const vtkIdType NumberOfPoints;
  Buffer<Index> Offsets;
  Buffer<Index> Corners;
  vtkSMPThreadLocal<Scratch> Local;
};

// Calls run with the coordinates of points stored as float or double.
template <typename Run>
void WithCoordinates(vtkDataArray* data, Run&& run)
{
  if (auto* floats = vtkFloatArray::FastDownCast(data))
  {
    run(floats->GetPointer(0));
  }
  else if (auto* doubles = vtkDoubleArray::FastDownCast(data))
  {
    run(doubles->GetPointer(0));
  }
}

// The output the topology's path writes when it turns, cuts and copies nothing: the
// input's points, cells and data arrays, the normals, and the identity original point ids.
void WriteOutput(const vtkOpenMeshNormalsPointByPoint::Settings& settings, vtkPolyData* input,
  vtkFloatArray* normals, vtkPolyData* output)
{
  vtkNew<vtkIdList> noCopies;
  vtkOpenMeshNormalsExecution::WritePointsWithCopies(input, noCopies, output);
  normals->SetName("Normals");
  output->GetPointData()->SetNormals(normals);
  if (settings.Splitting)
  {
    vtkOpenMeshNormalsExecution::StoreOriginalPointIds(
      output, settings.OriginalPointIdsArrayName, input->GetNumberOfPoints(), noCopies);
  }
  output->SetVerts(input->GetVerts());
  output->SetLines(input->GetLines());
  output->SetPolys(input->GetPolys());
  output->GetCellData()->CopyNormalsOff();
  output->GetCellData()->PassData(input->GetCellData());
}
}

//------------------------------------------------------------------------------
bool vtkOpenMeshNormalsPointByPoint::Takes(vtkPolyData* input)
{
  vtkCellArray* polys = input->GetPolys();
  vtkDataArray* coordinates = input->GetPoints() ? input->GetPoints()->GetData() : nullptr;
  return polys && polys->GetNumberOfCells() > 0 && input->GetNumberOfStrips() == 0 && coordinates &&
    (vtkFloatArray::FastDownCast(coordinates) || vtkDoubleArray::FastDownCast(coordinates)) &&
    3 * polys->GetNumberOfCells() < std::numeric_limits<Index>::max() &&
    polys->IsHomogeneous() == 3;
}

//------------------------------------------------------------------------------
vtkOpenMeshNormalsPointByPoint::Result vtkOpenMeshNormalsPointByPoint::Compute(
  const Settings& settings, vtkPolyData* input, vtkPolyData* output, vtkAlgorithm* filter)
{
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  const Index numberOfCorners = static_cast<Index>(3 * input->GetPolys()->GetNumberOfCells());
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(numberOfPoints);
  Result result = Result::NeedsTopology;
  VisitCells(input->GetPolys(),
    [&](const auto*, const auto* connectivity)
    {
      WithCoordinates(input->GetPoints()->GetData(),
        [&](const auto* coordinates)
        {
          WithWeighting(settings.Weighting,
            [&](auto weighting)
            {
              using IdType = std::remove_const_t<std::remove_pointer_t<decltype(connectivity)>>;
              using PointType = std::remove_const_t<std::remove_pointer_t<decltype(coordinates)>>;
              PointFans<IdType, PointType, decltype(weighting)> fans(
                settings, connectivity, numberOfCorners, coordinates, numberOfPoints);
              result = fans.Compute(normals->GetPointer(0), filter);
            });
        });
    });
  if (result == Result::Computed)
  {
    WriteOutput(settings, input, normals, output);
  }
  return result;
}
