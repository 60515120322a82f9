#include "vtkPhongObjectFactory.h"

#include "vtkPhongCompatibility.h"
#include "vtkPhongCompositePolyDataMapper.h"
#if VTKPHONG_VTK_9_3
#include "vtkPhongCompositeDelegator.h"
#endif
#include "vtkPhongPolyDataMapper.h"
#include "vtkSmartPointer.h"
#include "vtkVersion.h"

vtkStandardNewMacro(vtkPhongObjectFactory);

namespace
{
vtkObject* NewPolyDataMapper()
{
  return vtkPhongPolyDataMapper::New();
}

vtkObject* NewCompositeMapper()
{
  return vtkPhongCompositePolyDataMapper::New();
}

#if VTKPHONG_VTK_9_3
// vtkCompositePolyDataMapper::New() never asks the factory, but every composite mapper makes
// its delegators through it (vtkCompositePolyDataMapperDelegator::New): VTK's own composite
// mapper, made by name (PyVista's add_composite, ParaView's Surface), then draws its blocks
// with vtkPhong's block mapper, with the default lighting settings.
vtkObject* NewDelegator()
{
  return vtkPhongCompositeDelegator::New();
}
#endif

// The overridden VTK class, its vtkPhong replacement, and how to make one.
struct Override
{
  const char* VTKClass;
  const char* PhongClass;
  vtkObject* (*Create)();
};

const Override Overrides[] = {
  { "vtkPolyDataMapper", "vtkPhongPolyDataMapper", NewPolyDataMapper },
  { "vtkOpenGLPolyDataMapper", "vtkPhongPolyDataMapper", NewPolyDataMapper },
#if VTKPHONG_VTK_9_3
  { "vtkCompositePolyDataMapper", "vtkPhongCompositePolyDataMapper", NewCompositeMapper },
  { "vtkCompositePolyDataMapperDelegator", "vtkPhongCompositeDelegator", NewDelegator },
#else
  { "vtkCompositePolyDataMapper2", "vtkPhongCompositePolyDataMapper", NewCompositeMapper },
#endif
};

// The registered instance while the overrides are on.
vtkSmartPointer<vtkPhongObjectFactory>& Registered()
{
  static vtkSmartPointer<vtkPhongObjectFactory> factory;
  return factory;
}
}

//------------------------------------------------------------------------------
vtkPhongObjectFactory::vtkPhongObjectFactory()
{
  for (const Override& entry : Overrides)
  {
    this->RegisterOverride(entry.VTKClass, entry.PhongClass,
      "vtkPhong: exact Phong / Blinn-Phong lighting", 1, entry.Create);
  }
}

//------------------------------------------------------------------------------
const char* vtkPhongObjectFactory::GetVTKSourceVersion()
{
  return VTK_SOURCE_VERSION;
}

//------------------------------------------------------------------------------
const char* vtkPhongObjectFactory::GetDescription()
{
  return "vtkPhong overrides of VTK's polydata and composite mappers";
}

//------------------------------------------------------------------------------
void vtkPhongObjectFactory::SetOverridesEnabled(bool enabled)
{
  vtkSmartPointer<vtkPhongObjectFactory>& factory = Registered();
  if (enabled == (factory != nullptr))
  {
    return;
  }
  // Off in every factory registered so far (VTK's OpenGL2 one), or on again when vtkPhong's
  // goes.
  SetOtherFactoriesOverridesEnabled(!enabled);
  if (enabled)
  {
    factory = vtkSmartPointer<vtkPhongObjectFactory>::New();
    vtkObjectFactory::RegisterFactory(factory);
  }
  else
  {
    vtkObjectFactory::UnRegisterFactory(factory);
    factory = nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkPhongObjectFactory::SetOtherFactoriesOverridesEnabled(bool enabled)
{
  for (const Override& entry : Overrides)
  {
    vtkObjectFactory::SetAllEnableFlags(enabled, entry.VTKClass);
  }
}

bool vtkPhongObjectFactory::GetOverridesEnabled()
{
  return Registered() != nullptr;
}

//------------------------------------------------------------------------------
void vtkPhongObjectFactory::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OverridesEnabled: " << (GetOverridesEnabled() ? "On" : "Off") << "\n";
}
