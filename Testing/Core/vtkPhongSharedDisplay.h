// One X connection per process, shared by all the render windows a test or
// benchmark opens. Xvfb in the sandboxes this project runs in refuses (EAGAIN)
// roughly one connection in twelve made right after another one closed, and
// every vtkRenderWindow opens and closes its own: a program that makes several
// windows in a row would fail at random. A process's first connection is not
// affected; it is still retried, briefly, to be safe.

#ifndef vtkPhongSharedDisplay_h
#define vtkPhongSharedDisplay_h

#include "vtkRenderWindow.h"

namespace vtkPhongTest
{
// The process's X display connection (a Display*), or nullptr without X.
void* SharedDisplay();

// Make the window use the shared connection (when there is an X display at all).
inline void UseSharedDisplay(vtkRenderWindow* window)
{
  if (void* display = SharedDisplay())
  {
    window->SetDisplayId(display);
  }
}
}

#endif
