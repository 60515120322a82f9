/**
 * @class   vtkOpenMeshNormalsTopology
 * @brief   what vtkOpenMeshNormals derives from the connectivity alone (private)
 *
 * The faces in their consistent orientation, the connected pieces, OpenMesh's
 * halfedge mesh and the fan of faces around each vertex: everything that does
 * not depend on where the points are. vtkOpenMeshNormals keeps one between
 * executions and rebuilds it only when Matches() says that the polygons, the
 * strips or the settings that shape it changed, so that an animation (only
 * the points move) pays for it once.
 *
 * Build() runs steps 1-5 of docs/normals.md ("How it uses OpenMesh"): read
 * the faces, find each corner's twin, orient, load the halfedge mesh, read
 * the fans. Its data members are public: vtkOpenMeshNormalsExecution reads
 * them to compute the normals.
 *
 * Neither wrapped nor installed, so OpenMesh's types stay inside the module.
 *
 * @sa vtkOpenMeshNormals vtkOpenMeshNormalsExecution
 */

#ifndef vtkOpenMeshNormalsTopology_h
#define vtkOpenMeshNormalsTopology_h

#include "vtkOpenMeshNormalsBuffers.h"
#include "vtkType.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

class vtkOpenMeshNormals;
class vtkCellArray;
class vtkPolyData;

namespace vtkOpenMeshNormalsDetail
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

// Which cells something was computed from: the polygon and strip arrays (the same objects,
// unmodified since) and the number of points. The same stamp again means that only the
// points may have moved.
struct CellsStamp
{
  vtkCellArray* Polys = nullptr;
  vtkMTimeType PolysTime = 0;
  vtkCellArray* Strips = nullptr;
  vtkMTimeType StripsTime = 0;
  vtkIdType NumberOfPoints = -1;

  void Record(vtkPolyData* input);
  bool Matches(vtkPolyData* input) const;
};

// How often long serial loops look at AbortExecute.
constexpr Index AbortCheckInterval = 1 << 16;

// The twin of a corner: the corner, in the face across the corner's outgoing
// edge (from its point to the next corner's), that holds the same edge.
// Boundary and non-manifold edges have none.
constexpr Index NoTwin = -1;
constexpr Index NonManifoldEdge = -2;

// The corners at each point, as compressed rows: built while the topology is,
// then dropped.
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
  Index NumberOfPoints() const { return static_cast<Index>(this->Offsets.size()) - 1; }
};
}

class vtkOpenMeshNormalsTopology : public vtkOpenMeshNormalsTypes
{
public:
  using FaceList = vtkOpenMeshNormalsDetail::FaceList;
  using HalfedgeMesh = vtkOpenMeshNormalsDetail::HalfedgeMesh;
  using PointCorners = vtkOpenMeshNormalsDetail::PointCorners;

  /**
   * Whether this topology was built from the input's current polygons and
   * strips (the same arrays, unmodified), for as many points, with the same
   * settings: then only the geometry needs computing.
   */
  bool Matches(vtkPolyData* input, bool consistency, bool traversal, bool incremental,
    bool halfedgeMesh) const;

  /**
   * Builds everything from the input's polygons and strips. consistency:
   * orient each connected piece; traversal: cross non-manifold edges while
   * orienting; incremental: load every face through OpenMesh's add_face;
   * halfedgeMesh: build OpenMesh's halfedge mesh also when every face is
   * regular (else such a mesh gets its fans straight from the twins).
   * Reports progress (0.1 to 0.7) and errors through the filter; returns
   * false when the mesh is too large for 32-bit handles or the filter was
   * aborted.
   */
  bool Build(vtkPolyData* input, bool consistency, bool traversal, bool incremental,
    bool halfedgeMesh, vtkOpenMeshNormals* filter);

  Index NumberOfFaces() const { return this->Faces.Size(); }

  // Faces: polygons with at least three distinct points, in input order
  // (polygons, then the strips' triangles), each in its consistent
  // orientation.
  FaceList Faces;
  Buffer<Index> CornerFace;     // the face of each corner
  Buffer<Index> FaceVertex;     // the OpenMesh vertex of each corner
  Buffer<Index> FaceCell;       // the input cell each face comes from
  Buffer<char> FaceReversed;    // Consistency reversed the input order
  Buffer<Index> FaceComponent;  // the connected piece of each face
  Buffer<char> ComponentClosed; // per piece: no boundary, and orientable
  Buffer<Index> PolyFace;       // each input polygon's face, -1 if degenerate
  Buffer<Index> StripFaces;     // the faces from triangle strips, in order

  // OpenMesh's halfedge mesh, built where some face is irregular (or when
  // asked for): then it holds the vertices' positions. A mesh of regular faces
  // only skips it (HasHalfedgeMesh false) and keeps them in VertexPositions.
  HalfedgeMesh Mesh;
  bool HasHalfedgeMesh = false;
  Buffer<double> VertexPositions; // x, y, z per vertex, without a halfedge mesh
  Buffer<Index> VertexPoint;      // the input point of each OpenMesh vertex
  Buffer<char> VertexIsCopy;      // a copy made for a face OpenMesh refused
  Buffer<Index> MeshFace;         // the face of each OpenMesh face (unless the identity)
  bool MeshFaceIsIdentity = false;

  // The fan of each OpenMesh vertex in circulation order: corners, and
  // whether a corner shares an edge with the next one.
  Buffer<Index> FanOffsets;
  Buffer<Index> FanCorners;
  Buffer<Index> FanFaces; // the face of each fan corner
  Buffer<char> FanLinked;

  vtkIdType NonManifoldFaces = 0;
  vtkIdType RepeatedPointFaces = 0;
  vtkIdType DegenerateFaces = 0;
  vtkIdType IrregularFaces = 0; // loaded through OpenMesh's add_face

private:
  // Step 1: read the faces.
  void ReadFaces(vtkPolyData* input);
  template <typename Id>
  void ReadTriangles(const Id* connectivity, Index numberOfPolys, Index cellsBeforePolys);
  template <typename Id>
  void ReadPolygons(
    const Id* offsets, const Id* connectivity, Index numberOfPolys, Index cellsBeforePolys);
  template <typename Id>
  void ReadStrips(
    const Id* offsets, const Id* connectivity, Index numberOfStrips, Index cellsBeforeStrips);
  template <typename Iterator>
  bool AppendFace(Iterator begin, Iterator end, Index cell);
  void AssignCornerFaces();

  // Step 2: find twins.
  Buffer<Index> FindTwins(const PointCorners& around, Buffer<char>& sameDirection) const;

  // Step 3: orient.
  bool OrientFaces(PointCorners& around, Buffer<Index>& twins, Buffer<char>& sameDirection,
    bool consistency, bool traversal, vtkOpenMeshNormals* filter);
  void Reverse(
    const Buffer<signed char>& orientation, Buffer<Index>& twins, Buffer<char>& sameDirection);
  void ReverseCornersAround(const Buffer<signed char>& orientation, PointCorners& around) const;

  // Step 4: load the halfedge mesh (in vtkOpenMeshNormalsHalfedgeMesh.cxx).
  Buffer<char> FindIrregularFaces(const PointCorners& around, const Buffer<Index>& twins,
    const Buffer<char>& sameDirection) const;
  bool LoadMesh(const PointCorners& around, const Buffer<Index>& twins,
    const Buffer<char>& irregular, vtkOpenMeshNormals* filter);

  // Step 5: read the fans.
  void ReadFans();
  void FillFan(Index vertex);

  // Steps 4-5 without a halfedge mesh (in vtkOpenMeshNormalsDirectFans.cxx):
  // the vertices, then each fan walked across the twins in the order
  // OpenMesh's circulation would give. False, with nothing to keep, where
  // some face is not regular (an edge not shared by two opposite faces, a
  // point of several fans): such a mesh needs the halfedge mesh.
  bool ReadFansFromTwins(
    const PointCorners& around, const Buffer<Index>& twins, const Buffer<char>& sameDirection);
  void NumberVerticesDirectly(const PointCorners& around);
  bool FillFanFromTwins(Index vertex, const PointCorners& around, const Buffer<Index>& twins);

  // What the topology was built from.
  vtkOpenMeshNormalsDetail::CellsStamp Cells;
  bool Consistency = false;
  bool NonManifoldTraversal = false;
  bool Incremental = false;
  bool AlwaysHalfedgeMesh = false;
  bool Valid = false;
};

#endif
