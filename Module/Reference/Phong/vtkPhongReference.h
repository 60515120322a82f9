/**
 * @class   vtkPhongReference
 * @brief   the lighting model in double precision on the CPU: the ruler the GPU is measured with
 *
 * vtkPhongReference evaluates docs/lighting-model.md in double precision (GLM) from the same
 * VTK objects vtkPhongPolyDataMapper reads: the renderer's camera, lights, ambient light and
 * two-sided lighting, and the actor's property, back-face property and matrix. It is written
 * from the model's text and shares no code with the GLSL or the shader path, so a
 * mistake in either shows up as a difference.
 *
 * Two ways to feed it:
 * - RenderAnalytic() ray-casts an exact surface (a sphere, a parallelogram as
 *   vtkPlaneSource makes it, or a torus as vtkParametricTorus makes it, in the actor's
 *   model coordinates) through the centre of every pixel of the renderer's camera, and
 *   shades the exact position and normal. This is the ground truth a tessellated,
 *   interpolated GPU image is measured against.
 * - ShadeGBuffer() shades the view-coordinate positions and normals the mapper wrote with
 *   its PositionVC and NormalVC debug views into a float target (vtkPhongFloatRenderPass).
 *   Since both sides start from the same positions and normals, the difference is the GPU's
 *   shading arithmetic alone.
 *
 * Both write a float RGBA image the size of ImageSize (default: the renderer's size), first
 * row at the bottom, alpha 1 where a surface is shaded and 0 elsewhere, comparable pixel for
 * pixel with vtkPhongFloatRenderPass::GetFloatImage() (see vtkPhongImageComparison).
 *
 * The reference shades with the property's colours: textures and mapped scalars are not
 * modelled, nor is per-vertex Gouraud (compare those against it to measure what they cost),
 * VTK's user light transform (VR), stereo or off-axis cameras. Parameters out of range are
 * treated as docs/lighting-model.md says (non-finite colours and negative intensities as 0,
 * ...), silently: the mapper is the one that reports them.
 *
 * @sa vtkPhongPolyDataMapper vtkPhongFloatRenderPass vtkPhongImageComparison
 */

#ifndef vtkPhongReference_h
#define vtkPhongReference_h

#include "vtkObject.h"
#include "vtkReferencePhongModule.h" // for export macro

#include <memory> // for std::unique_ptr

class vtkActor;
class vtkImageData;
class vtkRenderer;

class VTKREFERENCEPHONG_EXPORT vtkPhongReference : public vtkObject
{
public:
  static vtkPhongReference* New();
  vtkTypeMacro(vtkPhongReference, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The scene: the renderer (camera, lights, ambient light, two-sided lighting) and the
   * actor whose material (and, for analytic surfaces, matrix) is used. Both are required.
   * The values are read when an image is made, so the objects can change between calls.
   */
  virtual void SetRenderer(vtkRenderer* renderer);
  vtkGetObjectMacro(Renderer, vtkRenderer);
  virtual void SetActor(vtkActor* actor);
  vtkGetObjectMacro(Actor, vtkActor);
  ///@}

  /**
   * The analytic surfaces RenderAnalytic() can cast rays at.
   */
  enum Surfaces
  {
    NoSurface = 0,
    Sphere = 1,
    Plane = 2,
    Torus = 3
  };

  ///@{
  /**
   * The surface, in the actor's model coordinates. Default: none (RenderAnalytic() fails).
   * Sphere: centre and radius (> 0). Plane: the parallelogram origin + s (point1 - origin) +
   * t (point2 - origin), s and t in [0, 1], facing cross(point1 - origin, point2 - origin),
   * as vtkPlaneSource. Torus: centre, ring radius and cross-section radius (both > 0), its
   * axis along z, as vtkParametricTorus.
   */
  void SetSurfaceToSphere(double cx, double cy, double cz, double radius);
  void SetSurfaceToPlane(const double origin[3], const double point1[3], const double point2[3]);
  void SetSurfaceToTorus(
    double cx, double cy, double cz, double ringRadius, double crossSectionRadius);
  vtkGetMacro(Surface, int);
  ///@}

  ///@{
  /**
   * Size in pixels of the images made. Default (0, 0): the renderer's size in its window.
   * A size with a different aspect ratio keeps the camera's vertical view angle, as VTK does.
   */
  vtkSetVector2Macro(ImageSize, int);
  vtkGetVector2Macro(ImageSize, int);
  ///@}

  /**
   * Ray-cast the surface through every pixel centre and shade the hits. Besides the "RGBA"
   * scalars the image gets point-data arrays "PositionWC" and "NormalWC" (the exact hit
   * point and outward unit normal, zero where nothing is hit). Returns 1 on success, 0 (with
   * an error) when the scene or surface is missing or invalid.
   */
  int RenderAnalytic(vtkImageData* output);

  /**
   * Shade a G-buffer: two float images of equal size holding, per pixel, the view-coordinate
   * position and the shading normal written by vtkPhongPolyDataMapper's PositionVC and
   * NormalVC views (alpha 1 on front faces, 0.5 on back faces, 0 for the background). The
   * normal is used as given (the mapper has already turned it towards the viewer); the alpha
   * selects the front or back material. Returns 1 on success, 0 with an error for images that
   * do not match.
   */
  int ShadeGBuffer(vtkImageData* positionVC, vtkImageData* normalVC, vtkImageData* output);

  /**
   * The colour of one point in world coordinates, N being the shading normal (unit; on a back
   * face with two-sided lighting, already reversed) and backFace whether the point lies on a
   * back face (selecting the back material).
   */
  void ShadePoint(
    const double positionWC[3], const double normalWC[3], bool backFace, double rgb[3]);

protected:
  vtkPhongReference();
  ~vtkPhongReference() override;

  /**
   * Read the renderer and actor into the internal double-precision scene for an image of the
   * given size. Returns false (with an error) when something is missing.
   */
  bool PrepareScene(int width, int height);
  bool ImageSizeFor(int size[2]);

  vtkRenderer* Renderer = nullptr;
  vtkActor* Actor = nullptr;
  int Surface = NoSurface;
  double SurfaceParameters[9] = { 0, 0, 0, 0, 0, 0, 0, 0, 0 };
  int ImageSize[2] = { 0, 0 };

private:
  vtkPhongReference(const vtkPhongReference&) = delete;
  void operator=(const vtkPhongReference&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
