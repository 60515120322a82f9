/**
 * @class   vtkPhongDepthPrePass
 * @brief   when vtkPhongPolyDataMapper's automatic depth pre-pass pays (private)
 *
 * The pre-pass draws the geometry once with a program that computes no light (colour writes
 * off), so that the lit draw that follows, with VTK's GL_LEQUAL test, shades each pixel once.
 * It saves the lighting of every hidden layer and costs about one unlit draw. Whether that
 * pays depends on how many of the fragments a plain draw would shade end up hidden, which
 * only the GPU knows: this class counts them (GL_SAMPLES_PASSED queries around the draws).
 *
 * - A plain draw counts the fragments it shades (Shaded).
 * - A draw with the pre-pass counts the fragments its lit draw shades (Visible); its depth
 *   pass leaves back faces out, so it does not count what a plain draw would shade.
 *
 * Automatic mode draws plainly first, then probes one frame with the pre-pass, then uses it
 * while the lighting of the hidden fragments (Shaded - Visible) costs more than the depth
 * pass over the geometry, under the lights the lit program evaluates (Pays(); the cost model
 * was measured on llvmpipe, docs/results/performance.md, "Depth complexity"). Each mode
 * counts one of the two numbers; the other is refreshed by one frame in the other mode when
 * the one counted moves by a quarter (the view or the data changed) or after
 * ReprobeInterval frames, and the decision is taken again; it is also taken again at once
 * when the number of evaluated lights or of triangles changes, and after a new plain count
 * when the culling of a closed surface's back faces starts or stops (a plain draw of a
 * closed surface shades about half as many fragments culled: the decision taken while its
 * analysis ran would otherwise hold until the next refresh).
 *
 * Counts arrive a frame late (the query results are read when available, never waited for).
 * Counting is skipped while another GL_SAMPLES_PASSED query is running (VTK's depth peeling).
 */

#ifndef vtkPhongDepthPrePass_h
#define vtkPhongDepthPrePass_h

#include <functional> // for std::function

class vtkActor;
class vtkMapper;
class vtkRenderer;
class vtkWindow;

class vtkPhongDepthPrePass
{
public:
  vtkPhongDepthPrePass() = default;
  ~vtkPhongDepthPrePass();
  vtkPhongDepthPrePass(const vtkPhongDepthPrePass&) = delete;
  vtkPhongDepthPrePass& operator=(const vtkPhongDepthPrePass&) = delete;

  /**
   * Draw a mapper's primitives for the frame, plainly or with the pre-pass, as `mode` (a
   * vtkPhongPolyDataMapper::DepthPrePassModes value) asks; returns whether the pre-pass was
   * used. `draw(depthOnly)` is the mapper's own draw (VTK's RenderPieceDraw), with the
   * depth-only program when depthOnly; `triangles` the polygons and strips it draws,
   * `depthTriangles` those its depth pass draws (fewer where vtkPhongVisibleClusters leaves
   * hidden ones out), `culledLights` the lights light culling leaves out of its lit program,
   * `backFacesCulled` whether the draw culls a closed surface's hidden faces
   * (vtkPhongClosedSurface).
   */
  bool Draw(int mode, vtkRenderer* ren, vtkActor* act, vtkMapper* mapper, double triangles,
    double depthTriangles, int culledLights, bool backFacesCulled,
    const std::function<void(bool depthOnly)>& draw);

  /**
   * Whether the pre-pass may draw the actor at all: opaque lit surfaces without edges or
   * vertices drawn over them (VTK offsets those against the surface's depth, which the
   * pre-pass already holds), outside selection.
   */
  static bool CanUse(vtkRenderer* ren, vtkActor* act, double triangles);

  /**
   * Whether the counts tell what the pre-pass saves (Automatic): the lit draw skips hidden
   * fragments only when its fragment shader leaves the depth alone (no polygon offset
   * written into gl_FragDepth, no imposters), and a render pass (shadows, SSAO) draws the
   * actor several times a frame with programs of its own.
   */
  static bool CanMeasure(vtkMapper* mapper, vtkActor* act);

  /**
   * Whether the automatic mode draws this frame with the pre-pass, given the lights the lit
   * program evaluates per fragment, the triangles drawn and those the depth pass would draw,
   * and whether back faces are culled. Call with a current context, once per draw.
   */
  bool Decide(int evaluatedLights, double triangles, double depthTriangles, bool backFacesCulled,
    vtkWindow* window);

  /**
   * The break-even: whether the pre-pass pays for a draw whose plain version shades `shaded`
   * fragments of which `visible` remain with the pre-pass, whose depth pass draws
   * `triangles` triangles, under `evaluatedLights` lights (the cost model is in
   * vtkPhongDepthPrePass.cxx).
   */
  static bool Pays(double shaded, double visible, double triangles, int evaluatedLights);

  ///@{
  /**
   * Count the fragments of the draw between Begin and End: the plain draw (Shaded) or the
   * lit draw after the depth pass (Visible).
   */
  enum Count
  {
    Shaded = 0,
    Visible = 1
  };
  void BeginCount(Count count);
  void EndCount();
  ///@}

  /**
   * Shaded / Visible, as last counted: how many fragments a plain draw shades per pixel it
   * shows. 0 before both were counted.
   */
  double GetDepthComplexity() const;

  /**
   * Whether the automatic mode has decided that the pre-pass pays (and keeps deciding so).
   * Until then its probes draw every triangle in the depth pass: the occlusion clusters,
   * whose arrangement costs a copy of the mesh and a sort (about 560 MB above the data at
   * 8M triangles on llvmpipe), wait for a pre-pass that will be used.
   */
  bool PaysSoFar() const { return this->Decided && this->DecidedPrePass; }

  /**
   * Delete the queries (their context is current or about to go).
   */
  void ReleaseGraphicsResources(vtkWindow* window);

  /// Frames drawn in one mode before the other mode's count is refreshed.
  static constexpr int ReprobeInterval = 64;

private:
  void DrawWithPrePass(
    vtkRenderer* ren, bool counting, const std::function<void(bool depthOnly)>& draw);
  void CollectCounts();
  void Reset();
  // Whether a probe of the pre-pass is worth drawing: Pays for the last shaded count with no
  // fragment left visible, the model's best case.
  bool CouldPay(double depthTriangles, int evaluatedLights) const;

  unsigned int Queries[2] = { 0, 0 };
  vtkWindow* Window = nullptr;
  bool Started[2] = { false, false }; // a count was started and not read yet
  int Running = -1;                   // the count running between Begin and End
  bool LastWithPrePass = false;
  double ShadedCount = 0.0;            // from the latest plain draw
  bool ShadedCulled = false;           // whether that draw culled back faces
  bool CullingOfStartedShaded = false; // the same for the plain count still in flight
  double VisibleCount = 0.0;           // from the latest draw with the pre-pass
  bool Decided = false;
  bool DecidedPrePass = false;
  bool Refreshing = false; // this frame runs in the other mode to refresh its count
  double SeenAtDecision = 0.0;
  int FramesSinceDecision = 0;
  int LightsAtDecision = 0;
  double TrianglesAtDecision = 0.0;
  double DepthTrianglesAtDecision = 0.0;
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongDepthPrePass.h
