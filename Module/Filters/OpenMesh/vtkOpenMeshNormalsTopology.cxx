#include "vtkOpenMeshNormalsTopology.h"

#include "vtkCellArray.h"
#include "vtkOpenMeshNormals.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <iterator>
#include <limits>

using namespace vtkOpenMeshNormalsDetail;

namespace
{
//------------------------------------------------------------------------------
// The search for each corner's twin among the corners at its point.
class TwinFinder
{
public:
  TwinFinder(const vtkOpenMeshNormalsTopology& topology, const PointCorners& around)
    : Faces(topology.Faces)
    , CornerFace(topology.CornerFace)
    , Around(around)
  {
    // Polygons keep each corner's next and previous points side by side: the
    // search reads one small record per candidate instead of following three
    // arrays. Triangles find them by arithmetic and skip the copy.
    if (!this->Faces.AllTriangles)
    {
      this->Neighbours.resize(2 * this->Faces.Points.size());
      vtkSMPTools::For(0, this->Faces.Size(),
        [&](Index begin, Index end)
        {
          for (Index f = begin; f < end; ++f)
          {
            for (Index c = this->Faces.Offsets[f]; c < this->Faces.Offsets[f + 1]; ++c)
            {
              this->Neighbours[2 * static_cast<size_t>(c)] =
                this->Faces.Points[this->Faces.Next(c, f)];
              this->Neighbours[2 * static_cast<size_t>(c) + 1] =
                this->Faces.Points[this->Faces.Previous(c, f)];
            }
          }
        });
    }
  }

  // The twins of all the corners at point a: for corner c (running a -> b),
  // the corner of another face at a that also runs a -> b (same direction:
  // inconsistent faces) or the corner at b of another face running b -> a;
  // NoTwin if none, NonManifoldEdge if several. A corner's own face has no
  // other corner at a (faces have no repeated points), and the neighbouring
  // points of the corners at a are read once per point, not once per corner.
  void FindAround(Index a, Buffer<Index>& twins, Buffer<char>& sameDirection,
    std::vector<std::pair<Index, Index>>& ring) const
  {
    const Index first = this->Around.Offsets[a], last = this->Around.Offsets[a + 1];
    ring.resize(last - first);
    for (Index i = first; i < last; ++i)
    {
      const Index d = this->Around.Corners[i];
      ring[i - first] = { this->NextPoint(d), this->PreviousPoint(d) };
    }
    for (Index i = first; i < last; ++i)
    {
      const Index b = ring[i - first].first;
      Index found = NoTwin;
      char same = 0;
      for (Index j = first; j < last && found != NonManifoldEdge; ++j)
      {
        Index twin = NoTwin;
        if (j == i)
        {
          continue;
        }
        if (ring[j - first].first == b)
        {
          twin = this->Around.Corners[j]; // it also runs a -> b
          same = 1;
        }
        else if (ring[j - first].second == b)
        {
          const Index d = this->Around.Corners[j]; // it runs b -> a
          twin = this->Faces.Previous(d, this->CornerFace[d]);
          same = 0;
        }
        if (twin != NoTwin)
        {
          found = (found == NoTwin) ? twin : NonManifoldEdge;
        }
      }
      const Index c = this->Around.Corners[i];
      twins[c] = found;
      sameDirection[c] = found >= 0 ? same : 0;
    }
  }

private:
  Index NextPoint(Index c) const
  {
    return this->Faces.AllTriangles ? this->Faces.Points[this->Faces.Next(c, 0)]
                                    : this->Neighbours[2 * static_cast<size_t>(c)];
  }
  Index PreviousPoint(Index c) const
  {
    return this->Faces.AllTriangles ? this->Faces.Points[this->Faces.Previous(c, 0)]
                                    : this->Neighbours[2 * static_cast<size_t>(c) + 1];
  }

  const FaceList& Faces;
  const Buffer<Index>& CornerFace;
  const PointCorners& Around;
  Buffer<Index> Neighbours;
};

//------------------------------------------------------------------------------
// The breadth-first walk over twins that orients each connected piece: faces
// sharing an edge must run it in opposite directions. Each piece then keeps
// the orientation most of its faces already have (not that of the face the
// walk started from). Fills the topology's FaceComponent and ComponentClosed.
class OrientationWalk
{
public:
  OrientationWalk(vtkOpenMeshNormalsTopology& topology, const PointCorners& around,
    const Buffer<Index>& twins, const Buffer<char>& sameDirection, bool traversal,
    Buffer<signed char>& orientation)
    : Topology(topology)
    , Faces(topology.Faces)
    , Around(around)
    , Twins(twins)
    , SameDirection(sameDirection)
    , Traversal(traversal)
    , Orientation(orientation)
  {
  }

  // Sets every face's orientation to 1 (kept) or -1 (reversed); false if the
  // filter was aborted.
  bool Run(vtkOpenMeshNormals* filter)
  {
    const Index numberOfFaces = this->Faces.Size();
    this->Orientation.assign(numberOfFaces, 0);
    this->Topology.FaceComponent.assign(numberOfFaces, 0);
    this->Topology.ComponentClosed.clear();
    this->Order.reserve(numberOfFaces);
    for (Index seed = 0; seed < numberOfFaces; ++seed)
    {
      if (this->Orientation[seed] == 0 && !this->WalkPiece(seed, filter))
      {
        return false;
      }
    }
    return true;
  }

private:
  bool WalkPiece(Index seed, vtkOpenMeshNormals* filter)
  {
    this->Component = static_cast<Index>(this->Topology.ComponentClosed.size());
    this->Closed = true;
    const size_t start = this->Order.size();
    this->Orientation[seed] = 1;
    this->Topology.FaceComponent[seed] = this->Component;
    this->Order.push_back(seed);
    for (size_t next = start; next < this->Order.size(); ++next)
    {
      this->VisitNeighbours(this->Order[next]);
      if (next % AbortCheckInterval == 0 && filter->GetAbortExecute())
      {
        return false;
      }
    }
    this->KeepMajorityOrientation(start);
    this->Topology.ComponentClosed.push_back(this->Closed);
    return true;
  }

  void VisitNeighbours(Index f)
  {
    for (Index c = this->Faces.Offsets[f]; c < this->Faces.Offsets[f + 1]; ++c)
    {
      const Index twin = this->Twins[c];
      if (twin >= 0)
      {
        this->Reach(f, this->Topology.CornerFace[twin], this->SameDirection[c] != 0);
        continue;
      }
      this->Closed = false;
      if (twin == NonManifoldEdge && this->Traversal)
      {
        this->FindFacesAcross(f, c);
        for (const auto& neighbour : this->Across)
        {
          this->Reach(f, neighbour.first, neighbour.second);
        }
      }
    }
  }

  // Face g shares an edge with face f; same: both run it the same way.
  void Reach(Index f, Index g, bool same)
  {
    if (this->Orientation[g] == 0)
    {
      // Consistent neighbours run their shared edge in opposite directions.
      this->Orientation[g] =
        static_cast<signed char>(same ? -this->Orientation[f] : this->Orientation[f]);
      this->Topology.FaceComponent[g] = this->Component;
      this->Order.push_back(g);
    }
    else if ((this->Orientation[g] == this->Orientation[f]) == same)
    {
      this->Closed = false; // not orientable (a Moebius strip)
    }
  }

  // The faces across the non-manifold edge of corner c of face f (which has
  // no single twin), and whether each runs the edge the same way.
  void FindFacesAcross(Index f, Index c)
  {
    this->Across.clear();
    const FaceList& faces = this->Faces;
    const Index a = faces.Points[c], b = faces.Points[faces.Next(c, f)];
    for (Index i = this->Around.Offsets[a]; i < this->Around.Offsets[a + 1]; ++i)
    {
      const Index d = this->Around.Corners[i];
      const Index g = this->Topology.CornerFace[d];
      if (g == f)
      {
        continue;
      }
      if (faces.Points[faces.Next(d, g)] == b)
      {
        this->Across.emplace_back(g, true);
      }
      else if (faces.Points[faces.Previous(d, g)] == b)
      {
        this->Across.emplace_back(g, false);
      }
    }
  }

  void KeepMajorityOrientation(size_t start)
  {
    Buffer<signed char>& orientation = this->Orientation;
    const size_t reversed = static_cast<size_t>(std::count_if(
      this->Order.begin() + start, this->Order.end(), [&](Index f) { return orientation[f] < 0; }));
    if (2 * reversed > this->Order.size() - start)
    {
      for (size_t i = start; i < this->Order.size(); ++i)
      {
        orientation[this->Order[i]] = static_cast<signed char>(-orientation[this->Order[i]]);
      }
    }
  }

  vtkOpenMeshNormalsTopology& Topology;
  const FaceList& Faces;
  const PointCorners& Around;
  const Buffer<Index>& Twins;
  const Buffer<char>& SameDirection;
  const bool Traversal;
  Buffer<signed char>& Orientation;
  Buffer<Index> Order; // the faces in the order the walk reached them
  std::vector<std::pair<Index, bool>> Across;
  Index Component = 0; // the piece being walked
  bool Closed = true;  // so far, it has no boundary and is orientable
};

// Visits the outgoing halfedges of vertex v in OpenMesh's circulation order:
// from an outgoing halfedge, the opposite of its previous is the next
// outgoing one, across a shared edge or, at a gap, through a boundary
// halfedge.
template <typename Visit>
void Circulate(const HalfedgeMesh& mesh, Index v, Visit&& visit)
{
  const HalfedgeHandle start = mesh.halfedge_handle(VertexHandle(v));
  if (!start.is_valid())
  {
    return;
  }
  HalfedgeHandle h = start;
  do
  {
    visit(h);
    h = mesh.opposite_halfedge_handle(mesh.prev_halfedge_handle(h));
  } while (h != start);
}
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsDetail::CellsStamp::Record(vtkPolyData* input)
{
  this->Polys = input->GetPolys();
  this->PolysTime = this->Polys->GetMTime();
  this->Strips = input->GetStrips();
  this->StripsTime = this->Strips->GetMTime();
  this->NumberOfPoints = input->GetNumberOfPoints();
}

//------------------------------------------------------------------------------
bool vtkOpenMeshNormalsDetail::CellsStamp::Matches(vtkPolyData* input) const
{
  vtkCellArray* polys = input->GetPolys();
  vtkCellArray* strips = input->GetStrips();
  return this->Polys == polys && this->PolysTime == polys->GetMTime() && this->Strips == strips &&
    this->StripsTime == strips->GetMTime() && this->NumberOfPoints == input->GetNumberOfPoints();
}

//------------------------------------------------------------------------------
bool vtkOpenMeshNormalsTopology::Matches(
  vtkPolyData* input, bool consistency, bool traversal, bool incremental, bool halfedgeMesh) const
{
  return this->Valid && this->Cells.Matches(input) && this->Consistency == consistency &&
    this->NonManifoldTraversal == traversal && this->Incremental == incremental &&
    this->AlwaysHalfedgeMesh == halfedgeMesh;
}

//------------------------------------------------------------------------------
bool vtkOpenMeshNormalsTopology::Build(vtkPolyData* input, bool consistency, bool traversal,
  bool incremental, bool halfedgeMesh, vtkOpenMeshNormals* filter)
{
  this->Valid = false;
  this->NonManifoldFaces = this->RepeatedPointFaces = this->DegenerateFaces = 0;
  const vtkIdType inputPoints = input->GetNumberOfPoints();
  const vtkIdType inputCorners = input->GetPolys()->GetNumberOfConnectivityIds() +
    3 * input->GetStrips()->GetNumberOfConnectivityIds();
  if (inputPoints >= std::numeric_limits<Index>::max() / 2 ||
    inputCorners >= std::numeric_limits<Index>::max() / 2)
  {
    vtkErrorWithObjectMacro(filter,
      "The mesh is too large for OpenMesh's 32-bit handles ("
        << inputPoints << " points, " << inputCorners << " polygon corners).");
    return false;
  }

  this->ReadFaces(input);
  filter->UpdateProgress(0.1);
  PointCorners around;
  around.Build(this->Faces.Points, static_cast<Index>(inputPoints));
  Buffer<char> sameDirection;
  Buffer<Index> twins = this->FindTwins(around, sameDirection);
  filter->UpdateProgress(0.25);
  if (!this->OrientFaces(around, twins, sameDirection, consistency, traversal, filter))
  {
    return false;
  }
  filter->UpdateProgress(0.4);
  this->HasHalfedgeMesh =
    incremental || halfedgeMesh || !this->ReadFansFromTwins(around, twins, sameDirection);
  if (this->HasHalfedgeMesh)
  {
    const Buffer<char> irregular = incremental
      ? Buffer<char>(this->NumberOfFaces(), 1)
      : this->FindIrregularFaces(around, twins, sameDirection);
    filter->UpdateProgress(0.5);
    if (!this->LoadMesh(around, twins, irregular, filter))
    {
      return false;
    }
    filter->UpdateProgress(0.6);
    this->ReadFans();
  }
  filter->UpdateProgress(0.7);

  this->Cells.Record(input);
  this->Consistency = consistency;
  this->NonManifoldTraversal = traversal;
  this->Incremental = incremental;
  this->AlwaysHalfedgeMesh = halfedgeMesh;
  this->Valid = true;
  return true;
}

//------------------------------------------------------------------------------
// Faces from polygons and strips, in input order, without repeated points
// (OpenMesh refuses them); faces left with fewer than three points are not
// faces. Fills PolyFace, StripFaces, FaceCell and CornerFace.
void vtkOpenMeshNormalsTopology::ReadFaces(vtkPolyData* input)
{
  vtkCellArray* polys = input->GetPolys();
  vtkCellArray* strips = input->GetStrips();
  const Index cellsBeforePolys =
    static_cast<Index>(input->GetNumberOfVerts() + input->GetNumberOfLines());
  const Index numberOfPolys = static_cast<Index>(polys->GetNumberOfCells());
  const Index numberOfStrips = static_cast<Index>(strips->GetNumberOfCells());
  FaceList& faces = this->Faces;
  faces.Offsets.assign(1, 0);
  faces.Points.clear();
  this->FaceCell.clear();
  this->PolyFace.assign(numberOfPolys, -1);
  this->StripFaces.clear();

  if (polys->GetNumberOfConnectivityIds() == 3 * numberOfPolys && numberOfStrips == 0)
  {
    // The common case, in parallel: triangles, read straight from storage.
    VisitCells(polys,
      [&](const auto*, const auto* connectivity)
      { this->ReadTriangles(connectivity, numberOfPolys, cellsBeforePolys); });
  }
  else
  {
    faces.Offsets.reserve(numberOfPolys + 1);
    faces.Points.reserve(
      polys->GetNumberOfConnectivityIds() + 3 * strips->GetNumberOfConnectivityIds());
    this->FaceCell.reserve(numberOfPolys);
    VisitCells(polys,
      [&](const auto* offsets, const auto* connectivity)
      { this->ReadPolygons(offsets, connectivity, numberOfPolys, cellsBeforePolys); });
    VisitCells(strips,
      [&](const auto* offsets, const auto* connectivity) {
        this->ReadStrips(offsets, connectivity, numberOfStrips, cellsBeforePolys + numberOfPolys);
      });
  }
  faces.AllTriangles = faces.Points.size() == 3 * static_cast<size_t>(faces.Size());
  this->AssignCornerFaces();
}

//------------------------------------------------------------------------------
// Triangles only: the good ones (three distinct points) are numbered by a
// prefix sum, then copied in parallel.
template <typename Id>
void vtkOpenMeshNormalsTopology::ReadTriangles(
  const Id* connectivity, Index numberOfPolys, Index cellsBeforePolys)
{
  FaceList& faces = this->Faces;
  Buffer<char> good(numberOfPolys);
  vtkSMPTools::For(0, numberOfPolys,
    [&](Index begin, Index end)
    {
      for (Index t = begin; t < end; ++t)
      {
        const auto a = connectivity[3 * t], b = connectivity[3 * t + 1],
                   c = connectivity[3 * t + 2];
        good[t] = a != b && b != c && a != c;
      }
    });
  Buffer<Index> rank(numberOfPolys + 1, 0); // the face of each good triangle
  for (Index t = 0; t < numberOfPolys; ++t)
  {
    rank[t + 1] = rank[t] + good[t];
  }
  const Index count = rank[numberOfPolys];
  this->RepeatedPointFaces = this->DegenerateFaces = numberOfPolys - count;
  faces.Offsets.resize(count + 1);
  faces.Points.resize(3 * static_cast<size_t>(count));
  this->FaceCell.resize(count);
  vtkSMPTools::For(0, numberOfPolys,
    [&](Index begin, Index end)
    {
      for (Index t = begin; t < end; ++t)
      {
        if (!good[t])
        {
          continue;
        }
        const Index f = rank[t];
        faces.Offsets[f + 1] = 3 * (f + 1);
        this->PolyFace[t] = f;
        this->FaceCell[f] = cellsBeforePolys + t;
        for (int k = 0; k < 3; ++k)
        {
          faces.Points[3 * static_cast<size_t>(f) + k] =
            static_cast<Index>(connectivity[3 * t + k]);
        }
      }
    });
  faces.Offsets[0] = 0;
}

//------------------------------------------------------------------------------
template <typename Id>
void vtkOpenMeshNormalsTopology::ReadPolygons(
  const Id* offsets, const Id* connectivity, Index numberOfPolys, Index cellsBeforePolys)
{
  for (Index poly = 0; poly < numberOfPolys; ++poly)
  {
    if (this->AppendFace(
          connectivity + offsets[poly], connectivity + offsets[poly + 1], cellsBeforePolys + poly))
    {
      this->PolyFace[poly] = this->Faces.Size() - 1;
    }
  }
}

//------------------------------------------------------------------------------
template <typename Id>
void vtkOpenMeshNormalsTopology::ReadStrips(
  const Id* offsets, const Id* connectivity, Index numberOfStrips, Index cellsBeforeStrips)
{
  for (Index strip = 0; strip < numberOfStrips; ++strip)
  {
    const auto* points = connectivity + offsets[strip];
    const Index count = static_cast<Index>(offsets[strip + 1] - offsets[strip]);
    for (Index i = 0; i + 2 < count; ++i)
    {
      // Every other triangle of a strip turns the other way.
      const Index odd = i % 2;
      const Index triangle[3] = { static_cast<Index>(points[i + odd]),
        static_cast<Index>(points[i + 1 - odd]), static_cast<Index>(points[i + 2]) };
      if (this->AppendFace(triangle, triangle + 3, cellsBeforeStrips + strip))
      {
        this->StripFaces.push_back(this->Faces.Size() - 1);
      }
    }
  }
}

//------------------------------------------------------------------------------
// Appends the face of cell's points [begin, end) without its repeated points;
// false (and nothing appended) if fewer than three are left.
template <typename Iterator>
bool vtkOpenMeshNormalsTopology::AppendFace(Iterator begin, Iterator end, Index cell)
{
  FaceList& faces = this->Faces;
  const size_t start = faces.Points.size();
  for (auto it = begin; it != end; ++it)
  {
    const Index point = static_cast<Index>(*it);
    if (std::find(faces.Points.begin() + start, faces.Points.end(), point) == faces.Points.end())
    {
      faces.Points.push_back(point);
    }
  }
  const size_t size = faces.Points.size() - start;
  if (static_cast<std::ptrdiff_t>(size) != std::distance(begin, end))
  {
    ++this->RepeatedPointFaces;
  }
  if (size < 3)
  {
    ++this->DegenerateFaces;
    faces.Points.resize(start);
    return false;
  }
  faces.Offsets.push_back(static_cast<Index>(faces.Points.size()));
  this->FaceCell.push_back(cell);
  return true;
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsTopology::AssignCornerFaces()
{
  const FaceList& faces = this->Faces;
  this->CornerFace.resize(faces.Points.size());
  vtkSMPTools::For(0, faces.Size(),
    [&](Index begin, Index end)
    {
      for (Index f = begin; f < end; ++f)
      {
        std::fill(this->CornerFace.begin() + faces.Offsets[f],
          this->CornerFace.begin() + faces.Offsets[f + 1], f);
      }
    });
}

//------------------------------------------------------------------------------
// For each corner, its twin, or NoTwin (a boundary edge) or NonManifoldEdge
// (more than two faces on the edge). sameDirection: the twin runs the edge the
// same way (the two faces are oriented inconsistently).
vtkOpenMeshNormalsTopology::Buffer<vtkOpenMeshNormalsTopology::Index>
vtkOpenMeshNormalsTopology::FindTwins(const PointCorners& around, Buffer<char>& sameDirection) const
{
  const FaceList& faces = this->Faces;
  const TwinFinder finder(*this, around);
  Buffer<Index> twins(faces.Points.size()); // every entry written below
  sameDirection.resize(faces.Points.size());
  vtkSMPTools::For(0, around.NumberOfPoints(),
    [&](Index begin, Index end)
    {
      std::vector<std::pair<Index, Index>> ring; // each corner's next and previous points
      for (Index a = begin; a < end; ++a)
      {
        finder.FindAround(a, twins, sameDirection, ring);
      }
    });
  return twins;
}

//------------------------------------------------------------------------------
// Orientation, with the twins and the point-to-corner index updated to the
// reversed faces. A mesh whose neighbours already agree keeps its orientation
// without a walk, unless the pieces are needed (AutoOrientNormals sees them
// as closed or not through ComponentClosed). Fills FaceReversed,
// FaceComponent and ComponentClosed.
bool vtkOpenMeshNormalsTopology::OrientFaces(PointCorners& around, Buffer<Index>& twins,
  Buffer<char>& sameDirection, bool consistency, bool traversal, vtkOpenMeshNormals* filter)
{
  const Index numberOfFaces = this->NumberOfFaces();
  Buffer<signed char> orientation;
  const bool disagreement =
    std::any_of(sameDirection.begin(), sameDirection.end(), [](char same) { return same != 0; }) ||
    (traversal &&
      std::any_of(twins.begin(), twins.end(), [](Index twin) { return twin == NonManifoldEdge; }));
  const bool autoOrient = filter->GetAutoOrientNormals() != 0;
  if (consistency && (disagreement || autoOrient))
  {
    OrientationWalk walk(*this, around, twins, sameDirection, traversal, orientation);
    if (!walk.Run(filter))
    {
      return false;
    }
  }
  else
  {
    orientation.assign(numberOfFaces, 1);
    this->FaceComponent.assign(numberOfFaces, 0);
    this->ComponentClosed.assign(1, false);
  }
  this->FaceReversed.resize(numberOfFaces);
  for (Index f = 0; f < numberOfFaces; ++f)
  {
    this->FaceReversed[f] = orientation[f] < 0;
  }
  if (std::find(orientation.begin(), orientation.end(), -1) != orientation.end())
  {
    this->Reverse(orientation, twins, sameDirection);
    this->ReverseCornersAround(orientation, around);
  }
  return true;
}

//------------------------------------------------------------------------------
// Reverses the faces whose orientation is -1, in place: (p0, p1, ..., pn-1)
// becomes (p0, pn-1, ..., p1), so the edge of corner j moves to corner n-1-j.
void vtkOpenMeshNormalsTopology::Reverse(
  const Buffer<signed char>& orientation, Buffer<Index>& twins, Buffer<char>& sameDirection)
{
  FaceList& faces = this->Faces;
  const Index numberOfCorners = static_cast<Index>(faces.Points.size());
  auto moved = [&](Index corner)
  {
    const Index f = this->CornerFace[corner];
    if (orientation[f] > 0)
    {
      return corner;
    }
    const Index first = faces.Offsets[f], last = faces.Offsets[f + 1];
    return first + (last - 1 - corner);
  };
  Buffer<Index> newTwins(numberOfCorners);
  Buffer<char> newSame(numberOfCorners);
  vtkSMPTools::For(0, numberOfCorners,
    [&](Index begin, Index end)
    {
      for (Index c = begin; c < end; ++c)
      {
        const Index twin = twins[c];
        newTwins[moved(c)] = twin >= 0 ? moved(twin) : twin;
        const bool flipped = (orientation[this->CornerFace[c]] < 0) !=
          (twin >= 0 && orientation[this->CornerFace[twin]] < 0);
        newSame[moved(c)] = twin >= 0 ? ((sameDirection[c] != 0) != flipped) : 0;
      }
    });
  twins.swap(newTwins);
  sameDirection.swap(newSame);
  vtkSMPTools::For(0, faces.Size(),
    [&](Index begin, Index end)
    {
      for (Index f = begin; f < end; ++f)
      {
        if (orientation[f] < 0)
        {
          std::reverse(faces.Points.begin() + faces.Offsets[f] + 1,
            faces.Points.begin() + faces.Offsets[f + 1]);
        }
      }
    });
}

//------------------------------------------------------------------------------
// A reversed face's point p_j moved from corner j to corner (n - j) mod n.
void vtkOpenMeshNormalsTopology::ReverseCornersAround(
  const Buffer<signed char>& orientation, PointCorners& around) const
{
  const FaceList& faces = this->Faces;
  vtkSMPTools::For(0, static_cast<vtkIdType>(around.Corners.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        Index& corner = around.Corners[i];
        const Index f = this->CornerFace[corner];
        if (orientation[f] < 0)
        {
          const Index first = faces.Offsets[f], n = faces.Offsets[f + 1] - first;
          corner = first + (n - (corner - first)) % n;
        }
      }
    });
}

//------------------------------------------------------------------------------
// The fan around each vertex, read through OpenMesh's circulation: fan sizes
// first, then the fans into their slots, both in parallel.
void vtkOpenMeshNormalsTopology::ReadFans()
{
  const HalfedgeMesh& mesh = this->Mesh;
  const Index numberOfVertices = static_cast<Index>(mesh.n_vertices());
  this->FanOffsets.assign(numberOfVertices + 1, 0);
  vtkSMPTools::For(0, numberOfVertices,
    [&](Index begin, Index end)
    {
      for (Index v = begin; v < end; ++v)
      {
        Index count = 0;
        Circulate(mesh, v, [&](HalfedgeHandle h) { count += !mesh.is_boundary(h); });
        this->FanOffsets[v + 1] = count;
      }
    });
  for (Index v = 0; v < numberOfVertices; ++v)
  {
    this->FanOffsets[v + 1] += this->FanOffsets[v];
  }
  this->FanCorners.resize(this->FanOffsets.back());
  this->FanFaces.resize(this->FanOffsets.back());
  this->FanLinked.resize(this->FanOffsets.back());
  vtkSMPTools::For(0, numberOfVertices,
    [&](Index begin, Index end)
    {
      for (Index v = begin; v < end; ++v)
      {
        this->FillFan(v);
      }
    });
}

//------------------------------------------------------------------------------
// Vertex v's fan into its slots; a gap (a boundary halfedge) unlinks the
// corner before it.
void vtkOpenMeshNormalsTopology::FillFan(Index v)
{
  const HalfedgeMesh& mesh = this->Mesh;
  Index slot = this->FanOffsets[v];
  bool sawGap = false;
  Circulate(mesh, v,
    [&](HalfedgeHandle h)
    {
      if (mesh.is_boundary(h))
      {
        sawGap = true;
        if (slot > this->FanOffsets[v])
        {
          this->FanLinked[slot - 1] = 0;
        }
        return;
      }
      const Index meshFace = mesh.face_handle(h).idx();
      const Index f = this->MeshFaceIsIdentity ? meshFace : this->MeshFace[meshFace];
      Index corner = this->Faces.Offsets[f];
      while (this->FaceVertex[corner] != v)
      {
        ++corner;
      }
      this->FanCorners[slot] = corner;
      this->FanFaces[slot] = f;
      this->FanLinked[slot] = 1;
      ++slot;
    });
  // A boundary vertex starts at a boundary halfedge: its fan does not close.
  if (sawGap && slot > this->FanOffsets[v])
  {
    this->FanLinked[slot - 1] = 0;
  }
}
