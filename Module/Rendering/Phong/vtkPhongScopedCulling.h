/**
 * @class   vtkPhongScopedCulling
 * @brief   face culling for as long as it lives, the window's state restored after (private)
 */

#ifndef vtkPhongScopedCulling_h
#define vtkPhongScopedCulling_h

class vtkOpenGLState;
class vtkRenderer;

class vtkPhongScopedCulling
{
public:
  /**
   * Culls `faces` (GL_BACK or GL_FRONT; 0: nothing) in `ren`'s window.
   */
  vtkPhongScopedCulling(vtkRenderer* ren, unsigned int faces);
  ~vtkPhongScopedCulling();
  vtkPhongScopedCulling(const vtkPhongScopedCulling&) = delete;
  void operator=(const vtkPhongScopedCulling&) = delete;

private:
  vtkOpenGLState* State = nullptr;
  bool WasEnabled = false;
  int Mode = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongScopedCulling.h
