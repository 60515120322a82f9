#include "vtkPhongAttenuation.h"

#include "vtkLight.h"
#include "vtkPhongProblemLog.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
vtkPhongAttenuation vtkPhongAttenuation::Of(vtkLight* light)
{
  vtkPhongAttenuation attenuation;
  const double* values = light->GetAttenuationValues();
  for (int i = 0; i < 3; ++i)
  {
    const double value = std::isfinite(values[i]) && values[i] > 0.0 ? values[i] : 0.0;
    attenuation.Coefficients[i] = std::min(value, vtkPhongProblemLog::LargestAttenuation);
  }
  return attenuation;
}

//------------------------------------------------------------------------------
bool vtkPhongAttenuation::IsNone() const
{
  return this->Coefficients[0] == 1.0 && this->Coefficients[1] == 0.0 &&
    this->Coefficients[2] == 0.0;
}

//------------------------------------------------------------------------------
double vtkPhongAttenuation::At(double d) const
{
  const auto& k = this->Coefficients;
  return 1.0 / std::max(k[0] + k[1] * d + k[2] * d * d, 1.0e-20);
}

//------------------------------------------------------------------------------
double vtkPhongAttenuation::SteepestOver(double nearest, double farthest) const
{
  const auto& k = this->Coefficients;
  const double denominator = k[0] + k[1] * nearest + k[2] * nearest * nearest;
  if (!(denominator > 1.0e-15))
  {
    return HUGE_VAL;
  }
  return (k[1] + 2.0 * k[2] * farthest) / (denominator * denominator);
}

//------------------------------------------------------------------------------
vtkPhongAttenuation vtkPhongAttenuation::Scaled(double scale) const
{
  vtkPhongAttenuation scaled;
  scaled.Coefficients = { { this->Coefficients[0], this->Coefficients[1] * scale,
    this->Coefficients[2] * scale * scale } };
  return scaled;
}
