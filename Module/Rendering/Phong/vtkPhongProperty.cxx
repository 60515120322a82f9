#include "vtkPhongProperty.h"

#include "vtkObjectFactory.h"
#include "vtkPhongClampedSetter.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkPhongProperty);

//------------------------------------------------------------------------------
vtkPhongProperty::vtkPhongProperty()
{
  // Keep vtkProperty's SpecularPower and our Shininess in step from the start.
  this->Shininess = this->GetSpecularPower();
}

//------------------------------------------------------------------------------
vtkPhongProperty::~vtkPhongProperty() = default;

//------------------------------------------------------------------------------
const char* vtkPhongProperty::GetLightingModelAsString()
{
  switch (this->LightingModel)
  {
    case BlinnPhong:
      return "BlinnPhong";
    case NormalizedPhong:
      return "NormalizedPhong";
    case NormalizedBlinnPhong:
      return "NormalizedBlinnPhong";
    case Phong:
    default:
      return "Phong";
  }
}

//------------------------------------------------------------------------------
void vtkPhongProperty::SetShininess(double shininess)
{
  if (std::isnan(shininess))
  {
    vtkErrorMacro(
      "Shininess must be a number in [0, 1e6]; NaN refused, keeping " << this->Shininess << ".");
    return;
  }
  if (shininess < 0.0)
  {
    vtkWarningMacro("Shininess " << shininess << " is negative; clamped to 0.");
  }
  const double clamped =
    std::min(std::max(shininess, this->GetShininessMinValue()), this->GetShininessMaxValue());
  if (this->Shininess == clamped && this->SpecularPower == std::min(clamped, 128.0))
  {
    return;
  }
  this->Shininess = clamped;
  this->Superclass::SetSpecularPower(std::min(clamped, 128.0));
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPhongProperty::SetSpecularPower(double specularPower)
{
  if (std::isnan(specularPower))
  {
    vtkErrorMacro("SpecularPower must be a number in [0, 128]; NaN refused.");
    return;
  }
  this->Superclass::SetSpecularPower(specularPower);
  if (this->Shininess != this->SpecularPower)
  {
    this->Shininess = this->SpecularPower;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPhongProperty::SetSpotEdgeWidth(double width)
{
  vtkPhongSetClamped(this, "SpotEdgeWidth", this->SpotEdgeWidth, width, 0.0, 90.0);
}

//------------------------------------------------------------------------------
void vtkPhongProperty::SetEmission(double red, double green, double blue)
{
  double rgb[3] = { red, green, blue };
  for (double& component : rgb)
  {
    if (!std::isfinite(component))
    {
      vtkErrorMacro("Emission components must be finite; (" << red << ", " << green << ", " << blue
                                                            << ") refused.");
      return;
    }
    if (component < 0.0)
    {
      vtkWarningMacro("Emission component " << component << " is negative; clamped to 0.");
      component = 0.0;
    }
  }
  if (std::equal(rgb, rgb + 3, this->Emission))
  {
    return;
  }
  std::copy(rgb, rgb + 3, this->Emission);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPhongProperty::SetEmission(const double rgb[3])
{
  this->SetEmission(rgb[0], rgb[1], rgb[2]);
}

//------------------------------------------------------------------------------
void vtkPhongProperty::SetInterpolationToPerVertexGouraud()
{
  this->SetInterpolationToGouraud();
  this->SetPerVertexGouraud(true);
}

//------------------------------------------------------------------------------
void vtkPhongProperty::DeepCopy(vtkProperty* p)
{
  if (p == nullptr)
  {
    return;
  }
  this->Superclass::DeepCopy(p);
  if (auto* phong = vtkPhongProperty::SafeDownCast(p))
  {
    this->LightingModel = phong->LightingModel;
    this->Shininess = phong->Shininess;
    std::copy(phong->Emission, phong->Emission + 3, this->Emission);
    this->SmoothTerminator = phong->SmoothTerminator;
    this->SoftSpotEdge = phong->SoftSpotEdge;
    this->SpotEdgeWidth = phong->SpotEdgeWidth;
    this->PerVertexGouraud = phong->PerVertexGouraud;
  }
  else
  {
    this->Shininess = p->GetSpecularPower();
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPhongProperty::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightingModel: " << this->GetLightingModelAsString() << "\n";
  os << indent << "Shininess: " << this->Shininess << "\n";
  os << indent << "Emission: (" << this->Emission[0] << ", " << this->Emission[1] << ", "
     << this->Emission[2] << ")\n";
  os << indent << "SmoothTerminator: " << (this->SmoothTerminator ? "On" : "Off") << "\n";
  os << indent << "SoftSpotEdge: " << (this->SoftSpotEdge ? "On" : "Off") << "\n";
  os << indent << "SpotEdgeWidth: " << this->SpotEdgeWidth << "\n";
  os << indent << "PerVertexGouraud: " << (this->PerVertexGouraud ? "On" : "Off") << "\n";
}
