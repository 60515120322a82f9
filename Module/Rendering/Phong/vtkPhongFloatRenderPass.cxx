#include "vtkPhongFloatRenderPass.h"

#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkPhongOpenGL.h"

#include "vtkPhongFloatDisplayFS.h"

vtkStandardNewMacro(vtkPhongFloatRenderPass);

//------------------------------------------------------------------------------
vtkPhongFloatRenderPass::vtkPhongFloatRenderPass()
{
  vtkNew<vtkRenderStepsPass> steps;
  this->SetDelegatePass(steps);
}

//------------------------------------------------------------------------------
vtkPhongFloatRenderPass::~vtkPhongFloatRenderPass()
{
  // The GL objects need a context to be freed: ReleaseGraphicsResources() has done that
  // when the window closed; here only the wrappers remain.
  if (this->FrameBufferObject)
  {
    this->FrameBufferObject->Delete();
  }
  if (this->ColorTexture)
  {
    this->ColorTexture->Delete();
  }
  delete this->QuadHelper;
}

//------------------------------------------------------------------------------
void vtkPhongFloatRenderPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Blending: " << (this->Blending ? "On" : "Off") << "\n";
  os << indent << "CopyToWindow: " << (this->CopyToWindow ? "On" : "Off") << "\n";
  int dims[3];
  this->FloatImage->GetDimensions(dims);
  os << indent << "FloatImage: " << dims[0] << " x " << dims[1] << "\n";
  os << indent << "FrameBufferObject: " << this->FrameBufferObject << "\n";
  os << indent << "ColorTexture: " << this->ColorTexture << "\n";
  os << indent << "QuadHelper: " << this->QuadHelper << "\n";
}

//------------------------------------------------------------------------------
vtkImageData* vtkPhongFloatRenderPass::GetFloatImage()
{
  return this->FloatImage;
}

//------------------------------------------------------------------------------
void vtkPhongFloatRenderPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  if (this->FrameBufferObject)
  {
    this->FrameBufferObject->ReleaseGraphicsResources(window);
    this->FrameBufferObject->Delete();
    this->FrameBufferObject = nullptr;
  }
  if (this->ColorTexture)
  {
    this->ColorTexture->ReleaseGraphicsResources(window);
    this->ColorTexture->Delete();
    this->ColorTexture = nullptr;
  }
  if (this->QuadHelper)
  {
    this->QuadHelper->ReleaseGraphicsResources(window);
    delete this->QuadHelper;
    this->QuadHelper = nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkPhongFloatRenderPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkErrorMacro("No delegate pass: nothing to render.");
    return;
  }
  vtkRenderer* renderer = s->GetRenderer();
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    vtkErrorMacro("vtkPhongFloatRenderPass needs an OpenGL render window.");
    return;
  }
  int width = 0;
  int height = 0;
  int x = 0;
  int y = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  if (width <= 0 || height <= 0)
  {
    return;
  }
  this->PrepareFloatTarget(window, width, height);
  this->RenderAndReadBack(s, window, width, height);
  if (this->CopyToWindow)
  {
    this->ShowInWindow(s, x, y, width, height);
  }
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
// An RGBA32F texture of the viewport's size and the framebuffer that draws into it.
void vtkPhongFloatRenderPass::PrepareFloatTarget(
  vtkOpenGLRenderWindow* window, int width, int height)
{
  if (!this->ColorTexture)
  {
    this->ColorTexture = vtkTextureObject::New();
    this->ColorTexture->SetContext(window);
    // Nearest: the window copy maps texels to pixels one to one.
    this->ColorTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->ColorTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->ColorTexture->Allocate2D(width, height, 4, VTK_FLOAT); // RGBA32F
  }
  this->ColorTexture->Resize(width, height);
  if (!this->FrameBufferObject)
  {
    this->FrameBufferObject = vtkOpenGLFramebufferObject::New();
    this->FrameBufferObject->SetContext(window);
  }
}

//------------------------------------------------------------------------------
// The delegate draws into the float target; its colour and depth become FloatImage.
void vtkPhongFloatRenderPass::RenderAndReadBack(
  const vtkRenderState* s, vtkOpenGLRenderWindow* window, int width, int height)
{
  vtkNew<vtkFloatArray> rgba;
  rgba->SetName("RGBA");
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  vtkNew<vtkFloatArray> depth;
  depth->SetName("Depth");
  depth->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  {
    vtkOpenGLState* state = window->GetState();
    vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
    if (!this->Blending)
    {
      state->vtkglDisable(GL_BLEND);
    }
    state->PushFramebufferBindings();
    // The delegate draws with the renderer's camera and a depth buffer of its own; the
    // framebuffer stays bound afterwards.
    this->RenderDelegate(
      s, width, height, width, height, this->FrameBufferObject, this->ColorTexture);
    this->FrameBufferObject->ActivateReadBuffer(0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rgba->GetPointer(0));
    glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth->GetPointer(0));
    state->PopFramebufferBindings();
  }
  this->FloatImage->Initialize();
  this->FloatImage->SetDimensions(width, height, 1);
  this->FloatImage->GetPointData()->SetScalars(rgba);
  this->FloatImage->GetPointData()->AddArray(depth);
  this->FloatImage->Modified();
}

//------------------------------------------------------------------------------
void vtkPhongFloatRenderPass::ShowInWindow(
  const vtkRenderState* s, int x, int y, int width, int height)
{
  auto* window = static_cast<vtkOpenGLRenderWindow*>(s->GetRenderer()->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  if (!this->QuadHelper)
  {
    this->QuadHelper = new vtkOpenGLQuadHelper(window,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), vtkPhongFloatDisplayFS,
      "");
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(this->QuadHelper->Program);
  }
  if (!this->QuadHelper->Program || !this->QuadHelper->Program->GetCompiled())
  {
    vtkErrorMacro("The shader that copies the float image into the window did not build.");
    return;
  }
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglViewport(x, y, width, height);
  state->vtkglScissor(x, y, width, height);
  this->ColorTexture->Activate();
  this->QuadHelper->Program->SetUniformi("floatImage", this->ColorTexture->GetTextureUnit());
  this->QuadHelper->Render();
  this->ColorTexture->Deactivate();
}
