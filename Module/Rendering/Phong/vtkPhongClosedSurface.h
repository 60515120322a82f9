/**
 * @class   vtkPhongClosedSurface
 * @brief   whether a mapper's back faces can be seen at all, and which faces to cull (private)
 *
 * Seen from outside, the first surface a viewing ray meets on a closed, consistently
 * oriented surface is one it enters the solid through: a face turned towards the viewer.
 * The faces turned away are all hidden behind it, but stock VTK still sets them up,
 * rasterizes them and tests their depth, and shades those drawn before the face in front.
 * On llvmpipe that is about a third of a closed mesh's frame.
 *
 * This class decides, once per upload of VTK's triangle index buffer, whether the triangles
 * are closed surfaces:
 * - No concave polygon: VTK fans polygons into triangles, and a concave one's fan overlaps
 *   itself with triangles turned over.
 * - Closed and consistently oriented: every edge is used exactly twice, once in each
 *   direction, by the points' ids or else with the points at one position taken as one
 *   (split normals and per-face points duplicate them; a triangle with two corners at one
 *   point, which covers no pixel, is then left out). A corner that is not finite rules
 *   culling out. Hashed sums over the edges, by ids and then by positions, tell most open
 *   surfaces in a pass each; the exact check goes through the edges a range of points at a
 *   time, in at most 64 MB.
 * - The surfaces bound a solid, never its inside-out: the largest connected surface's
 *   volume gives the orientation (outward, the usual, or inward), and every surface
 *   enclosing a volume of the other sign (a cavity: a contour around a minimum, a hollow
 *   solid's inner wall) lies inside the others, a winding number counted along a ray. A
 *   cavity outside (a surface turned inside out beside the others) rules culling out, as do
 *   cavities too many to check (more than 16M ray-triangle tests). Flat closed surfaces
 *   (both sides of a sheet, volume about 0) bound nothing and count for neither.
 *
 * A surface of more than 256k triangles is analysed on a thread of its own, on copies of the
 * indices and points, so that its first frames draw as stock VTK's do (nothing culled)
 * while the analysis runs (about 0.1 s a million triangles closed by their ids, beside
 * llvmpipe on two cores); the frame after it ends culls. The hashed sums run first, on the
 * frame's own thread, reading VTK's index buffer a block of 3 MB at a time: a surface they
 * find open (a terrain, a piece of a surface split between ranks) costs no copy of its
 * indices or points, and no thread.
 * A new upload first waits for the analysis of the previous one, so that at most one runs.
 *
 * Per view, HiddenFaces() answers whether the camera sees all of it from outside: every
 * corner of the drawn bounds lies beyond the near plane in the projection VTK draws with
 * (so the camera is outside, and no near-plane cut opens the solid). The face to cull
 * follows from the orientation and from the sign of the projection's determinant (a
 * mirroring actor or camera matrix turns the window's winding over).
 *
 * One assumption is not checked: a closed surface that passes through itself so that a
 * region lies inside it a negative number of times (a surface folded inside out) shows back
 * faces. Scanned, contoured and CAD meshes do not do that; the mapper's
 * ClosedSurfaceCulling switch turns this off.
 */

#ifndef vtkPhongClosedSurface_h
#define vtkPhongClosedSurface_h

#include "vtkPhongBufferBlocks.h" // for vtkPhongBufferBlock
#include "vtkSmartPointer.h"      // for vtkSmartPointer
#include "vtkType.h"              // for vtkMTimeType, VTK_DOUBLE_MAX

#include <cstddef> // for size_t
#include <cstdint> // for std::uint64_t
#include <memory>  // for std::unique_ptr
#include <vector>  // for std::vector

class vtkActor;
class vtkOpenGLHelper;
class vtkOpenGLIndexBufferObject;
class vtkPolyData;
class vtkRenderer;
class vtkShaderProperty;

class vtkPhongClosedSurface
{
public:
  vtkPhongClosedSurface();
  ~vtkPhongClosedSurface(); // waits for a background analysis
  vtkPhongClosedSurface(const vtkPhongClosedSurface&) = delete;
  vtkPhongClosedSurface& operator=(const vtkPhongClosedSurface&) = delete;

  /**
   * Analyse the triangles VTK's index buffer `triangles` draws (indices into the vertex
   * buffer that holds the points of `blocks`) when the buffer was rebuilt since (`builtAt`,
   * VTK's VBOBuildTime). Call with the window's context current.
   */
  void Update(vtkOpenGLIndexBufferObject* triangles, const std::vector<vtkPhongBufferBlock>& blocks,
    vtkMTimeType builtAt);

  /**
   * +1: closed surfaces, each enclosing its volume with outward faces; -1: all inward;
   * 0: not closed surfaces (or not analysed), nothing may be culled.
   */
  int GetOrientation() const { return this->Orientation; }

  /**
   * Whether the analysis of the last upload still runs in the background.
   */
  bool IsAnalysing() const;

  /**
   * The faces to cull (GL_BACK or GL_FRONT) when the renderer's camera sees the surfaces,
   * whose model bounds are `bounds`, from outside with the actor's matrix; 0 otherwise.
   */
  unsigned int HiddenFaces(vtkRenderer* ren, vtkActor* act, const double bounds[6]) const;

  /**
   * Whether a mapper draws, besides triangles that may form closed surfaces, nothing through
   * which a back face could show: a plain opaque surface (no translucency, texture, edges,
   * vertices or face culling of the property's own), no strips (VTK's strip order is not
   * checked), no wide lines, tubes or sphere points (a geometry shader makes them triangles of
   * any winding), no shader code of the user's (it may move or discard fragments; before VTK
   * 9.2 also `legacyShaders`, the mapper's own replacements), no clipping plane (its cut
   * opens the solid), no picking and no render pass. `primitives`: the mapper's
   * vtkOpenGLPolyDataMapper::Primitives.
   */
  static bool DrawsOnlySurfaces(vtkRenderer* ren, vtkActor* act, const vtkOpenGLHelper* primitives,
    vtkShaderProperty* legacyShaders, int clippingPlanes);

private:
  // Which way the triangles may be closed, from the hashed sums over their edges: by their
  // points' ids, or only with the points at one position taken as one; None: open.
  enum class Closure
  {
    None,
    ByIds,
    AtPositions
  };
  static Closure MayBeClosed(vtkOpenGLIndexBufferObject* triangles, vtkPolyData* input);
  static bool HasOnlyFinitePoints(vtkPolyData* input);
  static bool MayBeClosedAtPositions(const std::vector<unsigned int>& indices, vtkPolyData* input);
  static int Analyse(std::vector<unsigned int>& indices, vtkPolyData* input, Closure closure);
  void AnalyseInBackground(
    std::vector<unsigned int> indices, vtkPolyData* input, Closure closure, bool owned);
  void CollectBackground(bool wait);
  static bool HasConcavePolygons(vtkPolyData* input);
  static std::vector<std::uint32_t> WeldPoints(vtkPolyData* input);
  static bool WeldTriangles(
    std::vector<unsigned int>& indices, const std::vector<std::uint32_t>& welded);
  static bool IsClosedAndConsistent(const std::vector<unsigned int>& triangles);
  static bool ArePaired(const std::vector<unsigned int>& triangles,
    const std::vector<std::uint32_t>& edgesAt, unsigned int first, unsigned int last, size_t edges);
  struct Surface
  {
    double Volume = 0.0;
    double Lower[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX }; // its bounds
    double Upper[3] = { VTK_DOUBLE_MIN, VTK_DOUBLE_MIN, VTK_DOUBLE_MIN };
    vtkIdType Point = 0; // one of its points
  };
  static std::vector<Surface> FindSurfaces(const std::vector<unsigned int>& triangles,
    vtkPolyData* input, std::vector<std::uint32_t>& owner);
  static int Orient(const std::vector<unsigned int>& triangles, vtkPolyData* input);
  static int WindingNumber(vtkIdType point, size_t skip, const std::vector<unsigned int>& triangles,
    const std::vector<std::uint32_t>& owner, vtkPolyData* input);
  static int RayCrossing(
    const double origin[3], const double direction[3], const double corners[3][3], bool& grazed);

  int Orientation = 0;
  vtkMTimeType BuiltAt = 0;
  size_t IndexCount = 0;
  struct Background; // the analysis of a large surface on its own thread
  std::unique_ptr<Background> Pending;
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongClosedSurface.h
