#include "vtkPhongSeamFacesExchange.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataSetAttributes.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPhongGhostCellsStash.h"
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
// What each point of a ring is to its sender: an interior point, a boundary point, or a
// cut point shared with the receiver. Only boundary points are matched by position: the
// others may lie closer to one than the tolerance where triangles are small (near a
// sphere's poles), and cuts are lines, whose points lie far apart.
constexpr const char* SeamPointArrayName = "vtkPhongSeamPoint";
enum RingPoint : unsigned char
{
  Interior = 0,
  Boundary = 1,
  Cut = 2
};

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
// strip's winding), with the cell id the polydata gives it; ghost cells (flagged in ghost,
// unless it is empty) and faces naming a point outside the piece (the normals filter
// collapses them) are skipped.
template <typename Face>
void ForEachFace(vtkPolyData* piece, const std::vector<char>& ghost, Face&& face)
{
  const vtkIdType points = piece->GetNumberOfPoints();
  vtkIdType cellId = piece->GetNumberOfVerts() + piece->GetNumberOfLines();
  auto inPiece = [&](vtkIdType size, const vtkIdType* ids)
  {
    return (ghost.empty() || !ghost[cellId]) &&
      std::all_of(ids, ids + size, [points](vtkIdType p) { return p >= 0 && p < points; });
  };
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
std::vector<vtkIdType> BoundaryPoints(vtkPolyData* piece, const std::vector<char>& ghost)
{
  const vtkIdType n = piece->GetNumberOfPoints();
  std::vector<uint64_t> neighbours(static_cast<size_t>(n), 0);
  std::vector<char> used(static_cast<size_t>(n), 0);
  ForEachFace(piece, ghost,
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

// Points found by position within the tolerance: each piece's boundary points, and the
// seam mesh's received copies of other ranks' boundary points.
class PointGrid
{
public:
  explicit PointGrid(const Frame& frame)
    : Grid(frame)
  {
  }

  void Insert(vtkIdType id, const double x[3])
  {
    long long cell[3];
    if (this->CellOf(x, cell))
    {
      this->Entries.emplace(Key(cell), Entry{ id, { x[0], x[1], x[2] } });
    }
  }

  // The nearest point within the tolerance of x (the smallest id of the nearest), or -1.
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
      const auto range = this->Entries.equal_range(Key(around));
      for (auto entry = range.first; entry != range.second; ++entry)
      {
        const double d = Distance2(x, entry->second.Position);
        if (d <= best && (nearest < 0 || d < best || entry->second.Id < nearest))
        {
          best = d;
          nearest = entry->second.Id;
        }
      }
    }
    return nearest;
  }

private:
  struct Entry
  {
    vtkIdType Id;
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
  std::unordered_multimap<uint64_t, Entry> Entries;
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

// The faces of the piece around the given points, with a point array saying what each
// point is (RingPoint; positions are all the receiver needs: the normals come from
// geometry).
vtkSmartPointer<vtkPolyData> RingFaces(vtkPolyData* piece, const std::vector<char>& ghost,
  const std::vector<char>& isBoundary, const std::vector<vtkIdType>& around)
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
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkUnsignedCharArray> seamPoint;
  seamPoint->SetName(SeamPointArrayName);
  std::unordered_map<vtkIdType, vtkIdType> ringPoint;
  std::vector<vtkIdType> corners;
  ForEachFace(piece, ghost,
    [&](vtkIdType, vtkIdType size, const vtkIdType* ids)
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
          seamPoint->InsertNextValue(
            isAround[ids[k]] ? Cut : (isBoundary[ids[k]] ? Boundary : Interior));
        }
        corners[k] = inserted.first->second;
      }
      polys->InsertNextCell(size, corners.data());
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

// The seam mesh: the piece's faces around its cut points and the faces the other ranks
// sent, on one set of points. A sender's cut point becomes the piece's nearest copy of it;
// a sender's other boundary points become one point with the other senders' copies of it
// (where three pieces meet, two senders send the point between them); the other received
// points are new. Only cut points get their piece id (the fans of the others are partial
// here), every other point -1.
class SeamMeshBuilder
{
public:
  SeamMeshBuilder(vtkPolyData* piece, const std::vector<char>& isCut, const Frame& frame)
    : Piece(piece)
    , IsCut(isCut)
    , ReceivedBoundary(frame)
  {
    this->Points->SetDataTypeToDouble();
    this->PieceIds->SetName(vtkPhongSeamFacesExchange::PiecePointIdsArrayName());
  }

  void AddPieceFaces(const std::vector<char>& ghost)
  {
    ForEachFace(this->Piece, ghost,
      [&](vtkIdType, vtkIdType size, const vtkIdType* ids)
      {
        if (std::any_of(ids, ids + size, [&](vtkIdType p) { return this->IsCut[p] != 0; }))
        {
          this->AddFace(size, ids, [this](vtkIdType p) { return this->PiecePoint(p); });
        }
      });
  }

  void AddRing(vtkPolyData* ring, const PointGrid& grid)
  {
    const vtkIdType n = ring->GetNumberOfPoints();
    auto* seamPoint =
      vtkUnsignedCharArray::SafeDownCast(ring->GetPointData()->GetArray(SeamPointArrayName));
    std::vector<vtkIdType> meshPoint(static_cast<size_t>(n));
    const bool flagged = seamPoint && seamPoint->GetNumberOfTuples() == n;
    for (vtkIdType i = 0; i < n; ++i)
    {
      meshPoint[i] = this->ReceivedPoint(ring->GetPoint(i),
        flagged ? seamPoint->GetValue(i) : static_cast<unsigned char>(Interior), grid);
    }
    auto faces = vtk::TakeSmartPointer(ring->GetPolys()->NewIterator());
    for (faces->GoToFirstCell(); !faces->IsDoneWithTraversal(); faces->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      faces->GetCurrentCell(size, ids);
      if (std::all_of(ids, ids + size, [n](vtkIdType p) { return p >= 0 && p < n; }))
      {
        this->AddFace(size, ids, [&](vtkIdType p) { return meshPoint[p]; });
      }
    }
  }

  void Write(vtkPolyData* output)
  {
    output->SetPoints(this->Points);
    output->SetPolys(this->Polys);
    output->GetPointData()->AddArray(this->PieceIds);
  }

private:
  vtkIdType ReceivedPoint(const double x[3], unsigned char kind, const PointGrid& grid)
  {
    const vtkIdType own = kind == Cut ? grid.Find(x) : -1;
    if (own >= 0)
    {
      return this->PiecePoint(own);
    }
    if (kind == Interior)
    {
      return this->NewPoint(x, -1);
    }
    vtkIdType known = this->ReceivedBoundary.Find(x);
    if (known < 0)
    {
      known = this->NewPoint(x, -1);
      this->ReceivedBoundary.Insert(known, x);
    }
    return known;
  }

  vtkIdType NewPoint(const double x[3], vtkIdType pieceId)
  {
    this->PieceIds->InsertNextValue(pieceId);
    return this->Points->InsertNextPoint(x);
  }

  vtkIdType PiecePoint(vtkIdType p)
  {
    const auto found = this->MeshPointOf.find(p);
    if (found != this->MeshPointOf.end())
    {
      return found->second;
    }
    const vtkIdType added = this->NewPoint(this->Piece->GetPoint(p), this->IsCut[p] ? p : -1);
    this->MeshPointOf.emplace(p, added);
    return added;
  }

  template <typename MeshPoint>
  void AddFace(vtkIdType size, const vtkIdType* ids, MeshPoint&& meshPoint)
  {
    this->Corners.resize(static_cast<size_t>(size));
    std::transform(ids, ids + size, this->Corners.begin(), meshPoint);
    this->Polys->InsertNextCell(size, this->Corners.data());
  }

  vtkPolyData* Piece;
  const std::vector<char>& IsCut;
  PointGrid ReceivedBoundary;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Polys;
  vtkNew<vtkIdTypeArray> PieceIds;
  std::unordered_map<vtkIdType, vtkIdType> MeshPointOf;
  std::vector<vtkIdType> Corners;
};

// Per cell: a ghost cell (flagged in the ghost array, or in the one vtkPhongGhostCellsStash
// renamed it to), left out of the piece; empty when there is none.
std::vector<char> GhostCells(vtkPolyData* piece)
{
  std::vector<char> ghost;
  for (const char* name :
    { vtkDataSetAttributes::GhostArrayName(), vtkPhongGhostCellsStash::StashedGhostArrayName() })
  {
    vtkDataArray* flags = piece->GetCellData()->GetArray(name);
    if (!flags || flags->GetNumberOfTuples() != piece->GetNumberOfCells())
    {
      continue;
    }
    const std::vector<char> flagged = vtkPhongGhostCellsStash::GhostFlags(flags);
    ghost.resize(flagged.size(), 0);
    std::transform(ghost.begin(), ghost.end(), flagged.begin(), ghost.begin(),
      [](char a, char b) { return static_cast<char>(a || b); });
  }
  return ghost;
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
  vtkPolyData* piece = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfBoundaryPoints = this->NumberOfReceivedFaces = 0;
  this->NumberOfPartners = 0;
  vtkMultiProcessController* controller = this->Controller;
  if (!this->Enabled || !piece || !controller || controller->GetNumberOfProcesses() < 2)
  {
    return 1; // no seam: an empty mesh
  }
  const std::vector<char> ghost = GhostCells(piece);
  const std::vector<vtkIdType> boundary = BoundaryPoints(piece, ghost);
  this->NumberOfBoundaryPoints = static_cast<vtkIdType>(boundary.size());
  const Frame frame = GlobalFrame(controller, piece, this->Tolerance);
  const Boundaries all = GatherBoundaries(controller, piece, boundary);
  PointGrid grid(frame);
  std::vector<char> isBoundary(static_cast<size_t>(piece->GetNumberOfPoints()), 0);
  for (vtkIdType p : boundary)
  {
    grid.Insert(p, piece->GetPoint(p));
    isBoundary[p] = 1;
  }
  const std::vector<std::vector<vtkIdType>> matched = MatchAll(controller, grid, all);
  const std::vector<int> partners = Partners(controller, matched);
  std::vector<char> isCut(static_cast<size_t>(piece->GetNumberOfPoints()), 0);
  Rings rings;
  for (int partner : partners)
  {
    rings.push_back(
      Exchange(controller, partner, RingFaces(piece, ghost, isBoundary, matched[partner])));
    this->NumberOfReceivedFaces += rings.back()->GetNumberOfPolys();
    for (vtkIdType p : matched[partner])
    {
      isCut[p] = 1;
    }
  }
  this->NumberOfPartners = static_cast<int>(partners.size());
  SeamMeshBuilder seam(piece, isCut, frame);
  seam.AddPieceFaces(ghost);
  for (const auto& ring : rings)
  {
    seam.AddRing(ring, grid);
  }
  seam.Write(output);
  return 1;
}

//------------------------------------------------------------------------------
void vtkPhongSeamFacesExchange::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Enabled: " << (this->Enabled ? "On" : "Off") << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "NumberOfBoundaryPoints: " << this->NumberOfBoundaryPoints << "\n";
  os << indent << "NumberOfPartners: " << this->NumberOfPartners << "\n";
  os << indent << "NumberOfReceivedFaces: " << this->NumberOfReceivedFaces << "\n";
}
