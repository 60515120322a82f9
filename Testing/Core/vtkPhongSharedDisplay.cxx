// Kept apart from every VTK header: Xlib.h defines macros (Status, Bool, ...)
// that break vtksys.
#include "vtkPhongSharedDisplay.h"

#include <X11/Xlib.h>

#include <chrono>
#include <thread>

void* vtkPhongTest::SharedDisplay()
{
  static Display* display = []
  {
    for (int attempt = 0; attempt < 50; ++attempt)
    {
      if (Display* opened = XOpenDisplay(nullptr))
      {
        return opened;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return static_cast<Display*>(nullptr);
  }();
  return display;
}
