// The autoinit of vtkPhong::RenderingPhongOverrides, the C++ counterpart of Python's
// `import vtkphong.overrides`. A program that links the module and names it in
// vtk_module_autoinit calls this before main (through vtkRenderingCoreModule.h, which every
// VTK rendering header includes), and from then on VTK's factory returns vtkPhong's mappers
// for vtkPolyDataMapper and the composite mapper. vtkPhongObjectFactory::SetOverridesEnabled
// switches them off and on again at run time.
//
// Whichever of VTK's OpenGL2 factory and this one registers first, vtkPhong's wins:
// SetOverridesEnabled disables VTK's overrides of the same classes in the factories already
// registered, and a factory registered later comes after vtkPhong's in the search.

#include "vtkPhongObjectFactory.h"
#include "vtkRenderingPhongOverridesModule.h"

namespace
{
// Every translation unit that includes a rendering header constructs the autoinit once.
unsigned int ConstructCount = 0;
}

VTKRENDERINGPHONGOVERRIDES_EXPORT void vtkRenderingPhongOverrides_AutoInit_Construct()
{
  if (++ConstructCount == 1)
  {
    vtkPhongObjectFactory::SetOverridesEnabled(true);
  }
}
