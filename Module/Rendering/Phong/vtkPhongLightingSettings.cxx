#include "vtkPhongLightingSettings.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPhongClampedSetter.h"

#include <algorithm>
#include <cstdlib> // for std::getenv, std::strtod

vtkStandardNewMacro(vtkPhongLightingSettings);

namespace
{
// VTKPHONG_ERROR_BUDGET, in levels: the budget of a program that cannot call
// GetFactoryDefaults, run with VTK_AUTOLOAD_PATH and no change to its code (pvbatch too).
// Anything but a number in [0, 255] is reported and left out.
bool ApplyEnvironment(vtkPhongLightingSettings* settings)
{
  const char* text = std::getenv("VTKPHONG_ERROR_BUDGET");
  if (!text || !*text)
  {
    return false;
  }
  char* end = nullptr;
  const double levels = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(levels >= 0.0 && levels <= 255.0))
  {
    vtkErrorWithObjectMacro(settings,
      "VTKPHONG_ERROR_BUDGET=\"" << text << "\" is not a number of levels in [0, 255]: ignored");
    return false;
  }
  settings->SetErrorBudget(levels);
  return true;
}
}

//------------------------------------------------------------------------------
vtkPhongLightingSettings* vtkPhongLightingSettings::GetFactoryDefaults()
{
  static vtkNew<vtkPhongLightingSettings> defaults;
  static const bool fromEnvironment = ApplyEnvironment(defaults);
  (void)fromEnvironment;
  return defaults;
}

//------------------------------------------------------------------------------
void vtkPhongLightingSettings::SetLightCullingBound(double bound)
{
  this->SetLightCullingBound(bound, this);
}

//------------------------------------------------------------------------------
void vtkPhongLightingSettings::SetLightCullingBound(double bound, vtkObject* reporter)
{
  this->SetChecked(reporter, "LightCullingBound", this->LightCullingBound, bound, 1.0e9);
}

//------------------------------------------------------------------------------
void vtkPhongLightingSettings::SetErrorBudget(double levels)
{
  this->SetErrorBudget(levels, this);
}

//------------------------------------------------------------------------------
void vtkPhongLightingSettings::SetErrorBudget(double levels, vtkObject* reporter)
{
  this->SetChecked(reporter, "ErrorBudget", this->ErrorBudget, levels, 255.0);
}

//------------------------------------------------------------------------------
const char* vtkPhongLightingSettings::GetBudgetModeAsString(int mode)
{
  switch (mode)
  {
    case BudgetPerFragment:
      return "per fragment";
    case BudgetSpecularPerVertex:
      return "specular per vertex";
    case BudgetPerVertex:
      return "per vertex";
    default:
      return "unknown";
  }
}

//------------------------------------------------------------------------------
void vtkPhongLightingSettings::SetChecked(
  vtkObject* reporter, const char* name, double& member, double value, double largest)
{
  // The error names the object the user set it on; the change is this object's.
  double stored = member;
  if (vtkPhongSetClamped(reporter, name, stored, value, 0.0, largest) && reporter != this)
  {
    this->Modified();
  }
  member = stored;
}

//------------------------------------------------------------------------------
const char* vtkPhongLightingSettings::GetDebugViewAsString()
{
  return DebugViewAsString(this->DebugView);
}

//------------------------------------------------------------------------------
const char* vtkPhongLightingSettings::DebugViewAsString(int view)
{
  switch (view)
  {
    case AmbientTerm:
      return "AmbientTerm";
    case DiffuseTerm:
      return "DiffuseTerm";
    case SpecularTerm:
      return "SpecularTerm";
    case EmissionTerm:
      return "EmissionTerm";
    case ShadingNormal:
      return "ShadingNormal";
    case SingleLight:
      return "SingleLight";
    case PositionVC:
      return "PositionVC";
    case NormalVC:
      return "NormalVC";
    case BudgetUse:
      return "BudgetUse";
    case Final:
    default:
      return "Final";
  }
}

//------------------------------------------------------------------------------
void vtkPhongLightingSettings::DeepCopy(vtkPhongLightingSettings* other)
{
  if (!other || other == this)
  {
    return;
  }
  this->SetDebugView(other->DebugView);
  this->SetDebugLightIndex(other->DebugLightIndex);
  this->SetShaderSpecialization(other->ShaderSpecialization);
  this->SetInterpolatedDotProducts(other->InterpolatedDotProducts);
  this->SetLightCullingBound(other->LightCullingBound);
  this->SetErrorBudget(other->ErrorBudget);
  this->SetSpecularAntiAliasing(other->SpecularAntiAliasing);
  this->SetLightingWithoutLights(other->LightingWithoutLights);
  this->SetDepthPrePass(other->DepthPrePass);
  this->SetDepthPrePassOcclusionCulling(other->DepthPrePassOcclusionCulling);
  this->SetClosedSurfaceCulling(other->ClosedSurfaceCulling);
  this->SetMaximumNumberOfShaderPrograms(other->MaximumNumberOfShaderPrograms);
}

//------------------------------------------------------------------------------
void vtkPhongLightingSettings::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DebugView: " << this->GetDebugViewAsString() << "\n";
  os << indent << "DebugLightIndex: " << this->DebugLightIndex << "\n";
  os << indent << "ShaderSpecialization: " << (this->ShaderSpecialization ? "On" : "Off") << "\n";
  os << indent << "InterpolatedDotProducts: " << (this->InterpolatedDotProducts ? "On" : "Off")
     << "\n";
  os << indent << "LightCullingBound: " << this->LightCullingBound << "\n";
  os << indent << "ErrorBudget: " << this->ErrorBudget << "\n";
  os << indent << "SpecularAntiAliasing: " << (this->SpecularAntiAliasing ? "On" : "Off") << "\n";
  os << indent << "LightingWithoutLights: " << (this->LightingWithoutLights ? "On" : "Off") << "\n";
  os << indent << "DepthPrePass: " << this->DepthPrePass << "\n";
  os << indent
     << "DepthPrePassOcclusionCulling: " << (this->DepthPrePassOcclusionCulling ? "On" : "Off")
     << "\n";
  os << indent << "ClosedSurfaceCulling: " << (this->ClosedSurfaceCulling ? "On" : "Off") << "\n";
  os << indent << "MaximumNumberOfShaderPrograms: " << this->MaximumNumberOfShaderPrograms << "\n";
}

//------------------------------------------------------------------------------
bool vtkPhongLightingSettingsHolder::Set(vtkPhongLightingSettings* settings, vtkObject* holder)
{
  if (!settings)
  {
    vtkErrorWithObjectMacro(holder, "A mapper always has lighting settings: nullptr refused.");
    return false;
  }
  const bool changed = settings != this->Settings;
  this->Settings = settings;
  return changed;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkPhongLightingSettingsHolder::MTime(vtkMTimeType holderTime) const
{
  return std::max(holderTime, this->Settings->GetMTime());
}
