#include "vtkOpenMeshNormals.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkOpenMeshNormals);

namespace
{
// OpenMesh holds the topology (halfedges) and the positions in double
// precision; the normals live in the filter's own arrays.
struct MeshTraits : public OpenMesh::DefaultTraits
{
  using Point = OpenMesh::Vec3d;
};
using HalfedgeMesh = OpenMesh::PolyMesh_ArrayKernelT<MeshTraits>;
using VertexHandle = HalfedgeMesh::VertexHandle;
using HalfedgeHandle = HalfedgeMesh::HalfedgeHandle;
using FaceHandle = HalfedgeMesh::FaceHandle;

// Indices of points, faces, corners and halfedges: OpenMesh's handles are
// 32-bit, so is everything the filter keeps.
using Index = int;

// Growing a vector with this allocator leaves plain values uninitialized. The
// filter's large arrays are written by parallel loops right after they are
// sized; value-initializing them first would touch (page-fault) all their
// memory serially on one thread, which for a million triangles costs more
// than the computation.
template <typename T>
struct UninitializedAllocator : std::allocator<T>
{
  template <typename U>
  struct rebind
  {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <typename U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept
  {
  }
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value)
  {
    ::new (static_cast<void*>(p)) U; // default-, not value-initialized
  }
  template <typename U, typename... Arguments>
  void construct(U* p, Arguments&&... arguments)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Arguments>(arguments)...);
  }
};
template <typename T>
using Buffer = std::vector<T, UninitializedAllocator<T>>;

using Vector = std::array<double, 3>;

inline Vector Subtract(const double* a, const double* b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

inline Vector Cross(const Vector& a, const Vector& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

inline double Dot(const Vector& a, const Vector& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline bool IsFinite(const double* p)
{
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

// How often long serial loops look at AbortExecute.
constexpr Index AbortCheckInterval = 1 << 16;

// The twin of a corner: the corner, in the face across the corner's outgoing
// edge (from its point to the next corner's), that holds the same edge.
// Boundary and non-manifold edges have none.
constexpr Index NoTwin = -1;
constexpr Index NonManifoldEdge = -2;

// Faces as compressed rows: the corners of face f are [Offsets[f],
// Offsets[f + 1]), each holding an input point id.
struct FaceList
{
  Buffer<Index> Offsets{ 0 };
  Buffer<Index> Points;
  bool AllTriangles = false; // then face f's corners are 3f, 3f + 1, 3f + 2
  Index Size() const { return static_cast<Index>(this->Offsets.size()) - 1; }
  Index Next(Index corner, Index face) const
  {
    if (this->AllTriangles)
    {
      return corner % 3 == 2 ? corner - 2 : corner + 1;
    }
    return corner + 1 < this->Offsets[face + 1] ? corner + 1 : this->Offsets[face];
  }
  Index Previous(Index corner, Index face) const
  {
    if (this->AllTriangles)
    {
      return corner % 3 == 0 ? corner + 2 : corner - 1;
    }
    return corner > this->Offsets[face] ? corner - 1 : this->Offsets[face + 1] - 1;
  }
};

// The corners at each point, as compressed rows.
struct PointCorners
{
  Buffer<Index> Offsets;
  Buffer<Index> Corners;
  void Build(const Buffer<Index>& points, Index numberOfPoints)
  {
    this->Offsets.assign(numberOfPoints + 1, 0);
    for (Index point : points)
    {
      ++this->Offsets[point + 1];
    }
    for (Index p = 0; p < numberOfPoints; ++p)
    {
      this->Offsets[p + 1] += this->Offsets[p];
    }
    this->Corners.resize(points.size());
    Buffer<Index> fill(this->Offsets.begin(), this->Offsets.end() - 1);
    for (Index c = 0; c < static_cast<Index>(points.size()); ++c)
    {
      this->Corners[fill[points[c]]++] = c;
    }
  }
};

// Visits the offsets and connectivity of a vtkCellArray, whatever its
// storage (32- or 64-bit).
template <typename Visit>
void VisitCells(vtkCellArray* cells, Visit&& visit)
{
  if (cells->IsStorage64Bit())
  {
    visit(
      cells->GetOffsetsArray64()->GetPointer(0), cells->GetConnectivityArray64()->GetPointer(0));
  }
  else
  {
    visit(
      cells->GetOffsetsArray32()->GetPointer(0), cells->GetConnectivityArray32()->GetPointer(0));
  }
}
}

// Everything that depends only on the connectivity: kept between executions
// and reused when only the points change.
struct vtkOpenMeshNormals::Internals
{
  // What the topology was built from.
  vtkCellArray* Polys = nullptr;
  vtkMTimeType PolysTime = 0;
  vtkCellArray* Strips = nullptr;
  vtkMTimeType StripsTime = 0;
  vtkIdType NumberOfPoints = -1;
  bool Consistency = false;
  bool NonManifoldTraversal = false;
  bool Incremental = false;
  bool Valid = false;

  // Faces: polygons with at least three distinct points, in input order
  // (polygons, then the strips' triangles), each in its consistent
  // orientation.
  FaceList Faces;
  Buffer<Index> CornerFace;  // the face of each corner
  Buffer<Index> FaceVertex;  // the OpenMesh vertex of each corner
  Buffer<Index> FaceCell;    // the input cell each face comes from
  Buffer<char> FaceReversed; // Consistency reversed the input order
  Buffer<Index> FaceComponent;
  Buffer<char> ComponentClosed;
  Buffer<Index> PolyFace;   // each input polygon's face, -1 if degenerate
  Buffer<Index> StripFaces; // the faces from triangle strips, in order

  HalfedgeMesh Mesh;
  Buffer<Index> VertexPoint; // the input point of each OpenMesh vertex
  Buffer<char> VertexIsCopy; // a copy made for a face OpenMesh refused
  Buffer<Index> MeshFace;    // the face of each OpenMesh face (unless the identity)
  bool MeshFaceIsIdentity = false;

  // The fan of each OpenMesh vertex in circulation order: corners, and
  // whether a corner shares an edge with the next one.
  Buffer<Index> FanOffsets;
  Buffer<Index> FanCorners;
  Buffer<Index> FanFaces; // the face of each fan corner
  Buffer<char> FanLinked;

  // Per-update scratch, kept so that repeated updates reuse the memory.
  std::vector<double, UninitializedAllocator<double>> FaceLength;
  Buffer<char> FaceValid;
  Buffer<float> CornerWeight;
  Buffer<signed char> FaceSign;
  Buffer<Vector> UnitNormal;
  Buffer<char> Cuts;
  Buffer<Index> WedgeCount;
  Buffer<float> SingleNormal;
  Buffer<Index> SplitCornerPoint;
  Buffer<Index> FirstNewId;

  // The last output's connectivity and where its split points came from: a
  // positions-only update that cuts the fans at the same places reuses them.
  Buffer<char> LastCuts;
  vtkSmartPointer<vtkCellArray> LastPolys;
  Buffer<Index> LastSplitSource;
  Buffer<Index> LastCornerPoint;

  vtkIdType NonManifoldFaces = 0;
  vtkIdType RepeatedPointFaces = 0;
  vtkIdType DegenerateFaces = 0;
  vtkIdType IrregularFaces = 0; // loaded through OpenMesh's add_face

  Index NumberOfFaces() const { return this->Faces.Size(); }
  bool Matches(vtkPolyData* input, bool consistency, bool traversal, bool incremental) const;
  bool Build(vtkPolyData* input, bool consistency, bool traversal, bool incremental,
    vtkOpenMeshNormals* self);

private:
  void ReadFaces(vtkPolyData* input);
  Buffer<Index> FindTwins(const PointCorners& around, Buffer<char>& sameDirection) const;
  bool Orient(const PointCorners& around, const Buffer<Index>& twins,
    const Buffer<char>& sameDirection, bool traversal, Buffer<signed char>& orientation,
    vtkOpenMeshNormals* self);
  void Reverse(
    const Buffer<signed char>& orientation, Buffer<Index>& twins, Buffer<char>& sameDirection);
  Buffer<char> FindIrregularFaces(const PointCorners& around, const Buffer<Index>& twins,
    const Buffer<char>& sameDirection) const;
  bool LoadMesh(const PointCorners& around, const Buffer<Index>& twins,
    const Buffer<char>& irregular, vtkOpenMeshNormals* self);
  void ReadFans();
};

//------------------------------------------------------------------------------
bool vtkOpenMeshNormals::Internals::Matches(
  vtkPolyData* input, bool consistency, bool traversal, bool incremental) const
{
  vtkCellArray* polys = input->GetPolys();
  vtkCellArray* strips = input->GetStrips();
  return this->Valid && this->Polys == polys && this->PolysTime == polys->GetMTime() &&
    this->Strips == strips && this->StripsTime == strips->GetMTime() &&
    this->NumberOfPoints == input->GetNumberOfPoints() && this->Consistency == consistency &&
    this->NonManifoldTraversal == traversal && this->Incremental == incremental;
}

//------------------------------------------------------------------------------
// Faces from polygons and strips, in input order, without repeated points
// (OpenMesh refuses them); faces left with fewer than three points are not
// faces. Fills PolyFace, StripFaces, FaceCell and CornerFace.
void vtkOpenMeshNormals::Internals::ReadFaces(vtkPolyData* input)
{
  vtkCellArray* polys = input->GetPolys();
  vtkCellArray* strips = input->GetStrips();
  const Index cellsBeforePolys =
    static_cast<Index>(input->GetNumberOfVerts() + input->GetNumberOfLines());
  const Index numberOfPolys = static_cast<Index>(polys->GetNumberOfCells());
  const Index cellsBeforeStrips = cellsBeforePolys + numberOfPolys;
  FaceList& faces = this->Faces;
  faces.Offsets.assign(1, 0);
  faces.Points.clear();
  this->FaceCell.clear();
  this->PolyFace.assign(numberOfPolys, -1);
  this->StripFaces.clear();

  const bool onlyTriangles =
    polys->GetNumberOfConnectivityIds() == 3 * numberOfPolys && strips->GetNumberOfCells() == 0;
  if (onlyTriangles)
  {
    // The common case, in parallel: triangles, read straight from storage.
    Buffer<char> good(numberOfPolys);
    VisitCells(polys,
      [&](const auto*, const auto* connectivity)
      {
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
        Index count = 0;
        for (Index t = 0; t < numberOfPolys; ++t)
        {
          count += good[t];
        }
        this->RepeatedPointFaces = this->DegenerateFaces = numberOfPolys - count;
        Buffer<Index> rank(numberOfPolys + 1, 0);
        for (Index t = 0; t < numberOfPolys; ++t)
        {
          rank[t + 1] = rank[t] + good[t];
        }
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
      });
  }
  else
  {
    faces.Offsets.reserve(numberOfPolys + 1);
    faces.Points.reserve(
      polys->GetNumberOfConnectivityIds() + 3 * strips->GetNumberOfConnectivityIds());
    this->FaceCell.reserve(numberOfPolys);
    auto add = [&](auto begin, auto end, Index cell)
    {
      const size_t start = faces.Points.size();
      for (auto it = begin; it != end; ++it)
      {
        const Index point = static_cast<Index>(*it);
        if (std::find(faces.Points.begin() + start, faces.Points.end(), point) ==
          faces.Points.end())
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
    };
    VisitCells(polys,
      [&](const auto* offsets, const auto* connectivity)
      {
        for (Index poly = 0; poly < numberOfPolys; ++poly)
        {
          if (add(connectivity + offsets[poly], connectivity + offsets[poly + 1],
                cellsBeforePolys + poly))
          {
            this->PolyFace[poly] = faces.Size() - 1;
          }
        }
      });
    const Index numberOfStrips = static_cast<Index>(strips->GetNumberOfCells());
    VisitCells(strips,
      [&](const auto* offsets, const auto* connectivity)
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
            if (add(triangle, triangle + 3, cellsBeforeStrips + strip))
            {
              this->StripFaces.push_back(faces.Size() - 1);
            }
          }
        }
      });
  }
  const Index numberOfFaces = faces.Size();
  faces.AllTriangles = faces.Points.size() == 3 * static_cast<size_t>(numberOfFaces);
  this->CornerFace.resize(faces.Points.size());
  vtkSMPTools::For(0, numberOfFaces,
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
Buffer<Index> vtkOpenMeshNormals::Internals::FindTwins(
  const PointCorners& around, Buffer<char>& sameDirection) const
{
  const FaceList& faces = this->Faces;
  const Index numberOfCorners = static_cast<Index>(faces.Points.size());
  // Each corner's next and previous points side by side: the search below
  // reads one small record per candidate instead of following three arrays.
  // Triangles find them by arithmetic and skip the copy.
  Buffer<Index> neighbours(faces.AllTriangles ? 0 : 2 * static_cast<size_t>(numberOfCorners));
  if (!faces.AllTriangles)
  {
    vtkSMPTools::For(0, faces.Size(),
      [&](Index begin, Index end)
      {
        for (Index f = begin; f < end; ++f)
        {
          for (Index c = faces.Offsets[f]; c < faces.Offsets[f + 1]; ++c)
          {
            neighbours[2 * static_cast<size_t>(c)] = faces.Points[faces.Next(c, f)];
            neighbours[2 * static_cast<size_t>(c) + 1] = faces.Points[faces.Previous(c, f)];
          }
        }
      });
  }
  auto nextPoint = [&](Index c)
  {
    return faces.AllTriangles ? faces.Points[faces.Next(c, 0)]
                              : neighbours[2 * static_cast<size_t>(c)];
  };
  auto previousPoint = [&](Index c)
  {
    return faces.AllTriangles ? faces.Points[faces.Previous(c, 0)]
                              : neighbours[2 * static_cast<size_t>(c) + 1];
  };
  Buffer<Index> twins(numberOfCorners); // every entry written below
  sameDirection.resize(numberOfCorners);
  vtkSMPTools::For(0, faces.Size(),
    [&](Index begin, Index end)
    {
      for (Index f = begin; f < end; ++f)
      {
        const Index first = faces.Offsets[f], last = faces.Offsets[f + 1];
        for (Index c = first; c < last; ++c)
        {
          const Index a = faces.Points[c], b = nextPoint(c);
          Index found = NoTwin;
          char same = 0;
          for (Index i = around.Offsets[a]; i < around.Offsets[a + 1] && found != NonManifoldEdge;
               ++i)
          {
            const Index d = around.Corners[i]; // a corner of another face g at a
            if (d >= first && d < last)
            {
              continue;
            }
            Index twin = NoTwin;
            if (nextPoint(d) == b)
            {
              twin = d; // g also runs a -> b
              same = 1;
            }
            else if (previousPoint(d) == b)
            {
              twin = faces.Previous(d, this->CornerFace[d]); // g runs b -> a
              same = 0;
            }
            if (twin != NoTwin)
            {
              found = (found == NoTwin) ? twin : NonManifoldEdge;
            }
          }
          twins[c] = found;
          sameDirection[c] = found >= 0 ? same : 0;
        }
      }
    });
  return twins;
}

//------------------------------------------------------------------------------
// Orientation by a breadth-first walk over twins per connected piece; each
// piece keeps the orientation most of its faces already have (not that of the
// face the walk started from). Fills FaceComponent and ComponentClosed.
bool vtkOpenMeshNormals::Internals::Orient(const PointCorners& around, const Buffer<Index>& twins,
  const Buffer<char>& sameDirection, bool traversal, Buffer<signed char>& orientation,
  vtkOpenMeshNormals* self)
{
  const FaceList& faces = this->Faces;
  const Index numberOfFaces = faces.Size();
  orientation.assign(numberOfFaces, 0);
  this->FaceComponent.assign(numberOfFaces, 0);
  this->ComponentClosed.clear();

  // The faces across a non-manifold edge (which has no single twin).
  std::vector<std::pair<Index, bool>> across;
  auto nonManifoldNeighbours = [&](Index f, Index c)
  {
    across.clear();
    const Index a = faces.Points[c], b = faces.Points[faces.Next(c, f)];
    for (Index i = around.Offsets[a]; i < around.Offsets[a + 1]; ++i)
    {
      const Index d = around.Corners[i];
      const Index g = this->CornerFace[d];
      if (g == f)
      {
        continue;
      }
      if (faces.Points[faces.Next(d, g)] == b)
      {
        across.emplace_back(g, true);
      }
      else if (faces.Points[faces.Previous(d, g)] == b)
      {
        across.emplace_back(g, false);
      }
    }
  };

  Buffer<Index> order;
  order.reserve(numberOfFaces);
  for (Index seed = 0; seed < numberOfFaces; ++seed)
  {
    if (orientation[seed] != 0)
    {
      continue;
    }
    const Index component = static_cast<Index>(this->ComponentClosed.size());
    bool closed = true;
    const size_t start = order.size();
    orientation[seed] = 1;
    this->FaceComponent[seed] = component;
    order.push_back(seed);
    auto reach = [&](Index f, Index g, bool same)
    {
      if (orientation[g] == 0)
      {
        // Consistent neighbours run their shared edge in opposite directions.
        orientation[g] = static_cast<signed char>(same ? -orientation[f] : orientation[f]);
        this->FaceComponent[g] = component;
        order.push_back(g);
      }
      else if ((orientation[g] == orientation[f]) == same)
      {
        closed = false; // not orientable (a Moebius strip)
      }
    };
    for (size_t next = start; next < order.size(); ++next)
    {
      const Index f = order[next];
      for (Index c = faces.Offsets[f]; c < faces.Offsets[f + 1]; ++c)
      {
        const Index twin = twins[c];
        if (twin >= 0)
        {
          reach(f, this->CornerFace[twin], sameDirection[c] != 0);
        }
        else
        {
          closed = false;
          if (twin == NonManifoldEdge && traversal)
          {
            nonManifoldNeighbours(f, c);
            for (const auto& neighbour : across)
            {
              reach(f, neighbour.first, neighbour.second);
            }
          }
        }
      }
      if (next % AbortCheckInterval == 0 && self->GetAbortExecute())
      {
        return false;
      }
    }
    const size_t reversed = static_cast<size_t>(std::count_if(
      order.begin() + start, order.end(), [&](Index f) { return orientation[f] < 0; }));
    if (2 * reversed > order.size() - start)
    {
      for (size_t i = start; i < order.size(); ++i)
      {
        orientation[order[i]] = static_cast<signed char>(-orientation[order[i]]);
      }
    }
    this->ComponentClosed.push_back(closed);
  }
  return true;
}

//------------------------------------------------------------------------------
// Reverses the faces whose orientation is -1, in place: (p0, p1, ..., pn-1)
// becomes (p0, pn-1, ..., p1), so the edge of corner j moves to corner n-1-j.
void vtkOpenMeshNormals::Internals::Reverse(
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
// Faces the direct construction leaves to OpenMesh's add_face: those on a
// non-manifold or inconsistent edge, and every face around a point whose
// other faces do not make one fan (one cycle or one open chain).
Buffer<char> vtkOpenMeshNormals::Internals::FindIrregularFaces(
  const PointCorners& around, const Buffer<Index>& twins, const Buffer<char>& sameDirection) const
{
  const FaceList& faces = this->Faces;
  const Index numberOfFaces = faces.Size();
  const Index numberOfPoints = static_cast<Index>(around.Offsets.size()) - 1;
  Buffer<char> irregular(numberOfFaces, 0);
  vtkSMPTools::For(0, numberOfFaces,
    [&](Index begin, Index end)
    {
      for (Index f = begin; f < end; ++f)
      {
        for (Index c = faces.Offsets[f]; c < faces.Offsets[f + 1]; ++c)
        {
          if (twins[c] == NonManifoldEdge || (twins[c] >= 0 && sameDirection[c]))
          {
            irregular[f] = 1;
          }
        }
      }
    });
  // Around a point, from the corner c of a regular face: the next corner
  // (across c's outgoing edge) and the previous one (across its incoming
  // edge), or -1 at a gap.
  auto next = [&](Index c) -> Index
  {
    const Index twin = twins[c];
    if (twin < 0 || irregular[this->CornerFace[twin]])
    {
      return -1;
    }
    return faces.Next(twin, this->CornerFace[twin]);
  };
  auto previous = [&](Index c) -> Index
  {
    const Index twin = twins[faces.Previous(c, this->CornerFace[c])];
    return (twin < 0 || irregular[this->CornerFace[twin]]) ? -1 : twin;
  };
  // Whether the regular faces around point p make (at most) one fan.
  auto oneFan = [&](Index p)
  {
    Index count = 0, starts = 0, start = -1;
    for (Index i = around.Offsets[p]; i < around.Offsets[p + 1]; ++i)
    {
      const Index c = around.Corners[i];
      if (irregular[this->CornerFace[c]])
      {
        continue;
      }
      ++count;
      if (previous(c) < 0)
      {
        ++starts;
        start = c;
      }
      else if (start < 0)
      {
        start = c;
      }
    }
    if (count == 0)
    {
      return true;
    }
    if (starts > 1)
    {
      return false;
    }
    Index visited = 1;
    for (Index c = next(start); c >= 0 && c != start && visited <= count; c = next(c))
    {
      ++visited;
    }
    return visited == count;
  };
  Buffer<char> pointRegular(numberOfPoints, 1);
  std::atomic<bool> anyIrregular(false);
  vtkSMPTools::For(0, numberOfPoints,
    [&](Index begin, Index end)
    {
      for (Index p = begin; p < end; ++p)
      {
        if (!oneFan(p))
        {
          pointRegular[p] = 0;
          anyIrregular = true;
        }
      }
    });
  if (!anyIrregular)
  {
    return irregular;
  }
  // Spread, rarely: an irregular point's faces go to add_face, which can
  // leave the regular faces around their other points in several fans.
  Buffer<Index> work;
  for (Index p = 0; p < numberOfPoints; ++p)
  {
    if (!pointRegular[p])
    {
      work.push_back(p);
    }
  }
  while (!work.empty())
  {
    Buffer<Index> touched;
    for (Index p : work)
    {
      for (Index i = around.Offsets[p]; i < around.Offsets[p + 1]; ++i)
      {
        const Index f = this->CornerFace[around.Corners[i]];
        if (!irregular[f])
        {
          irregular[f] = 1;
          touched.insert(touched.end(), faces.Points.begin() + faces.Offsets[f],
            faces.Points.begin() + faces.Offsets[f + 1]);
        }
      }
    }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    work.clear();
    for (Index p : touched)
    {
      if (!oneFan(p))
      {
        work.push_back(p);
      }
    }
  }
  return irregular;
}

//------------------------------------------------------------------------------
// Loads the faces into OpenMesh. Regular faces are written straight into
// OpenMesh's kernel, in parallel, in the state add_face would leave them in;
// the others go through add_face, and a face it refuses gets its own copies
// of its vertices, as OpenMesh's importer does.
bool vtkOpenMeshNormals::Internals::LoadMesh(const PointCorners& around, const Buffer<Index>& twins,
  const Buffer<char>& irregular, vtkOpenMeshNormals* self)
{
  const FaceList& faces = this->Faces;
  const Index numberOfFaces = faces.Size();
  const Index numberOfCorners = static_cast<Index>(faces.Points.size());
  const Index numberOfPoints = static_cast<Index>(around.Offsets.size()) - 1;
  HalfedgeMesh& mesh = this->Mesh;
  mesh.clear();

  // One vertex for every point some face uses, in point order.
  Buffer<Index> vertexOfPoint(numberOfPoints, -1);
  this->VertexPoint.clear();
  for (Index p = 0; p < numberOfPoints; ++p)
  {
    if (around.Offsets[p + 1] > around.Offsets[p])
    {
      vertexOfPoint[p] = static_cast<Index>(this->VertexPoint.size());
      this->VertexPoint.push_back(p);
    }
  }
  const Index numberOfVertices = static_cast<Index>(this->VertexPoint.size());
  this->VertexIsCopy.assign(numberOfVertices, 0);

  // Regular faces first: OpenMesh face i is the i-th regular face. A regular
  // corner owns its edge unless its twin is an earlier regular corner.
  const bool allRegular = std::find(irregular.begin(), irregular.end(), 1) == irregular.end();
  // With every face regular OpenMesh's faces are the filter's, in order.
  Buffer<Index> meshFaceOf;
  this->MeshFace.clear();
  this->MeshFaceIsIdentity = allRegular;
  if (!allRegular)
  {
    meshFaceOf.assign(numberOfFaces, -1);
    for (Index f = 0; f < numberOfFaces; ++f)
    {
      if (!irregular[f])
      {
        meshFaceOf[f] = static_cast<Index>(this->MeshFace.size());
        this->MeshFace.push_back(f);
      }
    }
  }
  const Index numberOfRegularFaces =
    allRegular ? numberOfFaces : static_cast<Index>(this->MeshFace.size());
  auto regularTwin = [&](Index c)
  {
    const Index twin = twins[c];
    if (allRegular)
    {
      return twin >= 0 ? twin : NoTwin;
    }
    return (twin >= 0 && !irregular[this->CornerFace[twin]]) ? twin : NoTwin;
  };
  // Halfedge ids: a corner owning its edge takes halfedge 2e (its own
  // direction), its twin 2e + 1. Owners are counted per face in parallel and
  // numbered in face order.
  Buffer<Index> halfedgeOfCorner(numberOfCorners, -1);
  Buffer<Index> firstEdge(numberOfFaces + 1, 0);
  auto owns = [&](Index c)
  {
    const Index twin = regularTwin(c);
    return twin == NoTwin || c < twin;
  };
  vtkSMPTools::For(0, numberOfFaces,
    [&](Index begin, Index end)
    {
      for (Index f = begin; f < end; ++f)
      {
        Index count = 0;
        if (!irregular[f])
        {
          for (Index c = faces.Offsets[f]; c < faces.Offsets[f + 1]; ++c)
          {
            count += owns(c);
          }
        }
        firstEdge[f + 1] = count;
      }
    });
  for (Index f = 0; f < numberOfFaces; ++f)
  {
    firstEdge[f + 1] += firstEdge[f];
  }
  const Index numberOfEdges = firstEdge[numberOfFaces];
  vtkSMPTools::For(0, numberOfFaces,
    [&](Index begin, Index end)
    {
      for (Index f = begin; f < end; ++f)
      {
        if (irregular[f])
        {
          continue;
        }
        Index edge = firstEdge[f];
        for (Index c = faces.Offsets[f]; c < faces.Offsets[f + 1]; ++c)
        {
          if (owns(c))
          {
            halfedgeOfCorner[c] = 2 * edge++;
          }
        }
      }
    });
  vtkSMPTools::For(0, numberOfCorners,
    [&](Index begin, Index end)
    {
      for (Index c = begin; c < end; ++c)
      {
        if (halfedgeOfCorner[c] < 0 && !irregular[this->CornerFace[c]])
        {
          halfedgeOfCorner[c] = halfedgeOfCorner[regularTwin(c)] + 1;
        }
      }
    });
  mesh.resize(numberOfVertices, numberOfEdges, numberOfRegularFaces);
  this->FaceVertex.resize(numberOfCorners); // every corner written below
  vtkSMPTools::For(0, numberOfFaces,
    [&](Index begin, Index end)
    {
      for (Index f = begin; f < end; ++f)
      {
        if (irregular[f])
        {
          continue;
        }
        const FaceHandle face(allRegular ? f : meshFaceOf[f]);
        for (Index c = faces.Offsets[f]; c < faces.Offsets[f + 1]; ++c)
        {
          const Index next = faces.Next(c, f);
          const HalfedgeHandle h(halfedgeOfCorner[c]);
          this->FaceVertex[c] = vertexOfPoint[faces.Points[c]];
          // Each halfedge gets its vertex from the corner it belongs to; a
          // boundary halfedge (the owner's opposite, no twin) from its owner.
          mesh.set_vertex_handle(h, VertexHandle(vertexOfPoint[faces.Points[next]]));
          if (regularTwin(c) == NoTwin)
          {
            mesh.set_vertex_handle(
              mesh.opposite_halfedge_handle(h), VertexHandle(vertexOfPoint[faces.Points[c]]));
          }
          mesh.set_next_halfedge_handle(h, HalfedgeHandle(halfedgeOfCorner[next]));
          mesh.set_face_handle(h, face);
        }
        mesh.set_halfedge_handle(face, HalfedgeHandle(halfedgeOfCorner[faces.Offsets[f]]));
      }
    });
  // Each point's outgoing halfedge, and at its one gap (if any) the incoming
  // boundary halfedge continuing with the outgoing one, as add_face links them.
  vtkSMPTools::For(0, numberOfPoints,
    [&](Index begin, Index end)
    {
      for (Index p = begin; p < end; ++p)
      {
        Index anyOutgoing = -1, incomingBoundary = -1, outgoingBoundary = -1;
        for (Index i = around.Offsets[p]; i < around.Offsets[p + 1]; ++i)
        {
          const Index c = around.Corners[i];
          const Index f = this->CornerFace[c];
          if (irregular[f])
          {
            continue;
          }
          anyOutgoing = halfedgeOfCorner[c];
          if (regularTwin(c) == NoTwin) // c's edge p -> next has nothing across
          {
            incomingBoundary = halfedgeOfCorner[c] ^ 1;
          }
          const Index previous = faces.Previous(c, f);
          if (regularTwin(previous) == NoTwin) // previous -> p has nothing across
          {
            outgoingBoundary = halfedgeOfCorner[previous] ^ 1;
          }
        }
        if (anyOutgoing < 0)
        {
          continue;
        }
        const VertexHandle vertex(vertexOfPoint[p]);
        if (outgoingBoundary >= 0)
        {
          mesh.set_next_halfedge_handle(
            HalfedgeHandle(incomingBoundary), HalfedgeHandle(outgoingBoundary));
          mesh.set_halfedge_handle(vertex, HalfedgeHandle(outgoingBoundary));
        }
        else
        {
          mesh.set_halfedge_handle(vertex, HalfedgeHandle(anyOutgoing));
        }
      }
    });

  // Irregular faces through add_face; a refused face gets fresh vertices.
  this->IrregularFaces = numberOfFaces - numberOfRegularFaces;
  if (this->IrregularFaces > 0)
  {
    OpenMesh::mostream& errors = omerr(); // OpenMesh declares it globally
    const bool errorsWereOn = errors.is_enabled();
    errors.disable(); // the refusals are expected, counted and reported once
    std::vector<VertexHandle> handles;
    for (Index f = 0; f < numberOfFaces; ++f)
    {
      if (!irregular[f])
      {
        continue;
      }
      const Index first = faces.Offsets[f], size = faces.Offsets[f + 1] - first;
      handles.resize(size);
      for (Index k = 0; k < size; ++k)
      {
        handles[k] = VertexHandle(vertexOfPoint[faces.Points[first + k]]);
      }
      if (!mesh.add_face(handles).is_valid())
      {
        ++this->NonManifoldFaces;
        for (Index k = 0; k < size; ++k)
        {
          handles[k] = mesh.new_vertex();
          this->VertexPoint.push_back(faces.Points[first + k]);
          this->VertexIsCopy.push_back(1);
        }
        mesh.add_face(handles); // a face on fresh vertices cannot be refused
      }
      this->MeshFace.push_back(f);
      for (Index k = 0; k < size; ++k)
      {
        this->FaceVertex[first + k] = handles[k].idx();
      }
      if (f % AbortCheckInterval == 0 && self->GetAbortExecute())
      {
        break;
      }
    }
    if (errorsWereOn)
    {
      errors.enable();
    }
  }
  return !self->GetAbortExecute();
}

//------------------------------------------------------------------------------
// The fan around each vertex, read through OpenMesh's circulation (from an
// outgoing halfedge, the opposite of its previous is the next outgoing one,
// across a shared edge or, at a gap, through a boundary halfedge).
void vtkOpenMeshNormals::Internals::ReadFans()
{
  const HalfedgeMesh& mesh = this->Mesh;
  const Index numberOfVertices = static_cast<Index>(mesh.n_vertices());
  this->FanOffsets.assign(numberOfVertices + 1, 0);
  auto circulate = [&](Index v, auto&& visit)
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
  };
  // Fan sizes first, then the fans into their slots.
  vtkSMPTools::For(0, numberOfVertices,
    [&](Index begin, Index end)
    {
      for (Index v = begin; v < end; ++v)
      {
        Index count = 0;
        circulate(v, [&](HalfedgeHandle h) { count += !mesh.is_boundary(h); });
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
        Index slot = this->FanOffsets[v];
        bool sawGap = false;
        circulate(v,
          [&](HalfedgeHandle h)
          {
            if (!mesh.is_boundary(h))
            {
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
            }
            else
            {
              sawGap = true;
              if (slot > this->FanOffsets[v])
              {
                this->FanLinked[slot - 1] = 0;
              }
            }
          });
        // A boundary vertex starts at a boundary halfedge: its fan does not close.
        if (sawGap && slot > this->FanOffsets[v])
        {
          this->FanLinked[slot - 1] = 0;
        }
      }
    });
}

//------------------------------------------------------------------------------
bool vtkOpenMeshNormals::Internals::Build(
  vtkPolyData* input, bool consistency, bool traversal, bool incremental, vtkOpenMeshNormals* self)
{
  this->Valid = false;
  this->NonManifoldFaces = this->RepeatedPointFaces = this->DegenerateFaces = 0;
  const vtkIdType inputPoints = input->GetNumberOfPoints();
  const vtkIdType inputCorners = input->GetPolys()->GetNumberOfConnectivityIds() +
    3 * input->GetStrips()->GetNumberOfConnectivityIds();
  if (inputPoints >= std::numeric_limits<Index>::max() / 2 ||
    inputCorners >= std::numeric_limits<Index>::max() / 2)
  {
    vtkErrorWithObjectMacro(self,
      "The mesh is too large for OpenMesh's 32-bit handles ("
        << inputPoints << " points, " << inputCorners << " polygon corners).");
    return false;
  }
  const Index numberOfPoints = static_cast<Index>(inputPoints);

  this->ReadFaces(input);
  const Index numberOfFaces = this->Faces.Size();
  self->UpdateProgress(0.1);

  PointCorners around;
  around.Build(this->Faces.Points, numberOfPoints);
  Buffer<char> sameDirection;
  Buffer<Index> twins = this->FindTwins(around, sameDirection);
  self->UpdateProgress(0.25);

  // Orientation. A mesh whose neighbours already agree keeps its orientation
  // without a walk, unless the pieces are needed (AutoOrientNormals sees
  // them as closed or not through ComponentClosed).
  Buffer<signed char> orientation;
  const bool disagreement =
    std::any_of(sameDirection.begin(), sameDirection.end(), [](char same) { return same != 0; }) ||
    (traversal &&
      std::any_of(twins.begin(), twins.end(), [](Index twin) { return twin == NonManifoldEdge; }));
  const bool autoOrient = self->GetAutoOrientNormals() != 0;
  if (consistency && (disagreement || autoOrient))
  {
    if (!this->Orient(around, twins, sameDirection, traversal, orientation, self))
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
    // A reversed face's point p_j moved from corner j to corner (n - j) mod n.
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
  self->UpdateProgress(0.4);

  const Buffer<char> irregular = incremental
    ? Buffer<char>(numberOfFaces, 1)
    : this->FindIrregularFaces(around, twins, sameDirection);
  self->UpdateProgress(0.5);
  if (!this->LoadMesh(around, twins, irregular, self))
  {
    return false;
  }
  self->UpdateProgress(0.6);
  this->ReadFans();
  self->UpdateProgress(0.7);

  this->Polys = input->GetPolys();
  this->PolysTime = this->Polys->GetMTime();
  this->Strips = input->GetStrips();
  this->StripsTime = this->Strips->GetMTime();
  this->NumberOfPoints = inputPoints;
  this->Consistency = consistency;
  this->NonManifoldTraversal = traversal;
  this->Incremental = incremental;
  this->Valid = true;
  return true;
}

//------------------------------------------------------------------------------
vtkOpenMeshNormals::vtkOpenMeshNormals()
  : Internal(new Internals)
{
  this->SetOriginalPointIdsArrayName("vtkOriginalPointIds");
}

//------------------------------------------------------------------------------
vtkOpenMeshNormals::~vtkOpenMeshNormals()
{
  this->SetOriginalPointIdsArrayName(nullptr);
}

//------------------------------------------------------------------------------
const char* vtkOpenMeshNormals::GetWeightingAsString()
{
  switch (this->Weighting)
  {
    case Uniform:
      return "Uniform";
    case Area:
      return "Area";
    case Angle:
      return "Angle";
    case Max:
    default:
      return "Max";
  }
}

namespace
{
// Writes a unit normal, or +z where no normal is defined.
void StoreNormal(const Vector& sum, float* out)
{
  const double length = std::sqrt(Dot(sum, sum));
  if (length > 0.0 && std::isfinite(length))
  {
    out[0] = static_cast<float>(sum[0] / length);
    out[1] = static_cast<float>(sum[1] / length);
    out[2] = static_cast<float>(sum[2] / length);
  }
  else
  {
    out[0] = 0.f;
    out[1] = 0.f;
    out[2] = 1.f;
  }
}
}

//------------------------------------------------------------------------------
int vtkOpenMeshNormals::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfNonManifoldFaces = this->NumberOfFacesWithRepeatedPoints = 0;
  this->NumberOfDegenerateFaces = this->NumberOfReorientedFaces = this->NumberOfSplitPoints = 0;
  this->TopologyReused = false;
  if (!input || !input->GetPoints() || input->GetNumberOfPoints() == 0)
  {
    output->ShallowCopy(input); // empty input: nothing to compute
    return 1;
  }
  Internals& topology = *this->Internal;
  const bool consistency = this->Consistency || this->AutoOrientNormals;
  const bool traversal = this->NonManifoldTraversal != 0;
  const bool incremental = this->IncrementalConstruction != 0;

  // Topology: reused when only the points changed.
  if (topology.Matches(input, consistency, traversal, incremental))
  {
    this->TopologyReused = true;
  }
  else
  {
    topology.LastPolys = nullptr;
    if (!topology.Build(input, consistency, traversal, incremental, this))
    {
      output->Initialize(); // aborted
      return 1;
    }
  }
  this->NumberOfNonManifoldFaces = topology.NonManifoldFaces;
  this->NumberOfFacesWithRepeatedPoints = topology.RepeatedPointFaces;
  this->NumberOfDegenerateFaces = topology.DegenerateFaces;
  if (topology.NonManifoldFaces && !this->TopologyReused)
  {
    vtkWarningMacro(<< topology.NonManifoldFaces
                    << " faces made an edge or a vertex non-manifold; each got its own copies "
                       "of its vertices (it keeps its own normals at those vertices).");
  }

  const FaceList& faces = topology.Faces;
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  const vtkIdType numberOfFaces = topology.NumberOfFaces();
  const vtkIdType numberOfVertices = static_cast<vtkIdType>(topology.VertexPoint.size());
  const vtkIdType numberOfCorners = static_cast<vtkIdType>(faces.Points.size());

  // Positions in double precision, into OpenMesh's point array.
  vtkPoints* inputPoints = input->GetPoints();
  vtkSMPTools::For(0, numberOfVertices,
    [&](vtkIdType begin, vtkIdType end)
    {
      double p[3];
      for (vtkIdType v = begin; v < end; ++v)
      {
        inputPoints->GetPoint(topology.VertexPoint[v], p);
        topology.Mesh.set_point(
          VertexHandle(static_cast<int>(v)), HalfedgeMesh::Point(p[0], p[1], p[2]));
      }
    });
  const double* positions = numberOfVertices > 0 ? topology.Mesh.points()[0].data() : nullptr;
  auto position = [&](vtkIdType corner) { return positions + 3 * topology.FaceVertex[corner]; };

  // Face normals by Newell's method about the first corner (twice the area
  // times the unit normal), and which faces are usable.
  // Each face's unit normal (sign applied below) and Newell length (twice the area).
  auto& faceLength = topology.FaceLength;
  Buffer<Vector>& unitNormal = topology.UnitNormal;
  unitNormal.resize(numberOfFaces);
  Buffer<char>& faceValid = topology.FaceValid;
  faceLength.resize(numberOfFaces);
  faceValid.resize(numberOfFaces);
  // For a triangle, the cross product of the two edges at any corner is the
  // face's Newell vector N, so every weighting is a number per corner times
  // the unit face normal: Uniform 1, Area |N|/2, Angle atan2(|N|, e1.e2),
  // Max |N| / (|e1|^2 |e2|^2). Polygons take the general path below.
  const int weighting = this->Weighting;
  const bool triangles = faces.AllTriangles;
  Buffer<float>& cornerWeight = topology.CornerWeight;
  cornerWeight.resize(triangles ? numberOfCorners : 0);
  vtkSMPTools::For(0, numberOfFaces,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (Index f = static_cast<Index>(begin); f < end; ++f)
      {
        const Index first = faces.Offsets[f], last = faces.Offsets[f + 1];
        const double* origin = position(first);
        Vector sum = { 0.0, 0.0, 0.0 };
        bool finite = IsFinite(origin);
        for (Index c = first + 1; c + 1 < last; ++c)
        {
          const double* a = position(c);
          const double* b = position(c + 1);
          finite = finite && IsFinite(a) && IsFinite(b);
          const Vector n = Cross(Subtract(a, origin), Subtract(b, origin));
          sum[0] += n[0];
          sum[1] += n[1];
          sum[2] += n[2];
        }
        const double length = std::sqrt(Dot(sum, sum));
        const bool valid = finite && length > 0.0 && std::isfinite(length);
        faceValid[f] = valid;
        faceLength[f] = length;
        const double scale = valid ? 1.0 / length : 0.0;
        unitNormal[f] = { scale * sum[0], scale * sum[1], scale * sum[2] };
        if (!triangles)
        {
          continue;
        }
        const double* p[3] = { position(first), position(first + 1), position(first + 2) };
        for (int k = 0; k < 3; ++k)
        {
          double weight = 0.0;
          if (valid)
          {
            const Vector e1 = Subtract(p[(k + 1) % 3], p[k]);
            const Vector e2 = Subtract(p[(k + 2) % 3], p[k]);
            switch (weighting)
            {
              case Uniform:
                weight = 1.0;
                break;
              case Area:
                weight = 0.5 * length;
                break;
              case Angle:
                weight = std::atan2(length, Dot(e1, e2));
                break;
              case Max:
              default:
                weight = length / (Dot(e1, e1) * Dot(e2, e2));
                break;
            }
            if (!std::isfinite(weight))
            {
              weight = 0.0;
            }
          }
          cornerWeight[first + k] = static_cast<float>(weight);
        }
      }
    });

  // Orientation of each piece: AutoOrientNormals turns closed pieces outward
  // (positive signed volume), FlipNormals reverses everything.
  const vtkIdType numberOfComponents = static_cast<vtkIdType>(topology.ComponentClosed.size());
  Buffer<signed char> componentSign(numberOfComponents, 1);
  if (this->AutoOrientNormals)
  {
    std::vector<double> volume(numberOfComponents, 0.0);
    for (vtkIdType f = 0; f < numberOfFaces; ++f)
    {
      const vtkIdType c = topology.FaceComponent[f];
      if (topology.ComponentClosed[c] && faceValid[f])
      {
        // The cone from the origin over a planar face has volume N.p0 / 6;
        // these add up to the piece's signed volume.
        const double* p = position(faces.Offsets[f]);
        volume[c] += faceLength[f] *
          (unitNormal[f][0] * p[0] + unitNormal[f][1] * p[1] + unitNormal[f][2] * p[2]) / 6.0;
      }
    }
    for (vtkIdType c = 0; c < numberOfComponents; ++c)
    {
      componentSign[c] = (topology.ComponentClosed[c] && volume[c] < 0.0) ? -1 : 1;
    }
  }
  const signed char flip = this->FlipNormals ? -1 : 1;
  Buffer<signed char>& faceSign = topology.FaceSign;
  faceSign.resize(numberOfFaces);
  vtkSMPTools::For(0, numberOfFaces,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        const signed char sign = componentSign[topology.FaceComponent[f]] * flip;
        faceSign[f] = sign;
        if (sign < 0)
        {
          unitNormal[f] = { -unitNormal[f][0], -unitNormal[f][1], -unitNormal[f][2] };
        }
      }
    });
  for (vtkIdType f = 0; f < numberOfFaces; ++f)
  {
    this->NumberOfReorientedFaces += (faceSign[f] < 0) != (topology.FaceReversed[f] != 0);
  }
  this->UpdateProgress(0.75);
  if (this->GetAbortExecute())
  {
    output->Initialize();
    return 1;
  }

  // The weighted contribution of a corner to its vertex's normal.
  auto contribution = [&](Index corner, Vector& sum)
  {
    const Index f = topology.CornerFace[corner];
    if (triangles)
    {
      const double weight = cornerWeight[corner];
      const Vector& n = unitNormal[f];
      sum[0] += weight * n[0];
      sum[1] += weight * n[1];
      sum[2] += weight * n[2];
      return;
    }
    if (!faceValid[f])
    {
      return; // degenerate or non-finite faces give nothing
    }
    const Vector& n = unitNormal[f];
    double weight = 1.0;
    if (weighting == Area)
    {
      weight = 0.5 * faceLength[f];
    }
    else if (weighting != Uniform)
    {
      const double* p = position(corner);
      const Vector e1 = Subtract(position(faces.Next(corner, f)), p);
      const Vector e2 = Subtract(position(faces.Previous(corner, f)), p);
      const Vector c = Cross(e1, e2);
      if (weighting == Angle)
      {
        weight = std::atan2(std::sqrt(Dot(c, c)), Dot(e1, e2));
      }
      else // Max: (e1 x e2) / (|e1|^2 |e2|^2), turned with the face
      {
        const double scale = Dot(e1, e1) * Dot(e2, e2);
        if (scale > 0.0 && std::isfinite(scale))
        {
          const double s = faceSign[f] / scale;
          sum[0] += s * c[0];
          sum[1] += s * c[1];
          sum[2] += s * c[2];
        }
        return;
      }
    }
    if (std::isfinite(weight))
    {
      sum[0] += weight * n[0];
      sum[1] += weight * n[1];
      sum[2] += weight * n[2];
    }
  };

  // Point normals, and the output point of each corner.
  const Buffer<Index>* cornerPoint = &faces.Points;
  Buffer<Index>& splitCornerPoint = topology.SplitCornerPoint;
  vtkSmartPointer<vtkFloatArray> pointNormals;
  Buffer<Index> splitSource; // the input point of each added point
  const bool splitting = this->Splitting && this->ComputePointNormals;
  bool sameConnectivity = false;
  if (this->ComputePointNormals && !splitting)
  {
    // One normal per input point, over every face around it.
    pointNormals = vtkSmartPointer<vtkFloatArray>::New();
    pointNormals->SetNumberOfComponents(3);
    pointNormals->SetNumberOfTuples(numberOfPoints);
    Buffer<Vector> sums(numberOfPoints, Vector{ 0.0, 0.0, 0.0 });
    for (vtkIdType c = 0; c < numberOfCorners; ++c)
    {
      contribution(c, sums[faces.Points[c]]);
    }
    vtkSMPTools::For(0, numberOfPoints,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType p = begin; p < end; ++p)
        {
          StoreNormal(sums[p], pointNormals->GetPointer(3 * p));
        }
      });
  }
  else if (splitting)
  {
    // Cut each fan at gaps and sharp edges into wedges; one output point per
    // wedge. The first wedge of a point's own vertex keeps the point's id.
    const double cosFeature = std::cos(vtkMath::RadiansFromDegrees(this->FeatureAngle));
    Buffer<char>& cuts = topology.Cuts;
    Buffer<Index>& wedgeCount = topology.WedgeCount;
    cuts.resize(topology.FanCorners.size());
    wedgeCount.resize(numberOfVertices);
    // A vertex of one wedge (most of them) is done in this first pass: its
    // normal goes to its point, its corners to its point id.
    Buffer<float>& singleNormal = topology.SingleNormal;
    singleNormal.resize(3 * static_cast<size_t>(numberOfVertices));
    splitCornerPoint.resize(numberOfCorners);
    vtkSMPTools::For(0, numberOfVertices,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (Index v = static_cast<Index>(begin); v < end; ++v)
        {
          const Index first = topology.FanOffsets[v], last = topology.FanOffsets[v + 1];
          Index count = 0;
          for (Index here = first; here < last; ++here)
          {
            const Index next = here + 1 < last ? here + 1 : first;
            bool cut = !topology.FanLinked[here];
            if (!cut)
            {
              const Index f = topology.FanFaces[here], g = topology.FanFaces[next];
              cut = faceValid[f] && faceValid[g] && Dot(unitNormal[f], unitNormal[g]) <= cosFeature;
            }
            cuts[here] = cut;
            count += cut;
          }
          wedgeCount[v] = first == last ? 0 : std::max<Index>(count, 1);
          if (wedgeCount[v] == 1 && !topology.VertexIsCopy[v])
          {
            Vector sum = { 0.0, 0.0, 0.0 };
            for (Index entry = first; entry < last; ++entry)
            {
              const Index corner = topology.FanCorners[entry];
              contribution(corner, sum);
              splitCornerPoint[corner] = topology.VertexPoint[v];
            }
            StoreNormal(sum, singleNormal.data() + 3 * static_cast<size_t>(v));
          }
        }
      });
    // Output ids: a point's own vertex keeps its id for its first wedge; the
    // other wedges and all wedges of copies are new points, in vertex order.
    Buffer<Index>& firstNewId = topology.FirstNewId;
    firstNewId.resize(numberOfVertices);
    Buffer<Index> multiWedge; // the vertices left for the second pass
    Index nextId = static_cast<Index>(numberOfPoints);
    for (Index v = 0; v < numberOfVertices; ++v)
    {
      firstNewId[v] = nextId;
      const bool copy = topology.VertexIsCopy[v] != 0;
      nextId += wedgeCount[v] - (wedgeCount[v] > 0 && !copy ? 1 : 0);
      if (wedgeCount[v] > 1 || (copy && wedgeCount[v] > 0))
      {
        multiWedge.push_back(v);
      }
    }
    const Index numberOfOutputPoints = nextId;
    this->NumberOfSplitPoints = numberOfOutputPoints - numberOfPoints;
    auto wedgeId = [&](Index v, Index wedge)
    {
      if (!topology.VertexIsCopy[v])
      {
        return wedge == 0 ? topology.VertexPoint[v] : firstNewId[v] + wedge - 1;
      }
      return firstNewId[v] + wedge;
    };

    pointNormals = vtkSmartPointer<vtkFloatArray>::New();
    pointNormals->SetNumberOfComponents(3);
    pointNormals->SetNumberOfTuples(numberOfOutputPoints);
    float* normals = pointNormals->GetPointer(0);
    // Points no face uses (isolated, or only in degenerate faces, verts, lines): +z.
    vtkSMPTools::For(0, numberOfPoints,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType p = begin; p < end; ++p)
        {
          normals[3 * p] = 0.f;
          normals[3 * p + 1] = 0.f;
          normals[3 * p + 2] = 1.f;
        }
      });
    vtkSMPTools::For(0, numberOfVertices,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (Index v = static_cast<Index>(begin); v < end; ++v)
        {
          if (wedgeCount[v] == 1 && !topology.VertexIsCopy[v])
          {
            std::copy_n(singleNormal.data() + 3 * static_cast<size_t>(v), 3,
              normals + 3 * static_cast<size_t>(topology.VertexPoint[v]));
          }
        }
      });
    // Vertices cut into several wedges, and copies: each wedge its point.
    vtkSMPTools::For(0, static_cast<vtkIdType>(multiWedge.size()),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const Index v = multiWedge[i];
          const Index first = topology.FanOffsets[v], last = topology.FanOffsets[v + 1];
          // Start right after a cut, so every wedge is one run of the fan.
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
              const Index id = wedgeId(v, wedge);
              StoreNormal(sum, normals + 3 * static_cast<size_t>(id));
              for (Index e = runStart;; e = e + 1 < last ? e + 1 : first)
              {
                splitCornerPoint[topology.FanCorners[e]] = id;
                if (e == entry)
                {
                  break;
                }
              }
              ++wedge;
              sum = { 0.0, 0.0, 0.0 };
              runStart = following;
            }
            entry = following;
          }
        }
      });
    // The same cuts and orientation as last time: the same output connectivity.
    sameConnectivity = topology.LastPolys && topology.LastCuts == cuts &&
      topology.LastCornerPoint.size() == static_cast<size_t>(numberOfCorners);
    if (sameConnectivity)
    {
      cornerPoint = &topology.LastCornerPoint;
      splitSource = topology.LastSplitSource;
    }
    else
    {
      splitSource.resize(numberOfOutputPoints - numberOfPoints);
      for (Index v : multiWedge)
      {
        const Index end = wedgeId(v, wedgeCount[v] - 1) + 1;
        for (Index id = firstNewId[v]; id < end; ++id)
        {
          splitSource[id - numberOfPoints] = topology.VertexPoint[v];
        }
      }
      cornerPoint = &splitCornerPoint;
    }
    topology.LastCuts = cuts;
  }
  this->UpdateProgress(0.9);
  if (this->GetAbortExecute())
  {
    output->Initialize();
    return 1;
  }

  // Output polygons: the input's polygons in order (degenerate ones as they
  // were), then the strips' triangles; each face in its final orientation.
  vtkCellArray* inputPolys = input->GetPolys();
  const vtkIdType numberOfPolys = inputPolys->GetNumberOfCells();
  const vtkIdType numberOfStripFaces = static_cast<vtkIdType>(topology.StripFaces.size());
  vtkSmartPointer<vtkCellArray> outputPolys;
  const bool signsUnchanged =
    std::all_of(faceSign.begin(), faceSign.end(), [](signed char sign) { return sign > 0; }) &&
    !this->AutoOrientNormals && !this->FlipNormals;
  if (sameConnectivity && signsUnchanged)
  {
    outputPolys = topology.LastPolys;
  }
  else
  {
    auto polyOffsets = vtkSmartPointer<vtkIdTypeArray>::New();
    polyOffsets->SetNumberOfTuples(numberOfPolys + numberOfStripFaces + 1);
    vtkIdType* offsets = polyOffsets->GetPointer(0);
    offsets[0] = 0;
    // Sizes first: a face's size, or a degenerate polygon's original size.
    std::vector<const vtkIdType*> degeneratePoints(numberOfPolys, nullptr);
    const bool everyPolygonIsAFace = std::none_of(
      topology.PolyFace.begin(), topology.PolyFace.end(), [](Index face) { return face < 0; });
    if (everyPolygonIsAFace)
    {
      for (vtkIdType poly = 0; poly < numberOfPolys; ++poly)
      {
        const Index f = topology.PolyFace[poly];
        offsets[poly + 1] = offsets[poly] + (faces.Offsets[f + 1] - faces.Offsets[f]);
      }
    }
    else
    {
      auto iterator = vtk::TakeSmartPointer(inputPolys->NewIterator());
      vtkIdType poly = 0;
      for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal();
           iterator->GoToNextCell(), ++poly)
      {
        const vtkIdType f = topology.PolyFace[poly];
        vtkIdType size = 0;
        if (f >= 0)
        {
          size = faces.Offsets[f + 1] - faces.Offsets[f];
        }
        else
        {
          iterator->GetCurrentCell(size, degeneratePoints[poly]);
        }
        offsets[poly + 1] = offsets[poly] + size;
      }
    }
    for (vtkIdType i = 0; i < numberOfStripFaces; ++i)
    {
      const vtkIdType f = topology.StripFaces[i];
      offsets[numberOfPolys + i + 1] =
        offsets[numberOfPolys + i] + faces.Offsets[f + 1] - faces.Offsets[f];
    }
    auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
    connectivity->SetNumberOfTuples(offsets[numberOfPolys + numberOfStripFaces]);
    vtkIdType* ids = connectivity->GetPointer(0);
    const Buffer<Index>& pointOfCorner = *cornerPoint;
    auto writeFace = [&](vtkIdType f, vtkIdType* out)
    {
      const vtkIdType first = faces.Offsets[f], size = faces.Offsets[f + 1] - first;
      for (vtkIdType k = 0; k < size; ++k)
      {
        // A reversed face: (p0, p1, ..., pn-1) written as (p0, pn-1, ..., p1).
        const vtkIdType i = faceSign[f] > 0 ? k : (k == 0 ? 0 : size - k);
        out[k] = pointOfCorner[first + i];
      }
    };
    vtkSMPTools::For(0, numberOfPolys,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType poly = begin; poly < end; ++poly)
        {
          const vtkIdType f = topology.PolyFace[poly];
          if (f >= 0)
          {
            writeFace(f, ids + offsets[poly]);
          }
          else
          {
            std::copy(degeneratePoints[poly],
              degeneratePoints[poly] + (offsets[poly + 1] - offsets[poly]), ids + offsets[poly]);
          }
        }
      });
    vtkSMPTools::For(0, numberOfStripFaces,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          writeFace(topology.StripFaces[i], ids + offsets[numberOfPolys + i]);
        }
      });
    outputPolys = vtkSmartPointer<vtkCellArray>::New();
    outputPolys->SetData(polyOffsets, connectivity);
    if (splitting && signsUnchanged)
    {
      topology.LastPolys = outputPolys;
      topology.LastSplitSource = splitSource;
      topology.LastCornerPoint = *cornerPoint;
    }
    else
    {
      topology.LastPolys = nullptr;
    }
  }

  // Points: the input's, then the split copies (with their point data).
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  if (splitSource.empty())
  {
    output->SetPoints(inputPoints);
    outPD->CopyNormalsOff();
    outPD->PassData(inPD);
  }
  else
  {
    const vtkIdType added = static_cast<vtkIdType>(splitSource.size());
    vtkNew<vtkIdList> sources;
    vtkNew<vtkIdList> destinations;
    sources->SetNumberOfIds(added);
    destinations->SetNumberOfIds(added);
    for (vtkIdType i = 0; i < added; ++i)
    {
      sources->SetId(i, splitSource[i]);
      destinations->SetId(i, numberOfPoints + i);
    }
    vtkNew<vtkPoints> points;
    points->SetDataType(inputPoints->GetDataType());
    points->DeepCopy(inputPoints);
    points->GetData()->InsertTuples(destinations, sources, inputPoints->GetData());
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
      copy->InsertTuples(destinations, sources, source);
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
  if (pointNormals)
  {
    pointNormals->SetName("Normals");
    outPD->SetNormals(pointNormals);
  }
  if (splitting)
  {
    vtkNew<vtkIdTypeArray> originalIds;
    originalIds->SetName(
      this->OriginalPointIdsArrayName ? this->OriginalPointIdsArrayName : "vtkOriginalPointIds");
    const vtkIdType total = output->GetNumberOfPoints();
    originalIds->SetNumberOfTuples(total);
    vtkIdType* original = originalIds->GetPointer(0);
    for (vtkIdType p = 0; p < numberOfPoints; ++p)
    {
      original[p] = p;
    }
    std::copy(splitSource.begin(), splitSource.end(), original + numberOfPoints);
    outPD->AddArray(originalIds);
  }

  // Cells: vertices and lines as they were, then the polygons.
  output->SetVerts(input->GetVerts());
  output->SetLines(input->GetLines());
  output->SetPolys(outputPolys);
  const vtkIdType cellsBeforePolys = input->GetNumberOfVerts() + input->GetNumberOfLines();
  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = output->GetCellData();
  if (input->GetNumberOfStrips() == 0)
  {
    outCD->CopyNormalsOff();
    outCD->PassData(inCD);
  }
  else
  {
    // Strips became triangles: each carries its strip's cell data.
    const vtkIdType total = cellsBeforePolys + numberOfPolys + numberOfStripFaces;
    vtkNew<vtkIdList> sources;
    vtkNew<vtkIdList> destinations;
    sources->SetNumberOfIds(total);
    destinations->SetNumberOfIds(total);
    for (vtkIdType c = 0; c < cellsBeforePolys + numberOfPolys; ++c)
    {
      sources->SetId(c, c);
    }
    for (vtkIdType i = 0; i < numberOfStripFaces; ++i)
    {
      sources->SetId(
        cellsBeforePolys + numberOfPolys + i, topology.FaceCell[topology.StripFaces[i]]);
    }
    for (vtkIdType c = 0; c < total; ++c)
    {
      destinations->SetId(c, c);
    }
    outCD->CopyNormalsOff();
    outCD->CopyAllocate(inCD, total);
    outCD->CopyData(inCD, sources, destinations);
  }
  if (this->ComputeCellNormals)
  {
    vtkNew<vtkFloatArray> cellNormals;
    cellNormals->SetName("Normals");
    cellNormals->SetNumberOfComponents(3);
    const vtkIdType total = output->GetNumberOfCells();
    cellNormals->SetNumberOfTuples(total);
    const Vector up = { 0.0, 0.0, 1.0 };
    for (vtkIdType c = 0; c < total; ++c)
    {
      StoreNormal(up, cellNormals->GetPointer(3 * c));
    }
    for (vtkIdType poly = 0; poly < numberOfPolys; ++poly)
    {
      const vtkIdType f = topology.PolyFace[poly];
      if (f >= 0)
      {
        StoreNormal(unitNormal[f], cellNormals->GetPointer(3 * (cellsBeforePolys + poly)));
      }
    }
    for (vtkIdType i = 0; i < numberOfStripFaces; ++i)
    {
      StoreNormal(unitNormal[topology.StripFaces[i]],
        cellNormals->GetPointer(3 * (cellsBeforePolys + numberOfPolys + i)));
    }
    outCD->SetNormals(cellNormals);
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormals::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Weighting: " << this->GetWeightingAsString() << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "Splitting: " << (this->Splitting ? "On" : "Off") << "\n";
  os << indent << "Consistency: " << (this->Consistency ? "On" : "Off") << "\n";
  os << indent << "AutoOrientNormals: " << (this->AutoOrientNormals ? "On" : "Off") << "\n";
  os << indent << "ComputePointNormals: " << (this->ComputePointNormals ? "On" : "Off") << "\n";
  os << indent << "ComputeCellNormals: " << (this->ComputeCellNormals ? "On" : "Off") << "\n";
  os << indent << "FlipNormals: " << (this->FlipNormals ? "On" : "Off") << "\n";
  os << indent << "NonManifoldTraversal: " << (this->NonManifoldTraversal ? "On" : "Off") << "\n";
  os << indent << "IncrementalConstruction: " << (this->IncrementalConstruction ? "On" : "Off")
     << "\n";
  os << indent << "OriginalPointIdsArrayName: "
     << (this->OriginalPointIdsArrayName ? this->OriginalPointIdsArrayName : "(none)") << "\n";
  os << indent << "NumberOfNonManifoldFaces: " << this->NumberOfNonManifoldFaces << "\n";
  os << indent << "NumberOfFacesWithRepeatedPoints: " << this->NumberOfFacesWithRepeatedPoints
     << "\n";
  os << indent << "NumberOfDegenerateFaces: " << this->NumberOfDegenerateFaces << "\n";
  os << indent << "NumberOfReorientedFaces: " << this->NumberOfReorientedFaces << "\n";
  os << indent << "NumberOfSplitPoints: " << this->NumberOfSplitPoints << "\n";
  os << indent << "TopologyReused: " << (this->TopologyReused ? "yes" : "no") << "\n";
}
