// Step 4 of vtkOpenMeshNormalsTopology::Build: loading the faces into
// OpenMesh's halfedge mesh. Most faces are linked straight into OpenMesh's
// kernel, in parallel; the few that need add_face's checks are found first.

#include "vtkOpenMeshNormalsTopology.h"

#include "vtkOpenMeshNormals.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>

using namespace vtkOpenMeshNormalsDetail;

namespace
{
//------------------------------------------------------------------------------
// The faces the direct construction leaves to OpenMesh's add_face: those on a
// non-manifold or inconsistent edge, and every face around a point whose
// other faces do not make one fan (one cycle or one open chain).
class IrregularFaceFinder
{
public:
  IrregularFaceFinder(const vtkOpenMeshNormalsTopology& topology, const PointCorners& around,
    const Buffer<Index>& twins, const Buffer<char>& sameDirection)
    : Faces(topology.Faces)
    , CornerFace(topology.CornerFace)
    , Around(around)
    , Twins(twins)
    , SameDirection(sameDirection)
  {
  }

  Buffer<char> Find()
  {
    this->MarkFacesOnIrregularEdges();
    this->Spread(this->FindPointsOfSeveralFans());
    return std::move(this->Irregular);
  }

private:
  void MarkFacesOnIrregularEdges()
  {
    const Index numberOfFaces = this->Faces.Size();
    this->Irregular.assign(numberOfFaces, 0);
    vtkSMPTools::For(0, numberOfFaces,
      [&](Index begin, Index end)
      {
        for (Index f = begin; f < end; ++f)
        {
          for (Index c = this->Faces.Offsets[f]; c < this->Faces.Offsets[f + 1]; ++c)
          {
            if (this->Twins[c] == NonManifoldEdge ||
              (this->Twins[c] >= 0 && this->SameDirection[c]))
            {
              this->Irregular[f] = 1;
            }
          }
        }
      });
  }

  // The points whose regular faces make more than one fan.
  Buffer<Index> FindPointsOfSeveralFans() const
  {
    const Index numberOfPoints = this->Around.NumberOfPoints();
    Buffer<char> pointRegular(numberOfPoints, 1);
    std::atomic<bool> anyIrregular(false);
    vtkSMPTools::For(0, numberOfPoints,
      [&](Index begin, Index end)
      {
        for (Index p = begin; p < end; ++p)
        {
          if (!this->OneFan(p))
          {
            pointRegular[p] = 0;
            anyIrregular = true;
          }
        }
      });
    Buffer<Index> points;
    if (!anyIrregular)
    {
      return points;
    }
    for (Index p = 0; p < numberOfPoints; ++p)
    {
      if (!pointRegular[p])
      {
        points.push_back(p);
      }
    }
    return points;
  }

  // Rarely needed: an irregular point's faces go to add_face, which can
  // leave the regular faces around their other points in several fans.
  void Spread(Buffer<Index> work)
  {
    while (!work.empty())
    {
      Buffer<Index> touched;
      for (Index p : work)
      {
        for (Index i = this->Around.Offsets[p]; i < this->Around.Offsets[p + 1]; ++i)
        {
          const Index f = this->CornerFace[this->Around.Corners[i]];
          if (!this->Irregular[f])
          {
            this->Irregular[f] = 1;
            touched.insert(touched.end(), this->Faces.Points.begin() + this->Faces.Offsets[f],
              this->Faces.Points.begin() + this->Faces.Offsets[f + 1]);
          }
        }
      }
      std::sort(touched.begin(), touched.end());
      touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
      work.clear();
      for (Index p : touched)
      {
        if (!this->OneFan(p))
        {
          work.push_back(p);
        }
      }
    }
  }

  // Around a point, from the corner c of a regular face: the next corner
  // (across c's outgoing edge), or -1 at a gap.
  Index NextAround(Index c) const
  {
    const Index twin = this->Twins[c];
    if (twin < 0 || this->Irregular[this->CornerFace[twin]])
    {
      return -1;
    }
    return this->Faces.Next(twin, this->CornerFace[twin]);
  }

  // The previous corner (across c's incoming edge), or -1 at a gap.
  Index PreviousAround(Index c) const
  {
    const Index twin = this->Twins[this->Faces.Previous(c, this->CornerFace[c])];
    return (twin < 0 || this->Irregular[this->CornerFace[twin]]) ? -1 : twin;
  }

  // Whether the regular faces around point p make (at most) one fan.
  bool OneFan(Index p) const
  {
    Index count = 0, starts = 0, start = -1;
    for (Index i = this->Around.Offsets[p]; i < this->Around.Offsets[p + 1]; ++i)
    {
      const Index c = this->Around.Corners[i];
      if (this->Irregular[this->CornerFace[c]])
      {
        continue;
      }
      ++count;
      if (this->PreviousAround(c) < 0)
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
    for (Index c = this->NextAround(start); c >= 0 && c != start && visited <= count;
         c = this->NextAround(c))
    {
      ++visited;
    }
    return visited == count;
  }

  const FaceList& Faces;
  const Buffer<Index>& CornerFace;
  const PointCorners& Around;
  const Buffer<Index>& Twins;
  const Buffer<char>& SameDirection;
  Buffer<char> Irregular;
};

//------------------------------------------------------------------------------
// Loads the faces into OpenMesh. Regular faces are written straight into
// OpenMesh's kernel, in parallel, in the state add_face would leave them in;
// the others go through add_face, and a face it refuses gets its own copies
// of its vertices, as OpenMesh's importer does.
class HalfedgeMeshLoader
{
public:
  HalfedgeMeshLoader(vtkOpenMeshNormalsTopology& topology, const PointCorners& around,
    const Buffer<Index>& twins, const Buffer<char>& irregular)
    : Topology(topology)
    , Faces(topology.Faces)
    , Mesh(topology.Mesh)
    , Around(around)
    , Twins(twins)
    , Irregular(irregular)
    , AllRegular(std::find(irregular.begin(), irregular.end(), 1) == irregular.end())
  {
  }

  // False if the filter was aborted.
  bool Load(vtkOpenMeshNormals* filter)
  {
    this->Mesh.clear();
    this->NumberVertices();
    this->NumberRegularFaces();
    const Index numberOfEdges = this->NumberHalfedges();
    this->Mesh.resize(static_cast<Index>(this->Topology.VertexPoint.size()), numberOfEdges,
      this->NumberOfRegularFaces);
    this->Topology.FaceVertex.resize(this->Faces.Points.size()); // every corner written below
    vtkSMPTools::For(0, this->Faces.Size(),
      [&](Index begin, Index end)
      {
        for (Index f = begin; f < end; ++f)
        {
          this->LinkRegularFace(f);
        }
      });
    vtkSMPTools::For(0, this->Around.NumberOfPoints(),
      [&](Index begin, Index end)
      {
        for (Index p = begin; p < end; ++p)
        {
          this->LinkVertex(p);
        }
      });
    this->Topology.IrregularFaces = this->Faces.Size() - this->NumberOfRegularFaces;
    if (this->Topology.IrregularFaces > 0)
    {
      this->AddIrregularFaces(filter);
    }
    return !filter->GetAbortExecute();
  }

private:
  // One vertex for every point some face uses, in point order.
  void NumberVertices()
  {
    const Index numberOfPoints = this->Around.NumberOfPoints();
    this->VertexOfPoint.assign(numberOfPoints, -1);
    this->Topology.VertexPoint.clear();
    for (Index p = 0; p < numberOfPoints; ++p)
    {
      if (this->Around.Offsets[p + 1] > this->Around.Offsets[p])
      {
        this->VertexOfPoint[p] = static_cast<Index>(this->Topology.VertexPoint.size());
        this->Topology.VertexPoint.push_back(p);
      }
    }
    this->Topology.VertexIsCopy.assign(this->Topology.VertexPoint.size(), 0);
  }

  // Regular faces first: OpenMesh face i is the i-th regular face. With every
  // face regular OpenMesh's faces are the filter's, in order, and MeshFace is
  // not written.
  void NumberRegularFaces()
  {
    const Index numberOfFaces = this->Faces.Size();
    this->Topology.MeshFace.clear();
    this->Topology.MeshFaceIsIdentity = this->AllRegular;
    if (!this->AllRegular)
    {
      this->MeshFaceOf.assign(numberOfFaces, -1);
      for (Index f = 0; f < numberOfFaces; ++f)
      {
        if (!this->Irregular[f])
        {
          this->MeshFaceOf[f] = static_cast<Index>(this->Topology.MeshFace.size());
          this->Topology.MeshFace.push_back(f);
        }
      }
    }
    this->NumberOfRegularFaces =
      this->AllRegular ? numberOfFaces : static_cast<Index>(this->Topology.MeshFace.size());
  }

  // Halfedge ids: a corner owning its edge takes halfedge 2e (its own
  // direction), its twin 2e + 1. A regular corner owns its edge unless its
  // twin is an earlier regular corner. Owners are counted per face in
  // parallel and numbered in face order. Returns the number of edges.
  Index NumberHalfedges()
  {
    const Index numberOfFaces = this->Faces.Size();
    this->HalfedgeOfCorner.assign(this->Faces.Points.size(), -1);
    Buffer<Index> firstEdge(numberOfFaces + 1, 0);
    vtkSMPTools::For(0, numberOfFaces,
      [&](Index begin, Index end)
      {
        for (Index f = begin; f < end; ++f)
        {
          firstEdge[f + 1] = this->Irregular[f] ? 0 : this->CountOwnedEdges(f);
        }
      });
    for (Index f = 0; f < numberOfFaces; ++f)
    {
      firstEdge[f + 1] += firstEdge[f];
    }
    vtkSMPTools::For(0, numberOfFaces,
      [&](Index begin, Index end)
      {
        for (Index f = begin; f < end; ++f)
        {
          this->NumberOwnedHalfedges(f, firstEdge[f]);
        }
      });
    vtkSMPTools::For(0, static_cast<Index>(this->Faces.Points.size()),
      [&](Index begin, Index end)
      {
        for (Index c = begin; c < end; ++c)
        {
          if (this->HalfedgeOfCorner[c] < 0 && !this->Irregular[this->Topology.CornerFace[c]])
          {
            this->HalfedgeOfCorner[c] = this->HalfedgeOfCorner[this->RegularTwin(c)] + 1;
          }
        }
      });
    return firstEdge[numberOfFaces];
  }

  Index CountOwnedEdges(Index f) const
  {
    Index count = 0;
    for (Index c = this->Faces.Offsets[f]; c < this->Faces.Offsets[f + 1]; ++c)
    {
      count += this->Owns(c);
    }
    return count;
  }

  void NumberOwnedHalfedges(Index f, Index edge)
  {
    if (this->Irregular[f])
    {
      return;
    }
    for (Index c = this->Faces.Offsets[f]; c < this->Faces.Offsets[f + 1]; ++c)
    {
      if (this->Owns(c))
      {
        this->HalfedgeOfCorner[c] = 2 * edge++;
      }
    }
  }

  // A regular face's halfedges, written into the kernel.
  void LinkRegularFace(Index f)
  {
    if (this->Irregular[f])
    {
      return;
    }
    HalfedgeMesh& mesh = this->Mesh;
    const FaceHandle face(this->AllRegular ? f : this->MeshFaceOf[f]);
    for (Index c = this->Faces.Offsets[f]; c < this->Faces.Offsets[f + 1]; ++c)
    {
      const Index next = this->Faces.Next(c, f);
      const HalfedgeHandle h(this->HalfedgeOfCorner[c]);
      const VertexHandle vertex(this->VertexOfPoint[this->Faces.Points[c]]);
      this->Topology.FaceVertex[c] = vertex.idx();
      // Each halfedge gets its vertex from the corner it belongs to; a
      // boundary halfedge (the owner's opposite, no twin) from its owner.
      mesh.set_vertex_handle(h, VertexHandle(this->VertexOfPoint[this->Faces.Points[next]]));
      if (this->RegularTwin(c) == NoTwin)
      {
        mesh.set_vertex_handle(mesh.opposite_halfedge_handle(h), vertex);
      }
      mesh.set_next_halfedge_handle(h, HalfedgeHandle(this->HalfedgeOfCorner[next]));
      mesh.set_face_handle(h, face);
    }
    mesh.set_halfedge_handle(face, HalfedgeHandle(this->HalfedgeOfCorner[this->Faces.Offsets[f]]));
  }

  // Point p's outgoing halfedge, and at its one gap (if any) the incoming
  // boundary halfedge continuing with the outgoing one, as add_face links them.
  void LinkVertex(Index p)
  {
    Index anyOutgoing = -1, incomingBoundary = -1, outgoingBoundary = -1;
    for (Index i = this->Around.Offsets[p]; i < this->Around.Offsets[p + 1]; ++i)
    {
      const Index c = this->Around.Corners[i];
      const Index f = this->Topology.CornerFace[c];
      if (this->Irregular[f])
      {
        continue;
      }
      anyOutgoing = this->HalfedgeOfCorner[c];
      if (this->RegularTwin(c) == NoTwin) // c's edge p -> next has nothing across
      {
        incomingBoundary = this->HalfedgeOfCorner[c] ^ 1;
      }
      const Index previous = this->Faces.Previous(c, f);
      if (this->RegularTwin(previous) == NoTwin) // previous -> p has nothing across
      {
        outgoingBoundary = this->HalfedgeOfCorner[previous] ^ 1;
      }
    }
    if (anyOutgoing < 0)
    {
      return;
    }
    const VertexHandle vertex(this->VertexOfPoint[p]);
    if (outgoingBoundary >= 0)
    {
      this->Mesh.set_next_halfedge_handle(
        HalfedgeHandle(incomingBoundary), HalfedgeHandle(outgoingBoundary));
      this->Mesh.set_halfedge_handle(vertex, HalfedgeHandle(outgoingBoundary));
    }
    else
    {
      this->Mesh.set_halfedge_handle(vertex, HalfedgeHandle(anyOutgoing));
    }
  }

  // Irregular faces through add_face; a refused face gets fresh vertices.
  void AddIrregularFaces(vtkOpenMeshNormals* filter)
  {
    OpenMesh::mostream& errors = omerr(); // OpenMesh declares it globally
    const bool errorsWereOn = errors.is_enabled();
    errors.disable(); // the refusals are expected, counted and reported once
    std::vector<VertexHandle> handles;
    for (Index f = 0; f < this->Faces.Size(); ++f)
    {
      if (!this->Irregular[f])
      {
        continue;
      }
      this->AddIrregularFace(f, handles);
      if (f % AbortCheckInterval == 0 && filter->GetAbortExecute())
      {
        break;
      }
    }
    if (errorsWereOn)
    {
      errors.enable();
    }
  }

  void AddIrregularFace(Index f, std::vector<VertexHandle>& handles)
  {
    vtkOpenMeshNormalsTopology& topology = this->Topology;
    const Index first = this->Faces.Offsets[f], size = this->Faces.Offsets[f + 1] - first;
    handles.resize(size);
    for (Index k = 0; k < size; ++k)
    {
      handles[k] = VertexHandle(this->VertexOfPoint[this->Faces.Points[first + k]]);
    }
    if (!this->Mesh.add_face(handles).is_valid())
    {
      ++topology.NonManifoldFaces;
      for (Index k = 0; k < size; ++k)
      {
        handles[k] = this->Mesh.new_vertex();
        topology.VertexPoint.push_back(this->Faces.Points[first + k]);
        topology.VertexIsCopy.push_back(1);
      }
      this->Mesh.add_face(handles); // a face on fresh vertices cannot be refused
    }
    topology.MeshFace.push_back(f);
    for (Index k = 0; k < size; ++k)
    {
      topology.FaceVertex[first + k] = handles[k].idx();
    }
  }

  // The twin of corner c if it is a regular face's, else NoTwin.
  Index RegularTwin(Index c) const
  {
    const Index twin = this->Twins[c];
    if (this->AllRegular)
    {
      return twin >= 0 ? twin : NoTwin;
    }
    return (twin >= 0 && !this->Irregular[this->Topology.CornerFace[twin]]) ? twin : NoTwin;
  }

  bool Owns(Index c) const
  {
    const Index twin = this->RegularTwin(c);
    return twin == NoTwin || c < twin;
  }

  vtkOpenMeshNormalsTopology& Topology;
  const FaceList& Faces;
  HalfedgeMesh& Mesh;
  const PointCorners& Around;
  const Buffer<Index>& Twins;
  const Buffer<char>& Irregular;
  const bool AllRegular;
  Index NumberOfRegularFaces = 0;
  Buffer<Index> VertexOfPoint;
  Buffer<Index> MeshFaceOf; // the OpenMesh face of each face (unless the identity)
  Buffer<Index> HalfedgeOfCorner;
};
}

//------------------------------------------------------------------------------
vtkOpenMeshNormalsTopology::Buffer<char> vtkOpenMeshNormalsTopology::FindIrregularFaces(
  const PointCorners& around, const Buffer<Index>& twins, const Buffer<char>& sameDirection) const
{
  return IrregularFaceFinder(*this, around, twins, sameDirection).Find();
}

//------------------------------------------------------------------------------
bool vtkOpenMeshNormalsTopology::LoadMesh(const PointCorners& around, const Buffer<Index>& twins,
  const Buffer<char>& irregular, vtkOpenMeshNormals* filter)
{
  return HalfedgeMeshLoader(*this, around, twins, irregular).Load(filter);
}
