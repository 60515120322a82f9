#include "vtkPhongSeamFacesExchange.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataSetAttributes.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkPhongSeamFacesExchange);

namespace
{
constexpr int RingTag = 872341;
// The ring's points that are the sender's copies of points on the cut (the rest are the
// far corners of its faces, which may lie closer to a cut point than the tolerance where
// triangles are small: near a sphere's poles).
constexpr const char* SeamPointArrayName = "vtkPhongSeamPoint";

using Rings = std::vector<vtkSmartPointer<vtkPolyData>>;

// splitmix64's finaliser: neighbours' hashes, XORed, cancel only in pairs.
uint64_t Mix(uint64_t x)
{
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Calls face(cellId, size, ids) for each polygon and each triangle of each strip (in the
// strip's winding), with the cell id the polydata gives it; faces naming a point outside
// the piece are skipped (the normals filter collapses them).
template <typename Face>
void ForEachFace(vtkPolyData* piece, Face&& face)
{
  const vtkIdType points = piece->GetNumberOfPoints();
  auto inPiece = [points](vtkIdType size, const vtkIdType* ids)
  { return std::all_of(ids, ids + size, [points](vtkIdType p) { return p >= 0 && p < points; }); };
  vtkIdType cellId = piece->GetNumberOfVerts() + piece->GetNumberOfLines();
  vtkIdType size;
  const vtkIdType* ids;
  auto polys = vtk::TakeSmartPointer(piece->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell(), ++cellId)
  {
    polys->GetCurrentCell(size, ids);
    if (inPiece(size, ids))
    {
      face(cellId, size, ids);
    }
  }
  auto strips = vtk::TakeSmartPointer(piece->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell(), ++cellId)
  {
    strips->GetCurrentCell(size, ids);
    for (vtkIdType k = 0; k + 2 < size; ++k)
    {
      const vtkIdType odd = k & 1;
      const vtkIdType triangle[3] = { ids[k + odd], ids[k + 1 - odd], ids[k + 2] };
      if (inPiece(3, triangle))
      {
        face(cellId, 3, triangle);
      }
    }
  }
}

// The points on an open fan of faces: around an interior point every neighbour is named by
// two of its faces, and the XOR of the neighbours' hashes is 0.
std::vector<vtkIdType> BoundaryPoints(vtkPolyData* piece)
{
  const vtkIdType n = piece->GetNumberOfPoints();
  std::vector<uint64_t> neighbours(static_cast<size_t>(n), 0);
  std::vector<char> used(static_cast<size_t>(n), 0);
  ForEachFace(piece,
    [&](vtkIdType, vtkIdType size, const vtkIdType* ids)
    {
      for (vtkIdType k = 0; k < size; ++k)
      {
        const vtkIdType p = ids[k], previous = ids[(k + size - 1) % size];
        const vtkIdType next = ids[(k + 1) % size];
        neighbours[p] ^= (previous != p ? Mix(previous) : 0) ^ (next != p ? Mix(next) : 0);
        used[p] = 1;
      }
    });
  std::vector<vtkIdType> boundary;
  for (vtkIdType p = 0; p < n; ++p)
  {
    if (used[p] && neighbours[p] != 0)
    {
      boundary.push_back(p);
    }
  }
  return boundary;
}

// Where all ranks' points lie, and how close two copies of a point are.
struct Frame
{
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double Tolerance = 0.0;
  double CellSize = 1.0;
};

Frame GlobalFrame(vtkMultiProcessController* controller, vtkPolyData* piece, double fraction)
{
  // Minima of (min x, min y, min z, -max x, -max y, -max z): one reduction.
  double local[6] = { DBL_MAX, DBL_MAX, DBL_MAX, DBL_MAX, DBL_MAX, DBL_MAX };
  if (piece->GetNumberOfPoints() > 0)
  {
    const double* bounds = piece->GetPoints()->GetBounds();
    for (int axis = 0; axis < 3; ++axis)
    {
      local[axis] = bounds[2 * axis];
      local[3 + axis] = -bounds[2 * axis + 1];
    }
  }
  double global[6];
  controller->AllReduce(local, global, 6, vtkCommunicator::MIN_OP);
  Frame frame;
  double diagonal = 0.0;
  for (int axis = 0; axis < 3 && global[axis] != DBL_MAX; ++axis)
  {
    frame.Origin[axis] = global[axis];
    diagonal += (-global[3 + axis] - global[axis]) * (-global[3 + axis] - global[axis]);
  }
  diagonal = std::isfinite(diagonal) ? std::sqrt(diagonal) : 0.0;
  frame.Tolerance = fraction * diagonal;
  frame.CellSize =
    frame.Tolerance > 0.0 ? frame.Tolerance : (diagonal > 0.0 ? 1e-12 * diagonal : 1.0);
  return frame;
}

// Every rank's boundary points' positions, rank after rank.
struct Boundaries
{
  std::vector<double> Positions;  // x, y, z
  std::vector<vtkIdType> Offsets; // rank r's points: [Offsets[r], Offsets[r + 1])
};

Boundaries GatherBoundaries(
  vtkMultiProcessController* controller, vtkPolyData* piece, const std::vector<vtkIdType>& boundary)
{
  std::vector<double> mine(3 * boundary.size());
  for (size_t i = 0; i < boundary.size(); ++i)
  {
    piece->GetPoint(boundary[i], &mine[3 * i]);
  }
  const int ranks = controller->GetNumberOfProcesses();
  const vtkIdType length = static_cast<vtkIdType>(mine.size());
  std::vector<vtkIdType> lengths(static_cast<size_t>(ranks)), offsets(ranks + 1, 0);
  controller->AllGather(&length, lengths.data(), 1);
  for (int r = 0; r < ranks; ++r)
  {
    offsets[r + 1] = offsets[r] + lengths[r];
  }
  Boundaries all;
  all.Positions.resize(static_cast<size_t>(offsets[ranks]));
  controller->AllGatherV(mine.data(), all.Positions.data(), length, lengths.data(), offsets.data());
  all.Offsets.resize(offsets.size());
  std::transform(
    offsets.begin(), offsets.end(), all.Offsets.begin(), [](vtkIdType o) { return o / 3; });
  return all;
}

// This piece's boundary points, found by position within the tolerance.
class PointGrid
{
public:
  PointGrid(const Frame& frame, vtkPolyData* piece, const std::vector<vtkIdType>& points)
    : Grid(frame)
  {
    this->Entries.reserve(points.size());
    for (vtkIdType id : points)
    {
      Entry entry;
      entry.Id = id;
      piece->GetPoint(id, entry.Position);
      long long cell[3];
      if (this->CellOf(entry.Position, cell))
      {
        entry.Key = Key(cell);
        this->Entries.push_back(entry);
      }
    }
    std::sort(this->Entries.begin(), this->Entries.end(),
      [](const Entry& a, const Entry& b) { return a.Key < b.Key; });
  }

  // The nearest point within the tolerance of x, or -1.
  vtkIdType Find(const double x[3]) const
  {
    long long cell[3];
    if (!this->CellOf(x, cell))
    {
      return -1;
    }
    vtkIdType nearest = -1;
    double best = this->Grid.Tolerance * this->Grid.Tolerance;
    for (int neighbour = 0; neighbour < 27; ++neighbour)
    {
      const long long around[3] = { cell[0] + neighbour % 3 - 1, cell[1] + neighbour / 3 % 3 - 1,
        cell[2] + neighbour / 9 - 1 };
      Entry probe;
      probe.Key = Key(around);
      auto range = std::equal_range(this->Entries.begin(), this->Entries.end(), probe,
        [](const Entry& a, const Entry& b) { return a.Key < b.Key; });
      for (auto entry = range.first; entry != range.second; ++entry)
      {
        const double d = Distance2(x, entry->Position);
        if (d <= best && (nearest < 0 || d < best || entry->Id < nearest))
        {
          best = d;
          nearest = entry->Id;
        }
      }
    }
    return nearest;
  }

private:
  struct Entry
  {
    uint64_t Key = 0;
    vtkIdType Id = -1;
    double Position[3];
  };

  bool CellOf(const double x[3], long long cell[3]) const
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      const double c = std::floor((x[axis] - this->Grid.Origin[axis]) / this->Grid.CellSize);
      if (!(std::abs(c) < 4e18))
      {
        return false; // NaN or beyond any cell: matches nothing
      }
      cell[axis] = static_cast<long long>(c);
    }
    return true;
  }

  static uint64_t Key(const long long cell[3])
  {
    return Mix(static_cast<uint64_t>(cell[0]) ^
      Mix(static_cast<uint64_t>(cell[1]) ^ Mix(static_cast<uint64_t>(cell[2]))));
  }

  static double Distance2(const double a[3], const double b[3])
  {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
      (a[2] - b[2]) * (a[2] - b[2]);
  }

  Frame Grid;
  std::vector<Entry> Entries;
};

// For each rank, this piece's boundary points that match one of that rank's (none for
// this rank itself).
std::vector<std::vector<vtkIdType>> MatchAll(
  vtkMultiProcessController* controller, const PointGrid& grid, const Boundaries& all)
{
  const int ranks = controller->GetNumberOfProcesses();
  std::vector<std::vector<vtkIdType>> matched(static_cast<size_t>(ranks));
  for (int rank = 0; rank < ranks; ++rank)
  {
    if (rank == controller->GetLocalProcessId())
    {
      continue;
    }
    for (vtkIdType i = all.Offsets[rank]; i < all.Offsets[rank + 1]; ++i)
    {
      const vtkIdType own = grid.Find(&all.Positions[3 * i]);
      if (own >= 0)
      {
        matched[rank].push_back(own);
      }
    }
    std::sort(matched[rank].begin(), matched[rank].end());
    matched[rank].erase(
      std::unique(matched[rank].begin(), matched[rank].end()), matched[rank].end());
  }
  return matched;
}

// The ranks to exchange with, the same pairs on both sides: a pair exchanges when either
// rank matched a point of the other (a rank that matched none sends an empty ring).
std::vector<int> Partners(
  vtkMultiProcessController* controller, const std::vector<std::vector<vtkIdType>>& matched)
{
  const int ranks = controller->GetNumberOfProcesses();
  const int me = controller->GetLocalProcessId();
  std::vector<char> mine(static_cast<size_t>(ranks)), all(static_cast<size_t>(ranks) * ranks);
  for (int rank = 0; rank < ranks; ++rank)
  {
    mine[rank] = matched[rank].empty() ? 0 : 1;
  }
  controller->AllGather(mine.data(), all.data(), ranks);
  std::vector<int> partners;
  for (int rank = 0; rank < ranks; ++rank)
  {
    if (rank != me && (all[me * ranks + rank] || all[rank * ranks + me]))
    {
      partners.push_back(rank);
    }
  }
  return partners;
}

// The faces of the piece around the given points, as polygons with their point and cell
// data.
vtkSmartPointer<vtkPolyData> RingFaces(vtkPolyData* piece, const std::vector<vtkIdType>& around)
{
  auto ring = vtkSmartPointer<vtkPolyData>::New();
  if (around.empty())
  {
    return ring;
  }
  std::vector<char> isAround(static_cast<size_t>(piece->GetNumberOfPoints()), 0);
  for (vtkIdType p : around)
  {
    isAround[p] = 1;
  }
  vtkNew<vtkPoints> points;
  points->SetDataType(piece->GetPoints()->GetDataType());
  vtkNew<vtkCellArray> polys;
  ring->GetPointData()->CopyAllocate(piece->GetPointData());
  ring->GetCellData()->CopyAllocate(piece->GetCellData());
  vtkNew<vtkUnsignedCharArray> seamPoint;
  seamPoint->SetName(SeamPointArrayName);
  std::unordered_map<vtkIdType, vtkIdType> ringPoint;
  std::vector<vtkIdType> corners;
  ForEachFace(piece,
    [&](vtkIdType cellId, vtkIdType size, const vtkIdType* ids)
    {
      if (std::none_of(ids, ids + size, [&](vtkIdType p) { return isAround[p] != 0; }))
      {
        return;
      }
      corners.resize(static_cast<size_t>(size));
      for (vtkIdType k = 0; k < size; ++k)
      {
        const auto inserted = ringPoint.emplace(ids[k], points->GetNumberOfPoints());
        if (inserted.second)
        {
          points->InsertNextPoint(piece->GetPoint(ids[k]));
          seamPoint->InsertNextValue(isAround[ids[k]]);
          ring->GetPointData()->CopyData(piece->GetPointData(), ids[k], inserted.first->second);
        }
        corners[k] = inserted.first->second;
      }
      ring->GetCellData()->CopyData(
        piece->GetCellData(), cellId, polys->InsertNextCell(size, corners.data()));
    });
  ring->SetPoints(points);
  ring->SetPolys(polys);
  ring->GetPointData()->AddArray(seamPoint);
  return ring;
}

// Sends the ring to the partner and receives the partner's; the lower rank sends first, so
// that ranks going through their partners in increasing order never wait on each other.
vtkSmartPointer<vtkPolyData> Exchange(
  vtkMultiProcessController* controller, int partner, vtkPolyData* ring)
{
  auto received = vtkSmartPointer<vtkPolyData>::New();
  const bool sendsFirst = controller->GetLocalProcessId() < partner;
  if (sendsFirst)
  {
    controller->Send(ring, partner, RingTag);
  }
  controller->Receive(received, partner, RingTag);
  if (!sendsFirst)
  {
    controller->Send(ring, partner, RingTag);
  }
  return received;
}

// The piece's points, then the received points that are not the piece's own: for each
// ring, the output point of each of its points. A sender's cut point becomes the piece's
// nearest copy of it; every other point is new.
std::vector<std::vector<vtkIdType>> MapRingPoints(
  vtkPolyData* piece, const Rings& rings, const PointGrid& grid, vtkIdType& total)
{
  total = piece->GetNumberOfPoints();
  std::vector<std::vector<vtkIdType>> outputPoint(rings.size());
  for (size_t k = 0; k < rings.size(); ++k)
  {
    const vtkIdType n = rings[k]->GetNumberOfPoints();
    auto* seamPoint =
      vtkUnsignedCharArray::SafeDownCast(rings[k]->GetPointData()->GetArray(SeamPointArrayName));
    outputPoint[k].resize(static_cast<size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      const bool onCut = seamPoint && seamPoint->GetNumberOfTuples() == n && seamPoint->GetValue(i);
      const vtkIdType own = onCut ? grid.Find(rings[k]->GetPoint(i)) : -1;
      outputPoint[k][i] = own >= 0 ? own : total++;
    }
  }
  return outputPoint;
}

void AppendPoints(vtkPolyData* piece, const Rings& rings,
  const std::vector<std::vector<vtkIdType>>& outputPoint, vtkIdType total, vtkPolyData* output)
{
  const vtkIdType own = piece->GetNumberOfPoints();
  vtkNew<vtkPoints> points;
  points->SetDataType(piece->GetPoints()->GetDataType());
  points->SetNumberOfPoints(total);
  points->GetData()->InsertTuples(0, own, 0, piece->GetPoints()->GetData());
  vtkDataSetAttributes::FieldList fields(static_cast<int>(rings.size()) + 1);
  fields.IntersectFieldList(piece->GetPointData());
  for (const auto& ring : rings)
  {
    fields.IntersectFieldList(ring->GetPointData());
  }
  vtkPointData* data = output->GetPointData();
  data->CopyAllocate(fields, total);
  data->CopyData(fields, piece->GetPointData(), 0, 0, own, 0);
  for (size_t k = 0; k < rings.size(); ++k)
  {
    for (vtkIdType i = 0; i < rings[k]->GetNumberOfPoints(); ++i)
    {
      if (outputPoint[k][i] >= own)
      {
        points->SetPoint(outputPoint[k][i], rings[k]->GetPoint(i));
        data->CopyData(
          fields, rings[k]->GetPointData(), static_cast<int>(k) + 1, i, outputPoint[k][i]);
      }
    }
  }
  output->SetPoints(points);
}

// Cells in the polydata's order: the piece's vertices, lines and polygons, the received
// faces (polygons too), then the piece's strips; the received ones flagged as ghosts.
void AppendFaces(vtkPolyData* piece, const Rings& rings,
  const std::vector<std::vector<vtkIdType>>& outputPoint, vtkPolyData* output)
{
  vtkIdType ghostFaces = 0, ghostCorners = 0;
  for (const auto& ring : rings)
  {
    ghostFaces += ring->GetPolys()->GetNumberOfCells();
    ghostCorners += ring->GetPolys()->GetNumberOfConnectivityIds();
  }
  vtkCellArray* ownPolys = piece->GetPolys();
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(ownPolys->GetNumberOfCells() + ghostFaces,
    ownPolys->GetNumberOfConnectivityIds() + ghostCorners);
  polys->Append(ownPolys);
  vtkDataSetAttributes::FieldList fields(static_cast<int>(rings.size()) + 1);
  fields.IntersectFieldList(piece->GetCellData());
  for (const auto& ring : rings)
  {
    fields.IntersectFieldList(ring->GetCellData());
  }
  const vtkIdType beforeStrips =
    piece->GetNumberOfVerts() + piece->GetNumberOfLines() + ownPolys->GetNumberOfCells();
  const vtkIdType total = piece->GetNumberOfCells() + ghostFaces;
  vtkCellData* data = output->GetCellData();
  data->CopyAllocate(fields, total);
  data->CopyData(fields, piece->GetCellData(), 0, 0, beforeStrips, 0);
  vtkIdType cell = beforeStrips;
  std::vector<vtkIdType> corners;
  for (size_t k = 0; k < rings.size(); ++k)
  {
    auto faces = vtk::TakeSmartPointer(rings[k]->GetPolys()->NewIterator());
    for (faces->GoToFirstCell(); !faces->IsDoneWithTraversal(); faces->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      faces->GetCurrentCell(size, ids);
      corners.resize(static_cast<size_t>(size));
      for (vtkIdType i = 0; i < size; ++i)
      {
        corners[i] = outputPoint[k][ids[i]];
      }
      polys->InsertNextCell(size, corners.data());
      data->CopyData(fields, rings[k]->GetCellData(), static_cast<int>(k) + 1,
        faces->GetCurrentCellId(), cell++);
    }
  }
  data->CopyData(fields, piece->GetCellData(), 0, cell, piece->GetNumberOfStrips(), beforeStrips);
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfTuples(total);
  ghosts->FillValue(0);
  std::fill_n(ghosts->GetPointer(beforeStrips), ghostFaces,
    static_cast<unsigned char>(vtkDataSetAttributes::DUPLICATECELL));
  data->AddArray(ghosts);
  output->SetVerts(piece->GetVerts());
  output->SetLines(piece->GetLines());
  output->SetPolys(polys);
  output->SetStrips(piece->GetStrips());
}

// The input without its own ghost cells (the faces they hold come again from their ranks).
vtkSmartPointer<vtkPolyData> WithoutGhostCells(vtkPolyData* input)
{
  auto piece = vtkSmartPointer<vtkPolyData>::New();
  if (!input)
  {
    return piece;
  }
  piece->ShallowCopy(input);
  if (vtkUnsignedCharArray* ghosts = input->GetCellGhostArray())
  {
    if (ghosts->GetNumberOfTuples() > 0 && ghosts->GetRange(0)[1] != 0)
    {
      piece->RemoveGhostCells();
    }
    piece->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  }
  return piece;
}
}

//------------------------------------------------------------------------------
vtkPhongSeamFacesExchange::vtkPhongSeamFacesExchange()
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkPhongSeamFacesExchange::~vtkPhongSeamFacesExchange()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
vtkCxxSetObjectMacro(vtkPhongSeamFacesExchange, Controller, vtkMultiProcessController);

//------------------------------------------------------------------------------
// The steps of the class documentation, in order. Every rank makes every collective call,
// whatever its piece holds (an empty piece included).
int vtkPhongSeamFacesExchange::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfBoundaryPoints = this->NumberOfReceivedFaces = 0;
  this->NumberOfPartners = 0;
  vtkMultiProcessController* controller = this->Controller;
  if (!controller || controller->GetNumberOfProcesses() < 2)
  {
    output->ShallowCopy(input);
    return 1;
  }
  const vtkSmartPointer<vtkPolyData> piece = WithoutGhostCells(input);
  const std::vector<vtkIdType> boundary = BoundaryPoints(piece);
  this->NumberOfBoundaryPoints = static_cast<vtkIdType>(boundary.size());
  const Frame frame = GlobalFrame(controller, piece, this->Tolerance);
  const Boundaries all = GatherBoundaries(controller, piece, boundary);
  const PointGrid grid(frame, piece, boundary);
  const std::vector<std::vector<vtkIdType>> matched = MatchAll(controller, grid, all);
  const std::vector<int> partners = Partners(controller, matched);
  Rings rings;
  for (int partner : partners)
  {
    rings.push_back(Exchange(controller, partner, RingFaces(piece, matched[partner])));
    this->NumberOfReceivedFaces += rings.back()->GetNumberOfPolys();
  }
  this->NumberOfPartners = static_cast<int>(partners.size());
  if (this->NumberOfReceivedFaces == 0)
  {
    output->ShallowCopy(piece);
    return 1;
  }
  vtkIdType total = 0;
  const auto outputPoint = MapRingPoints(piece, rings, grid, total);
  AppendPoints(piece, rings, outputPoint, total, output);
  AppendFaces(piece, rings, outputPoint, output);
  output->GetFieldData()->ShallowCopy(piece->GetFieldData());
  return 1;
}

//------------------------------------------------------------------------------
void vtkPhongSeamFacesExchange::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "NumberOfBoundaryPoints: " << this->NumberOfBoundaryPoints << "\n";
  os << indent << "NumberOfPartners: " << this->NumberOfPartners << "\n";
  os << indent << "NumberOfReceivedFaces: " << this->NumberOfReceivedFaces << "\n";
}
