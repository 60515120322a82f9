/**
 * @class   vtkOpenMeshNormals
 * @brief   point and cell normals on OpenMesh's halfedge structure: exact, robust, fast
 *
 * vtkOpenMeshNormals computes normals for polygonal meshes like vtkPolyDataNormals, whose
 * settings it mirrors (FeatureAngle, Splitting, Consistency, AutoOrientNormals,
 * ComputePointNormals, ComputeCellNormals, FlipNormals, NonManifoldTraversal), so it can
 * replace it in a pipeline. It adds the choice of vertex weighting, each the textbook
 * definition, in double precision:
 *
 * - Uniform (Gouraud 1971): the mean of the unit normals of the faces around the vertex;
 * - Area: the face normals weighted by the face areas;
 * - Angle (Thurmer and Wuthrich 1998): weighted by the face's angle at the vertex;
 * - Max (Max 1999): the sum over the corners at the vertex of
 *   (e1 x e2) / (|e1|^2 |e2|^2), e1 and e2 the corner's two edges; exact for vertices of a
 *   triangulated sphere. For a polygon's corner the same formula uses its two edges.
 *
 * The default, Max, is the most accurate on the meshes measured in docs/normals.md.
 *
 * The mesh is first oriented consistently (Consistency), across each connected piece,
 * keeping the orientation of the majority of its faces (not that of cell 0); closed pieces
 * are then turned outward with AutoOrientNormals. The oriented faces are loaded into an
 * OpenMesh polygonal mesh; around each vertex, its fan of faces is cut at boundaries and,
 * with Splitting, at sharp edges (dihedral angle above FeatureAngle). Each piece of fan gets
 * its own normal and output point: split points are appended after the input's points, and
 * the array named by OriginalPointIdsArrayName ("vtkOriginalPointIds") maps every output
 * point back to its input point.
 *
 * Input people really have:
 * - polygons of any size (face normals by Newell's method), triangle strips (output as
 *   triangles, cell data copied), vertices and lines (passed through);
 * - a face repeating a vertex index: the repeats are removed (OpenMesh refuses such faces);
 *   a face left with fewer than three vertices is kept in the output but has no normal;
 * - non-manifold edges and vertices, which OpenMesh's halfedge structure refuses: such a
 *   face gets its own copies of its vertices (as OpenMesh's own importer does) and is kept;
 *   GetNumberOfNonManifoldFaces() counts them and a warning reports them;
 * - zero-area faces and faces with a NaN or infinite vertex contribute nothing to their
 *   neighbours' normals;
 * - isolated points, points of degenerate faces only, and empty input.
 * Output normals are always finite and unit length. Where no normal is defined (a point no
 * valid face touches, a degenerate face) the normal is (0, 0, 1).
 *
 * A smooth, consistently oriented triangle mesh (the common input of a renderer) is computed
 * point by point, in bounded memory, without the topology (PointByPoint). When only the
 * points move (the input's polygons and strips are the same arrays, unmodified, with the
 * same number of points: an animation, a deformation), the topology (orientation, halfedge
 * mesh, vertex fans) is built once and reused, and only the geometry is recomputed.
 *
 * @sa vtkPolyDataNormals vtkPhongPolyDataMapper
 */

#ifndef vtkOpenMeshNormals_h
#define vtkOpenMeshNormals_h

#include "vtkFiltersOpenMeshModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

class VTKFILTERSOPENMESH_EXPORT vtkOpenMeshNormals : public vtkPolyDataAlgorithm
{
public:
  static vtkOpenMeshNormals* New();
  vtkTypeMacro(vtkOpenMeshNormals, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * How the normals of the faces around a vertex are combined.
   */
  enum Weightings
  {
    Uniform = 0,
    Area = 1,
    Angle = 2,
    Max = 3
  };

  ///@{
  /**
   * The vertex weighting. Default Max (see the class documentation); one of Uniform, Area,
   * Angle, Max (values are clamped).
   */
  vtkSetClampMacro(Weighting, int, Uniform, Max);
  vtkGetMacro(Weighting, int);
  void SetWeightingToUniform() { this->SetWeighting(Uniform); }
  void SetWeightingToArea() { this->SetWeighting(Area); }
  void SetWeightingToAngle() { this->SetWeighting(Angle); }
  void SetWeightingToMax() { this->SetWeighting(Max); }
  const char* GetWeightingAsString();
  ///@}

  ///@{
  /**
   * The angle in degrees between two faces above which their shared edge is sharp. Default
   * 30 (as vtkPolyDataNormals), range [0, 180]; NaN is refused with an error.
   */
  virtual void SetFeatureAngle(double angle);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /**
   * Split points along sharp edges so each side gets its own normal. Default on.
   */
  vtkSetMacro(Splitting, vtkTypeBool);
  vtkGetMacro(Splitting, vtkTypeBool);
  vtkBooleanMacro(Splitting, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Orient the faces of each connected piece consistently (reordering their points), keeping
   * the orientation most of the piece's faces already have. Default on.
   */
  vtkSetMacro(Consistency, vtkTypeBool);
  vtkGetMacro(Consistency, vtkTypeBool);
  vtkBooleanMacro(Consistency, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Turn each closed piece so its normals point outward (its signed volume is positive);
   * implies Consistency. Open pieces keep their consistent orientation. Default off.
   */
  vtkSetMacro(AutoOrientNormals, vtkTypeBool);
  vtkGetMacro(AutoOrientNormals, vtkTypeBool);
  vtkBooleanMacro(AutoOrientNormals, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Output point normals. Default on.
   */
  vtkSetMacro(ComputePointNormals, vtkTypeBool);
  vtkGetMacro(ComputePointNormals, vtkTypeBool);
  vtkBooleanMacro(ComputePointNormals, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Output cell normals (unit Newell normals of the polygons; (0, 0, 1) for vertex and line
   * cells and degenerate faces). Default off.
   */
  vtkSetMacro(ComputeCellNormals, vtkTypeBool);
  vtkGetMacro(ComputeCellNormals, vtkTypeBool);
  vtkBooleanMacro(ComputeCellNormals, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Reverse every normal and the order of every polygon's points. Default off.
   */
  vtkSetMacro(FlipNormals, vtkTypeBool);
  vtkGetMacro(FlipNormals, vtkTypeBool);
  vtkBooleanMacro(FlipNormals, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Let Consistency cross non-manifold edges (edges with more than two faces), orienting
   * every face on such an edge against the face it was reached from. Default on (as
   * vtkPolyDataNormals).
   */
  vtkSetMacro(NonManifoldTraversal, vtkTypeBool);
  vtkGetMacro(NonManifoldTraversal, vtkTypeBool);
  vtkBooleanMacro(NonManifoldTraversal, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Measurement and testing only (the output is the same either way): load every face into
   * OpenMesh with PolyConnectivity::add_face, one by one. By default
   * faces whose edges and points are regular (two opposite faces per interior edge, one fan
   * per point) are linked directly into OpenMesh's kernel, which gives the same halfedge
   * structure without add_face's searches, and only the others go through add_face. Default
   * off; the tests use it to check both constructions give the same normals.
   */
  vtkSetMacro(IncrementalConstruction, vtkTypeBool);
  vtkGetMacro(IncrementalConstruction, vtkTypeBool);
  vtkBooleanMacro(IncrementalConstruction, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Measurement and testing only (the output is the same either way): build OpenMesh's
   * halfedge mesh also for a mesh whose faces are all regular (two opposite
   * faces per interior edge, one fan per point). By default such a mesh skips it: the fan of
   * faces around each point is walked across the corners' twins, which gives the fans
   * OpenMesh's circulation would, in the same order, without the halfedge mesh's memory.
   * Meshes with any other face always go through OpenMesh. Default off; the tests use it to
   * check both paths give identical output.
   */
  vtkSetMacro(AlwaysHalfedgeMesh, vtkTypeBool);
  vtkGetMacro(AlwaysHalfedgeMesh, vtkTypeBool);
  vtkBooleanMacro(AlwaysHalfedgeMesh, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Compute, where the mesh allows, one point at a time in bounded memory, without building
   * the topology: a triangle mesh (no strips) whose every point has one fan of faces,
   * consistently oriented, and, with Splitting, no sharp edge and no cone's apex in it. The
   * output is the same, bit for bit; the memory is the normals (and original point ids),
   * 4 bytes a point and at most 64 MB of corners, instead of the topology's (about 170 bytes
   * a triangle, kept between executions). The first point that needs the topology (a face to
   * turn, a non-manifold edge or vertex, a repeated vertex index, a point to split) sends the
   * mesh to it. Not taken with ComputeCellNormals, AutoOrientNormals, FlipNormals,
   * IncrementalConstruction or AlwaysHalfedgeMesh. A positions-only update after a point by
   * point execution (the same cell arrays, unmodified, and as many points: an animation)
   * builds the topology and keeps it, so that the updates after it reuse it, several times
   * faster. Off: the topology is always built and kept. Default on.
   */
  vtkSetMacro(PointByPoint, vtkTypeBool);
  vtkGetMacro(PointByPoint, vtkTypeBool);
  vtkBooleanMacro(PointByPoint, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Whether the copies of one point are one vertex for the point normals. Pieces of one
   * surface (ParaView's ranks, a source's pieces, appended blocks) each hold their own copy of
   * the points on their cuts; joined, they get the normals of the whole surface, without a
   * seam. Copies are the points that share a global id (the input's point data GlobalIds),
   * or, when the input has none, points within JoinTolerance of each other. The output keeps
   * every copy as its own point, with its own point data (texture coordinates on either side
   * of a texture seam stay apart); a copy whose corners got different normals is copied again,
   * as split points are. Default off (VTK's filters treat every point as its own vertex).
   */
  vtkSetMacro(JoinCoincidentPoints, vtkTypeBool);
  vtkGetMacro(JoinCoincidentPoints, vtkTypeBool);
  vtkBooleanMacro(JoinCoincidentPoints, vtkTypeBool);
  ///@}

  ///@{
  /**
   * How close two points without global ids must be to be copies of one point
   * (JoinCoincidentPoints), as a fraction of the input's bounding-box diagonal. Default 1e-6
   * (pieces of a source compute the same point by different sums, a few float steps apart);
   * range 0 (the same coordinates only) to 1e-3.
   */
  vtkSetClampMacro(JoinTolerance, double, 0.0, 1e-3);
  vtkGetMacro(JoinTolerance, double);
  ///@}

  ///@{
  /**
   * The name of the output point array giving each output point's input point id, written
   * when Splitting is on. Default "vtkOriginalPointIds", which null also gives.
   */
  vtkSetStringMacro(OriginalPointIdsArrayName);
  vtkGetStringMacro(OriginalPointIdsArrayName);
  ///@}

  ///@{
  /**
   * What the last execution found: cells (of any kind) that named a point the input does not
   * have, collapsed and reported with a warning (vtkPhongCellValidator), faces given their own
   * vertex copies because OpenMesh refused them (non-manifold), faces that repeated a vertex index,
   * faces left with fewer than three distinct vertices, faces whose orientation Consistency or
   * AutoOrientNormals reversed, points added by Splitting (or by JoinCoincidentPoints), points
   * joined to another as its copy, and whether the topology of the previous
   * execution was reused (only the points had changed), and whether the normals were computed
   * point by point, without the topology (PointByPoint).
   */
  vtkGetMacro(NumberOfInvalidCells, vtkIdType);
  vtkGetMacro(NumberOfNonManifoldFaces, vtkIdType);
  vtkGetMacro(NumberOfFacesWithRepeatedPoints, vtkIdType);
  vtkGetMacro(NumberOfDegenerateFaces, vtkIdType);
  vtkGetMacro(NumberOfReorientedFaces, vtkIdType);
  vtkGetMacro(NumberOfSplitPoints, vtkIdType);
  vtkGetMacro(NumberOfJoinedPoints, vtkIdType);
  vtkGetMacro(TopologyReused, bool);
  vtkGetMacro(ComputedPointByPoint, bool);
  ///@}

protected:
  vtkOpenMeshNormals();
  ~vtkOpenMeshNormals() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Weighting = Max;
  double FeatureAngle = 30.0;
  vtkTypeBool Splitting = 1;
  vtkTypeBool Consistency = 1;
  vtkTypeBool AutoOrientNormals = 0;
  vtkTypeBool ComputePointNormals = 1;
  vtkTypeBool ComputeCellNormals = 0;
  vtkTypeBool FlipNormals = 0;
  vtkTypeBool NonManifoldTraversal = 1;
  vtkTypeBool IncrementalConstruction = 0;
  vtkTypeBool AlwaysHalfedgeMesh = 0;
  vtkTypeBool PointByPoint = 1;
  vtkTypeBool JoinCoincidentPoints = 0;
  double JoinTolerance = 1e-6;
  char* OriginalPointIdsArrayName = nullptr;

  vtkIdType NumberOfInvalidCells = 0;
  vtkIdType NumberOfNonManifoldFaces = 0;
  vtkIdType NumberOfFacesWithRepeatedPoints = 0;
  vtkIdType NumberOfDegenerateFaces = 0;
  vtkIdType NumberOfReorientedFaces = 0;
  vtkIdType NumberOfSplitPoints = 0;
  vtkIdType NumberOfJoinedPoints = 0;
  bool TopologyReused = false;
  bool ComputedPointByPoint = false;

private:
  vtkOpenMeshNormals(const vtkOpenMeshNormals&) = delete;
  void operator=(const vtkOpenMeshNormals&) = delete;

  // OriginalPointIdsArrayName, or "vtkOriginalPointIds" when it is null: split points always
  // get their array (the joined normals read it back).
  const char* OriginalIdsName() const;
  // The input with its cells that name missing points collapsed (and reported).
  vtkSmartPointer<vtkPolyData> CheckCellPointIds(vtkPolyData* input);
  // The normals of an input whose cells are checked; false if aborted.
  bool ComputeNormals(vtkPolyData* input, vtkPolyData* output);
  // The same with the copies of each point joined (JoinCoincidentPoints).
  bool ComputeJoinedNormals(
    vtkPolyData* input, const std::vector<vtkIdType>& representative, vtkPolyData* output);
  // Whether the settings and the input allow vtkOpenMeshNormalsPointByPoint, and this is not
  // a positions-only update (which reuses a kept topology, or builds one for the next).
  bool MayComputePointByPoint(vtkPolyData* input) const;
  // Reuses the topology (vtkOpenMeshNormalsTopology) or builds it.
  bool UpdateTopology(vtkPolyData* input);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
