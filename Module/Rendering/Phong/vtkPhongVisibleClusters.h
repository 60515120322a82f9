/**
 * @class   vtkPhongVisibleClusters
 * @brief   the depth pre-pass draws only the triangles seen in the last frames (private)
 *
 * The depth pass of vtkPhongDepthPrePass only has to leave, at each pixel, a depth no nearer
 * than the nearest surface there: any subset of the triangles will do, because the lit draw
 * that follows draws them all with VTK's GL_LEQUAL test. On llvmpipe the depth pass costs
 * mostly per triangle, so in a deep scene (nested contours) drawing the hidden layers into
 * it costs about as much as the pre-pass saves.
 *
 * This class cuts a mapper's triangles into up to MaximumClusters spatially compact
 * clusters (a copy of VTK's triangle index buffer, reordered) and keeps the depth pass to
 * the clusters seen:
 * - The depth pass draws the seen clusters, each counted by a GL_SAMPLES_PASSED query every
 *   RecountInterval frames: first those not counted this frame (in runs, a draw each), then
 *   the counted ones nearest first. A cluster none of whose fragments passed the depth test
 *   is hidden behind the ones drawn before it, and is left out from the next frame on.
 * - Each frame it also draws, last and counted, a share (1/RetestInterval) of the hidden
 *   clusters, so that a cluster that comes into view is back within RetestInterval frames.
 * - The counts are read a frame later, never waited for.
 *
 * Bounding boxes tested against the depth buffer were tried first and dropped: boxes around
 * patches of closely nested contours reach through the contour in front, and on llvmpipe
 * rasterizing them costs more than the triangles they save. Counting the real triangles
 * where they are drawn anyway is exact and costs a query per cluster.
 *
 * A hidden cluster that comes into view costs frames of overdraw, never a wrong pixel.
 */

#ifndef vtkPhongVisibleClusters_h
#define vtkPhongVisibleClusters_h

#include "vtkBoundingBox.h" // for vtkBoundingBox
#include "vtkNew.h"         // for vtkNew
#include "vtkType.h"        // for vtkMTimeType

#include <cstddef> // for size_t
#include <cstdint> // for std::uint32_t
#include <memory>  // for std::unique_ptr
#include <vector>  // for std::vector

class vtkActor;
class vtkMapper;
class vtkOpenGLHelper;
class vtkOpenGLIndexBufferObject;
class vtkPolyData;
class vtkRenderer;
class vtkWindow;

class vtkPhongVisibleClusters
{
public:
  vtkPhongVisibleClusters();
  ~vtkPhongVisibleClusters();
  vtkPhongVisibleClusters(const vtkPhongVisibleClusters&) = delete;
  vtkPhongVisibleClusters& operator=(const vtkPhongVisibleClusters&) = delete;

  /**
   * Whether the clusters were made from the index buffer `triangles` as built at `builtAt`,
   * in `window`: then Update reads nothing of its `input`.
   */
  bool IsCurrent(
    vtkWindow* window, vtkOpenGLIndexBufferObject* triangles, vtkMTimeType builtAt) const;

  /**
   * Make the clusters of the triangles VTK's index buffer `triangles` draws (indices into the
   * points of `input`), when the buffer was rebuilt since (`builtAt`, VTK's VBOBuildTime).
   * Returns false, and the depth pass should draw everything, when the buffer's indices do
   * not name `input`'s points. Call with the window's context current.
   */
  bool Update(vtkWindow* window, vtkOpenGLIndexBufferObject* triangles, vtkPolyData* input,
    vtkMTimeType builtAt);

  /**
   * Read the last frame's counts when the GPU has them; returns how many triangles the next
   * Draw draws (0 before the first Update).
   */
  double CollectVisibility();

  /**
   * The depth pass's triangles: the seen clusters nearest first, then this frame's share of
   * the hidden ones, with the program and vertex array already bound.
   */
  void Draw(vtkRenderer* ren, vtkActor* act);

  ///@{
  /// The clusters' triangles, and those the last Draw drew.
  double GetNumberOfTriangles() const { return this->Triangles; }
  double GetNumberOfTrianglesDrawn() const { return this->TrianglesDrawn; }
  ///@}

  void ReleaseGraphicsResources(vtkWindow* window);

  /**
   * Whether a mapper's depth pass may be cut to the clusters: it draws triangles alone (no
   * points, lines or strips in the same pass; `primitives`: its
   * vtkOpenGLPolyDataMapper::Primitives), as a surface from the renderer's camera (a render
   * pass may draw the actor from a light's view: vtkPhongDepthPrePass::CanMeasure), into the
   * picture's depth buffer (no selection).
   */
  static bool CanCull(
    vtkRenderer* ren, vtkActor* act, vtkMapper* mapper, const vtkOpenGLHelper* primitives);

  /**
   * Each triangle's connected component (triangles sharing a point), numbered in order of
   * first appearance. Also used by vtkPhongClosedSurface.
   */
  static std::vector<std::uint32_t> ConnectedComponents(
    const std::vector<unsigned int>& indices, vtkPolyData* input);

  /**
   * The indices of VTK's triangle index buffer exactly as it uploaded them (polygons
   * triangulated, invalid cells collapsed); false when there are none. Also used by
   * vtkPhongClosedSurface.
   */
  static bool ReadIndices(
    vtkOpenGLIndexBufferObject* triangles, std::vector<unsigned int>& indices);

  /**
   * Whether VTK's triangle index buffer holds whole triangles to read (ReadIndices is false
   * where it does not).
   */
  static bool HoldsTriangles(vtkOpenGLIndexBufferObject* triangles);

  /**
   * `indices.size()` of those indices from the `first` on, which the buffer holds: a block
   * of them, for a pass that needs no copy of all.
   */
  static void ReadIndices(
    vtkOpenGLIndexBufferObject* triangles, size_t first, std::vector<unsigned int>& indices);

  ///@{
  /**
   * At most MaximumClusters clusters of at least MinimumClusterTriangles triangles. A hidden
   * cluster is drawn again every RetestInterval frames to see whether it came into view; a
   * seen one is counted every RecountInterval frames to see whether it went out of view.
   */
  static constexpr int MaximumClusters = 256;
  static constexpr int MinimumClusterTriangles = 256;
  static constexpr int RetestInterval = 32;
  static constexpr int RecountInterval = 4;
  ///@}

private:
  struct Cluster
  {
    size_t Group = 0; // its connected component, or run of small ones (GroupBoxes)
    vtkIdType FirstIndex = 0;
    vtkIdType IndexCount = 0;
    unsigned int FirstVertex = 0; // the range of vertices its triangles use
    unsigned int LastVertex = 0;
    vtkBoundingBox Box; // around its finite points
    bool Seen = true;
    bool Counted = false; // drawn with a query not read yet
  };

  void Arrange(const std::vector<unsigned int>& indices, vtkPolyData* input); // no GL
  void Install();                                                             // GL
  void ArrangeInBackground(std::vector<unsigned int> indices, vtkPolyData* input);
  void CollectBackground();
  void Split(std::vector<std::uint32_t>& order, const std::vector<double>& centroids, size_t first,
    size_t last, size_t target);
  static std::vector<double> Centroids(
    const std::vector<unsigned int>& indices, vtkPolyData* input);
  void ComputeBounds(const std::vector<unsigned int>& sorted, vtkPolyData* input);
  std::vector<size_t> DrawOrder(vtkRenderer* ren, vtkActor* act);
  void DrawUncountedRuns(const std::vector<bool>& counted);
  void DrawCluster(size_t k); // counted
  void Reset();

  std::vector<Cluster> Clusters;
  std::vector<unsigned int> Sorted; // the triangles in cluster order, until uploaded
  struct Background;                // clusters arranged on a thread of their own
  std::unique_ptr<Background> Pending;
  // Each group's box: a group's clusters are drawn together, nearest group first.
  std::vector<vtkBoundingBox> GroupBoxes;
  vtkNew<vtkOpenGLIndexBufferObject> SortedTriangles;
  std::vector<unsigned int> Queries; // one per cluster
  bool Counting = false;             // queries were issued and not read yet
  bool CountAll = false;             // the next draw counts every cluster (just built)
  size_t NextRetest = 0;             // where the hidden clusters' round robin goes on
  size_t Frame = 0;                  // depth passes drawn, for the seen clusters' recounts
  vtkMTimeType BuiltAt = 0;
  size_t IndexCount = 0;
  vtkWindow* Window = nullptr;
  double Triangles = 0.0;
  double TrianglesDrawn = 0.0;
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongVisibleClusters.h
