// The loadable form of the switch: a shared library that VTK's object factory loads from
// a directory named in VTK_AUTOLOAD_PATH, so that a program gets vtkPhong's mappers with no
// change to its code and no rebuild (a C++ program, pvpython, a Python script).
//
// VTK loads the libraries of the listed directories when its factory list is first made and
// registers the factory each one's vtkLoad returns. Factories registered before it (VTK's
// OpenGL2 one, made by a program's autoinit) would be asked first: their overrides of the
// classes vtkPhong overrides are switched off, as `import vtkphong.overrides` does. The
// library is built against one VTK, and VTK refuses it, with a warning, under another
// (vtkGetFactoryVersion).

#include "vtkPhongObjectFactory.h"
#include "vtkVersion.h" // VTK_SOURCE_VERSION, for VTK_FACTORY_INTERFACE_IMPLEMENT

namespace
{
// What vtkLoad makes: vtkPhong's factory, preferred over those registered before it.
struct vtkPhongAutoloadFactory
{
  static vtkObjectFactory* New()
  {
    vtkPhongObjectFactory::SetOtherFactoriesOverridesEnabled(false);
    return vtkPhongObjectFactory::New();
  }
};
}

VTK_FACTORY_INTERFACE_IMPLEMENT(vtkPhongAutoloadFactory)
