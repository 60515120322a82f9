// Steps 4-5 of vtkOpenMeshNormalsTopology::Build for a mesh whose faces are
// all regular (two opposite faces per interior edge, one fan per point): the
// fans come straight from the corners' twins, without OpenMesh's halfedge
// mesh. For a million triangles that mesh is about 66 MB that a fresh filter
// would have to first-touch and link, only to be circulated once. Meshes with
// any irregular face keep going through OpenMesh (HalfedgeMesh.cxx), where
// add_face and the vertex copies need its halfedge structure.
//
// The fans are those OpenMesh's circulation gives, corner for corner and in
// the same order, so the output does not depend on the path taken
// (vtkOpenMeshNormals::AlwaysHalfedgeMesh builds the mesh anyway; the tests
// compare both). With HalfedgeMeshLoader's linking, a vertex's circulation
// starts at its outgoing boundary halfedge if it has one (then the first face
// corner is the one whose outgoing edge has no twin), else at the outgoing
// halfedge of the last corner in the point-to-corner index; from a corner c
// it moves to the twin of c's previous corner (the opposite of the halfedge
// before c's).

#include "vtkOpenMeshNormalsTopology.h"

#include "vtkSMPTools.h"

#include <atomic>

using namespace vtkOpenMeshNormalsDetail;

//------------------------------------------------------------------------------
// One vertex for every point some face uses, in point order (as
// HalfedgeMeshLoader numbers them), and each corner's vertex.
void vtkOpenMeshNormalsTopology::NumberVerticesDirectly(const PointCorners& around)
{
  const Index numberOfPoints = around.NumberOfPoints();
  Buffer<Index> vertexOfPoint(numberOfPoints);
  this->VertexPoint.clear();
  for (Index p = 0; p < numberOfPoints; ++p)
  {
    const bool used = around.Offsets[p + 1] > around.Offsets[p];
    vertexOfPoint[p] = used ? static_cast<Index>(this->VertexPoint.size()) : -1;
    if (used)
    {
      this->VertexPoint.push_back(p);
    }
  }
  this->VertexIsCopy.assign(this->VertexPoint.size(), 0);
  this->FaceVertex.resize(this->Faces.Points.size()); // every corner written below
  vtkSMPTools::For(0, static_cast<Index>(this->Faces.Points.size()),
    [&](Index begin, Index end)
    {
      for (Index c = begin; c < end; ++c)
      {
        this->FaceVertex[c] = vertexOfPoint[this->Faces.Points[c]];
      }
    });
  this->Mesh.clear();
  this->MeshFace.clear();
  this->MeshFaceIsIdentity = true;
  this->IrregularFaces = 0;
}

//------------------------------------------------------------------------------
// Every corner at a point is in its fan, so the fans' slots are the
// point-to-corner index's rows (points without corners have no vertex). The
// walks themselves check that each point has one fan, which is what
// IrregularFaceFinder would check for the halfedge path.
bool vtkOpenMeshNormalsTopology::ReadFansFromTwins(
  const PointCorners& around, const Buffer<Index>& twins, const Buffer<char>& sameDirection)
{
  std::atomic<bool> regular(true);
  vtkSMPTools::For(0, static_cast<Index>(twins.size()),
    [&](Index begin, Index end)
    {
      for (Index c = begin; c < end && regular; ++c)
      {
        if (twins[c] == NonManifoldEdge || (twins[c] >= 0 && sameDirection[c]))
        {
          regular = false;
        }
      }
    });
  if (!regular)
  {
    return false;
  }
  this->NumberVerticesDirectly(around);
  const Index numberOfVertices = static_cast<Index>(this->VertexPoint.size());
  this->FanOffsets.resize(numberOfVertices + 1);
  this->FanOffsets[0] = 0;
  for (Index v = 0; v < numberOfVertices; ++v)
  {
    const Index p = this->VertexPoint[v];
    this->FanOffsets[v + 1] = this->FanOffsets[v] + around.Offsets[p + 1] - around.Offsets[p];
  }
  const Index numberOfFanCorners = this->FanOffsets.back();
  this->FanCorners.resize(numberOfFanCorners);
  this->FanFaces.resize(numberOfFanCorners);
  this->FanLinked.resize(numberOfFanCorners);
  vtkSMPTools::For(0, numberOfVertices,
    [&](Index begin, Index end)
    {
      for (Index v = begin; v < end && regular; ++v)
      {
        if (!this->FillFanFromTwins(v, around, twins))
        {
          regular = false;
        }
      }
    });
  return regular;
}

//------------------------------------------------------------------------------
// Vertex v's fan into its slots, in circulation order; an open fan (a
// boundary vertex) has its last corner unlinked. False if the walk does not
// reach every corner at the point (it has several fans).
bool vtkOpenMeshNormalsTopology::FillFanFromTwins(
  Index v, const PointCorners& around, const Buffer<Index>& twins)
{
  const Index p = this->VertexPoint[v];
  const Index first = around.Offsets[p], last = around.Offsets[p + 1];
  Index start = around.Corners[last - 1];
  for (Index i = first; i < last; ++i)
  {
    if (twins[around.Corners[i]] < 0) // its outgoing edge is on the boundary
    {
      start = around.Corners[i];
      break;
    }
  }
  const Index end = this->FanOffsets[v + 1];
  Index slot = this->FanOffsets[v];
  Index c = start;
  bool open = false;
  while (slot < end)
  {
    const Index f = this->CornerFace[c];
    this->FanCorners[slot] = c;
    this->FanFaces[slot] = f;
    this->FanLinked[slot] = 1;
    ++slot;
    c = twins[this->Faces.Previous(c, f)];
    if (c < 0)
    {
      open = true;
      break;
    }
    if (c == start)
    {
      break;
    }
  }
  if (open)
  {
    this->FanLinked[slot - 1] = 0;
  }
  return slot == end && (open || c == start);
}
