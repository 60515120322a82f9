/**
 * @class   vtkOpenMeshNormalsExecution
 * @brief   the steps of one vtkOpenMeshNormals execution, on a ready topology (private)
 *
 * vtkOpenMeshNormals::RequestData builds or reuses the topology
 * (vtkOpenMeshNormalsTopology), then calls these steps in the order they are
 * declared: step 6 of docs/normals.md, the part that runs again when only
 * the points move. Each step reads what the earlier ones left in the
 * workspace or in this object.
 *
 * The loops over corners are compiled once per vertex weighting (the
 * functors of vtkOpenMeshNormalsWeightings.h), so that the weighting is not
 * decided again at every corner.
 *
 * Neither wrapped nor installed.
 *
 * @sa vtkOpenMeshNormals vtkOpenMeshNormalsTopology vtkOpenMeshNormalsWorkspace
 */

#ifndef vtkOpenMeshNormalsExecution_h
#define vtkOpenMeshNormalsExecution_h

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkOpenMeshNormalsBuffers.h"
#include "vtkSmartPointer.h"

class vtkIdList;

namespace vtkOpenMeshNormalsDetail
{
struct FaceNormal;
}
class vtkOpenMeshNormalsTopology;
class vtkPolyData;

/**
 * The arrays of vtkOpenMeshNormals' executions. They outlive an execution so
 * that repeated updates (an animation) reuse their memory instead of
 * allocating and page-faulting it again. The Last members remember the
 * previous output's connectivity: a positions-only update that cuts the fans
 * at the same places reuses it.
 */
struct vtkOpenMeshNormalsWorkspace : public vtkOpenMeshNormalsTypes
{
  // Per face.
  Buffer<Vector> UnitNormal;    // in the output's orientation
  Buffer<double> FaceLength;    // the Newell vector's length: twice the area
  Buffer<char> FaceValid;       // finite, with a nonzero area
  Buffer<signed char> FaceSign; // -1 where AutoOrientNormals or FlipNormals turned it

  // Per corner.
  Buffer<float> CornerWeight;     // triangles only: weight times unit normal is the contribution
  Buffer<Index> SplitCornerPoint; // the output point of each corner

  // Per fan entry and per vertex.
  Buffer<char> Cuts;          // the fan is cut after this entry
  Buffer<Index> WedgeCount;   // the pieces of each vertex's fan
  Buffer<float> SingleNormal; // the normal of a vertex of one wedge
  Buffer<Index> FirstNewId;   // the first added output point of each vertex

  // The last output.
  Buffer<char> LastCuts;
  vtkSmartPointer<vtkCellArray> LastPolys;
  Buffer<Index> LastSplitSource;
  Buffer<Index> LastCornerPoint;
};

class vtkOpenMeshNormalsExecution : public vtkOpenMeshNormalsTypes
{
public:
  /**
   * The filter's settings this execution needs.
   */
  struct Settings
  {
    int Weighting;       // vtkOpenMeshNormals::Weightings
    double FeatureAngle; // degrees
    bool Splitting;      // Splitting with ComputePointNormals
    bool ComputeCellNormals;
    bool AutoOrientNormals;
    bool FlipNormals;
    const char* OriginalPointIdsArrayName; // not null
  };

  vtkOpenMeshNormalsExecution(const Settings& settings, vtkOpenMeshNormalsTopology& topology,
    vtkOpenMeshNormalsWorkspace& workspace, vtkPolyData* input, vtkPolyData* output);

  /**
   * The input's points, in double precision, into OpenMesh's point array.
   */
  void LoadPositions();

  /**
   * Each face's Newell normal and whether it is usable; for triangles, in the
   * same pass (their points are then in cache), the corners' weights.
   */
  void ComputeFaceNormals();

  /**
   * Turns closed pieces outward (AutoOrientNormals) and everything with
   * FlipNormals; returns the number of faces whose output orientation
   * differs from the input's.
   */
  vtkIdType OrientComponents();

  /**
   * Without splitting: one normal per input point, over all its faces.
   */
  void ComputeSharedPointNormals();

  ///@{
  /**
   * With splitting: cut each vertex's fan at gaps and sharp edges into
   * wedges (storing the normal of the vertices of one wedge on the way),
   * number the wedges' output points (returns the number of added points),
   * store the other wedges' normals, and find where the added points come
   * from (reusing the last output's numbering when the cuts did not change).
   */
  void CutFans();
  vtkIdType NumberWedges();
  void StoreWedgeNormals();
  void FindSplitSources();
  ///@}

  /**
   * The output polygons: the input's polygons in order (degenerate ones as
   * they were), then the strips' triangles, each in its final orientation.
   */
  void BuildOutputPolys();

  /**
   * The output points (the split points with copies of their point data),
   * the point normals and the original point ids.
   */
  void WritePoints();

  /**
   * The output cells and cell data (the strips' triangles carry their
   * strip's), and the cell normals.
   */
  void WriteCells();

  ///@{
  /**
   * The output's points and point data: the input's, then a copy of each input point
   * `copies` names, every array but the normals keeping its attribute role (without copies,
   * the input's own arrays); then the array named `idsName` giving each output point's input
   * point. Split points use them, and so do the copies of joined points
   * (vtkOpenMeshNormalsJoin).
   */
  static void WritePointsWithCopies(vtkPolyData* input, vtkIdList* copies, vtkPolyData* output);
  static void StoreOriginalPointIds(
    vtkPolyData* output, const char* idsName, vtkIdType inputPoints, vtkIdList* copies);
  ///@}

private:
  const double* Position(Index corner) const;
  Index WedgeId(Index vertex, Index wedge) const;

  template <typename Weighting>
  void ComputeFaceNormal(Index face);
  template <typename Weighting>
  void StoreTriangleCornerWeights(Index first, const vtkOpenMeshNormalsDetail::FaceNormal& face);
  Buffer<signed char> ComputeComponentSigns() const;
  void ApplyFaceSigns(const Buffer<signed char>& componentSign);
  template <typename Contribution>
  void SumSharedPointNormals(const Contribution& contribution);
  template <typename Contribution>
  void CutFan(Index vertex, const Contribution& contribution);
  bool IsSingularFan(Index first, Index last) const;
  template <typename Contribution>
  void StoreSingleWedgeNormal(Index vertex, const Contribution& contribution);
  void CopySingleWedgeNormals(float* normals) const;
  template <typename Contribution>
  void StoreWedgeNormalsOf(Index vertex, const Contribution& contribution, float* normals);
  void AssignWedgeCorners(Index vertex, Index runStart, Index runEnd, Index id);
  vtkSmartPointer<vtkCellArray> NewOutputPolys() const;
  bool OutputPolysAreInputPolys(bool signsUnchanged) const;
  void CountPolygonSizes(vtkIdType* offsets, std::vector<vtkIdType>& degenerateIds,
    std::vector<vtkIdType>& degenerateFirst) const;
  void WriteFace(vtkIdType face, vtkIdType* out) const;
  void CopyCellData();
  void StoreCellNormals();

  const Settings Options;
  const double CosFeatureAngle;
  vtkOpenMeshNormalsTopology& Topology;
  vtkOpenMeshNormalsWorkspace& Workspace;
  vtkPolyData* const Input;
  vtkPolyData* const Output;
  const vtkIdType NumberOfPoints;
  const vtkIdType NumberOfFaces;
  const vtkIdType NumberOfVertices;
  const vtkIdType NumberOfCorners;
  const vtkIdType NumberOfPolys;
  const vtkIdType NumberOfStripFaces;
  const bool Triangles; // every face is a triangle
  const double* Positions = nullptr;

  // What the steps pass on.
  vtkSmartPointer<vtkFloatArray> PointNormals;
  Buffer<Index> MultiWedge; // the vertices of several wedges, and the copies
  Index NumberOfOutputPoints = 0;
  const Buffer<Index>* CornerPoint; // the output point of each corner
  Buffer<Index> SplitSource;        // the input point of each added point
  bool SameConnectivity = false;    // the last output's cuts: its polygons may be reused
  vtkSmartPointer<vtkCellArray> OutputPolys;
};

#endif
