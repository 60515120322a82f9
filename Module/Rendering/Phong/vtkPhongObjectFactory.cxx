#include "vtkPhongObjectFactory.h"

#include "vtkPhongCompatibility.h"
#include "vtkPhongCompositePolyDataMapper.h"
#if VTKPHONG_VTK_9_3
#include "vtkPhongCompositeDelegator.h"
#endif
#include "vtkPhongPolyDataMapper.h"
#include "vtkSmartPointer.h"
#include "vtkVersion.h"

#if VTKPHONG_HAS_OVERRIDE_ATTRIBUTES
#include "vtkOpenGLCompositePolyDataMapperDelegator.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOverrideAttribute.h"
#endif

vtkStandardNewMacro(vtkPhongObjectFactory);

namespace
{
// The mappers the factory makes start from the process's factory defaults
// (vtkPhongLightingSettings::GetFactoryDefaults), which code that never names vtkPhong's
// mappers can still set.
template <typename Mapper>
vtkObject* NewFromFactoryDefaults()
{
  Mapper* mapper = Mapper::New();
  mapper->GetLightingSettings()->DeepCopy(vtkPhongLightingSettings::GetFactoryDefaults());
  return mapper;
}

#if VTKPHONG_VTK_9_3
// vtkCompositePolyDataMapper::New() never asks the factory, but every composite mapper makes
// its delegators through it (vtkCompositePolyDataMapperDelegator::New): VTK's own composite
// mapper, made by name (PyVista's add_composite, ParaView's Surface), then draws its blocks
// with vtkPhong's block mapper, starting from the factory defaults (vtkPhongBlockMapper).
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
  { "vtkPolyDataMapper", "vtkPhongPolyDataMapper", NewFromFactoryDefaults<vtkPhongPolyDataMapper> },
  { "vtkOpenGLPolyDataMapper", "vtkPhongPolyDataMapper",
    NewFromFactoryDefaults<vtkPhongPolyDataMapper> },
#if VTKPHONG_VTK_9_3
  { "vtkCompositePolyDataMapper", "vtkPhongCompositePolyDataMapper",
    NewFromFactoryDefaults<vtkPhongCompositePolyDataMapper> },
  { "vtkCompositePolyDataMapperDelegator", "vtkPhongCompositeDelegator", NewDelegator },
#else
  { "vtkCompositePolyDataMapper2", "vtkPhongCompositePolyDataMapper",
    NewFromFactoryDefaults<vtkPhongCompositePolyDataMapper> },
#endif
};

#if VTKPHONG_HAS_OVERRIDE_ATTRIBUTES
// VTK 9.7 chooses among the overrides of a class by their attributes when the user states
// preferences (vtkObjectFactory::SetPreferences, VTK_FACTORY_PREFER, --vtk-factory-prefer):
// the overrides whose attributes match the first preference are kept, in registration order,
// and narrowed by the next ones; the first of them that makes an object wins. Registration
// order (vtkPhong's factory first) decides only when none matches or none of those is
// enabled. An override without attributes never matches: with
// VTK_FACTORY_PREFER=RenderingBackend=OpenGL, VTK's OpenGL override of the same class wins
// wherever it is enabled (VTK's OpenGL2 factory registered after vtkPhong's, as under
// VTK_AUTOLOAD_PATH). So each override carries the attributes VTK gives the OpenGL class the
// vtkPhong class derives from, made by VTK itself so that they follow whatever VTK declares
// (9.7.0: RenderingBackend=OpenGL for vtkOpenGLPolyDataMapper, plus Platform=Desktop for
// vtkOpenGLCompositePolyDataMapperDelegator). VTK's composite mapper has no override of its
// own; vtkPhong's draws with OpenGL mappers and takes vtkOpenGLPolyDataMapper's. With equal
// attributes, registration order decides again. Written to VTK 9.7.0's headers
// (vtkOverrideAttribute.h, vtkObjectFactory.h, vtkOpenGLPolyDataMapper.h) and not compiled
// here: Debian has no VTK 9.7. RegisterOverride takes the new chain returned.
vtkOverrideAttribute* NewAttributes(const Override& entry)
{
  if (entry.Create == NewDelegator)
  {
    return vtkOpenGLCompositePolyDataMapperDelegator::CreateOverrideAttributes();
  }
  return vtkOpenGLPolyDataMapper::CreateOverrideAttributes();
}
#endif

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
  const char* description = "vtkPhong: exact Phong / Blinn-Phong lighting";
  for (const Override& entry : Overrides)
  {
#if VTKPHONG_HAS_OVERRIDE_ATTRIBUTES
    this->RegisterOverride(
      entry.VTKClass, entry.PhongClass, description, 1, entry.Create, NewAttributes(entry));
#else
    this->RegisterOverride(entry.VTKClass, entry.PhongClass, description, 1, entry.Create);
#endif
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
