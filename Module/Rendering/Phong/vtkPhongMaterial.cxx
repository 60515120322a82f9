#include "vtkPhongMaterial.h"

#include "vtkPhongProblemLog.h"
#include "vtkPhongProperty.h"
#include "vtkProperty.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
double vtkPhongMaterial::ShininessOf(vtkProperty* material)
{
  auto* phong = vtkPhongProperty::SafeDownCast(material);
  return phong ? phong->GetShininess() : material->GetSpecularPower();
}

//------------------------------------------------------------------------------
int vtkPhongMaterial::LightingModelOf(vtkProperty* material)
{
  auto* phong = vtkPhongProperty::SafeDownCast(material);
  return phong ? phong->GetLightingModel() : vtkPhongProperty::Phong;
}

//------------------------------------------------------------------------------
double vtkPhongMaterial::LobeNormalization(int lightingModel, double shininess)
{
  switch (lightingModel)
  {
    case vtkPhongProperty::NormalizedPhong:
      return (shininess + 2.0) / 2.0;
    case vtkPhongProperty::NormalizedBlinnPhong:
      return (shininess + 8.0) / 8.0;
    default:
      return 1.0;
  }
}

//------------------------------------------------------------------------------
void vtkPhongMaterial::FiniteProduct(
  double coefficient, const double color[3], const double scale[3], float product[3])
{
  // Bad values were reported where the material's own uniforms were checked.
  auto usable = [](double value)
  {
    const double largest = vtkPhongProblemLog::LargestValue;
    return std::isfinite(value) ? std::min(std::max(value, -largest), largest) : 0.0;
  };
  const double k = usable(coefficient);
  for (int c = 0; c < 3; ++c)
  {
    product[c] = static_cast<float>(k * usable(color[c]) * scale[c]);
  }
}
