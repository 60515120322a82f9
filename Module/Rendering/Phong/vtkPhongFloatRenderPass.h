/**
 * @class   vtkPhongFloatRenderPass
 * @brief   renders a renderer into a 32-bit float target and reads the pixels back
 *
 * An 8-bit window clamps every colour to [0, 1] and cannot hold NaN or Inf, so it hides the
 * very values a numerical test looks for. vtkPhongFloatRenderPass renders its delegate pass
 * (by default the renderer's usual steps, a vtkRenderStepsPass) into an RGBA32F colour
 * target with its own depth buffer, reads the result back into a float image, and then
 * copies it into the window, clamped, so the window still shows the picture (non-finite
 * pixels in magenta).
 *
 * @code
 * vtkNew<vtkPhongFloatRenderPass> pass;
 * renderer->SetPass(pass);
 * window->Render();
 * vtkImageData* image = pass->GetFloatImage(); // RGBA float, unclamped, plus "Depth"
 * @endcode
 *
 * The image has the renderer's size in pixels, its first row at the bottom (as
 * vtkWindowToImageFilter), 4-component float scalars named "RGBA" with whatever the shaders
 * wrote, and a 1-component point-data array "Depth" (window depth in [0, 1]; 1 where nothing
 * was drawn). Blending is off by default: an opaque fragment then replaces what is below it
 * exactly, whereas blending would turn an Inf left by a hidden fragment into NaN (Inf * 0).
 * Turn Blending on for translucent props.
 *
 * With vtkPhongPolyDataMapper's PositionVC and NormalVC debug views the image is a G-buffer
 * that vtkPhongReference can shade in double precision.
 *
 * @sa vtkPhongPolyDataMapper vtkToneMappingPass
 */

#ifndef vtkPhongFloatRenderPass_h
#define vtkPhongFloatRenderPass_h

#include "vtkImageData.h" // for vtkNew<vtkImageData>
#include "vtkImageProcessingPass.h"
#include "vtkNew.h"                  // for vtkNew
#include "vtkRenderingPhongModule.h" // for export macro

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLQuadHelper;
class vtkTextureObject;

class VTKRENDERINGPHONG_EXPORT vtkPhongFloatRenderPass : public vtkImageProcessingPass
{
public:
  static vtkPhongFloatRenderPass* New();
  vtkTypeMacro(vtkPhongFloatRenderPass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Render the delegate into the float target, read it back and show it.
   */
  void Render(const vtkRenderState* s) override;

  void ReleaseGraphicsResources(vtkWindow* window) override;

  /**
   * The pixels of the last render (see the class description). Empty before the first render.
   * The pass owns the image and overwrites it at each render.
   */
  vtkImageData* GetFloatImage();

  ///@{
  /**
   * Whether blending is on while the delegate renders. Default off (exact opaque values; see
   * the class description).
   */
  vtkSetMacro(Blending, bool);
  vtkGetMacro(Blending, bool);
  vtkBooleanMacro(Blending, bool);
  ///@}

  ///@{
  /**
   * Whether the float picture is copied into the window after the read-back, clamped to
   * [0, 1] with non-finite pixels in magenta. Default on; off leaves the window's colour
   * buffer untouched (a G-buffer pass need not be shown).
   */
  vtkSetMacro(CopyToWindow, bool);
  vtkGetMacro(CopyToWindow, bool);
  vtkBooleanMacro(CopyToWindow, bool);
  ///@}

protected:
  vtkPhongFloatRenderPass();
  ~vtkPhongFloatRenderPass() override;

  void PrepareFloatTarget(vtkOpenGLRenderWindow* window, int width, int height);
  void RenderAndReadBack(
    const vtkRenderState* s, vtkOpenGLRenderWindow* window, int width, int height);
  void ShowInWindow(const vtkRenderState* s, int x, int y, int width, int height);

  bool Blending = false;
  bool CopyToWindow = true;
  vtkNew<vtkImageData> FloatImage;
  vtkOpenGLFramebufferObject* FrameBufferObject = nullptr;
  vtkTextureObject* ColorTexture = nullptr;
  vtkOpenGLQuadHelper* QuadHelper = nullptr;

private:
  vtkPhongFloatRenderPass(const vtkPhongFloatRenderPass&) = delete;
  void operator=(const vtkPhongFloatRenderPass&) = delete;
};

#endif
