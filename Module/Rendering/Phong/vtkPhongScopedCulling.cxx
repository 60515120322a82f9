#include "vtkPhongScopedCulling.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkPhongOpenGL.h"

//------------------------------------------------------------------------------
vtkPhongScopedCulling::vtkPhongScopedCulling(vtkRenderer* ren, unsigned int faces)
{
  if (faces == 0)
  {
    return;
  }
  this->State = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
  this->WasEnabled = this->State->GetEnumState(GL_CULL_FACE);
  GLint mode = GL_BACK;
  this->State->vtkglGetIntegerv(GL_CULL_FACE_MODE, &mode);
  this->Mode = mode;
  this->State->vtkglCullFace(faces);
  this->State->vtkglEnable(GL_CULL_FACE);
}

//------------------------------------------------------------------------------
vtkPhongScopedCulling::~vtkPhongScopedCulling()
{
  if (this->State)
  {
    this->State->SetEnumState(GL_CULL_FACE, this->WasEnabled);
    this->State->vtkglCullFace(static_cast<GLenum>(this->Mode));
  }
}
