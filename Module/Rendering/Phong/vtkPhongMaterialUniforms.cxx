#include "vtkPhongMaterialUniforms.h"

#include "vtkPhongMaterial.h"
#include "vtkPhongProblemLog.h"
#include "vtkPhongProperty.h"
#include "vtkProperty.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
vtkPhongMaterialUniforms::vtkPhongMaterialUniforms(
  vtkShaderProgram* program, const Plan& plan, vtkPhongProblemLog& log)
  : Program(program)
  , ThePlan(plan)
  , Log(log)
{
}

//------------------------------------------------------------------------------
void vtkPhongMaterialUniforms::Upload()
{
  vtkPhongUniformValues values = this->Values();
  if (this->ThePlan.Has(vtkPhongFeature::DebugBudget))
  {
    values.push_back(vtkPhongUniformValue::Vec3("phongBudgetUse", BudgetUseColor(this->ThePlan)));
  }
  vtkPhongUniformValue::Upload(this->Program, values);
}

//------------------------------------------------------------------------------
vtkPhongUniformValues vtkPhongMaterialUniforms::Values()
{
  vtkPhongUniformValues values;
  this->AddSide(this->ThePlan.FrontMaterial, "", true, values);
  this->AddProducts(values);
  // VTK declares back-face uniforms when the actor has a back property; with one-sided
  // lighting the contract uses the front material on both faces.
  this->AddSide(this->ThePlan.BackMaterial, "BF",
    this->ThePlan.BackMaterial != this->ThePlan.FrontMaterial, values);
  return values;
}

//------------------------------------------------------------------------------
// The BudgetUse view's colour (vtkPhongLightingSettings::DebugViews): the mode's hue, its
// brightness from 0.25 (nothing of the budget spent) to 1 (all of it).
vtkPhongMaterialUniforms::RGB vtkPhongMaterialUniforms::BudgetUseColor(const Plan& plan)
{
  static const RGB hues[3] = { { { 0.0f, 0.4f, 1.0f } }, { { 0.0f, 1.0f, 0.3f } },
    { { 1.0f, 0.4f, 0.0f } } };
  const RGB& hue = hues[std::min(std::max(plan.BudgetMode, 0), 2)];
  const double share = std::min(std::max(plan.BudgetShare, 0.0), 1.0);
  const auto brightness = static_cast<float>(0.25 + 0.75 * share);
  return { { brightness * hue[0], brightness * hue[1], brightness * hue[2] } };
}

//------------------------------------------------------------------------------
// The selection of material per face is VTK's (Color::Impl); only values change here. Every
// value is checked (and a problem reported) whether or not the variant reads it.
void vtkPhongMaterialUniforms::AddSide(
  vtkProperty* material, const char* suffix, bool report, vtkPhongUniformValues& out)
{
  this->Side = suffix;
  this->SideName = this->Side.empty() ? "front" : "back";
  this->Report = report;
  const double shininess = vtkPhongMaterial::ShininessOf(material);
  const double normalization = vtkPhongMaterial::LobeNormalization(
    vtkPhongMaterial::LightingModelOf(this->ThePlan.FrontMaterial), shininess);

  const RGB ambientColor = this->CheckedColor(material->GetAmbientColor(), 1.0, "ambient");
  const RGB diffuseColor = this->CheckedColor(material->GetDiffuseColor(), 1.0, "diffuse");
  const RGB specularColor =
    this->CheckedColor(material->GetSpecularColor(), normalization, "specular");
  const float opacity = this->CheckedCoefficient(material->GetOpacity(), "opacity");
  const float ambient = this->CheckedCoefficient(material->GetAmbient(), "ambient");
  const float diffuse = this->CheckedCoefficient(material->GetDiffuse(), "diffuse");
  const float specular = this->CheckedCoefficient(material->GetSpecular(), "specular");
  const std::string& side = this->Side;
  const auto Stock = vtkPhongUniformValue::Source::StockMaterial;
  out.push_back(vtkPhongUniformValue::Vec3("ambientColorUniform" + side, ambientColor, Stock));
  out.push_back(vtkPhongUniformValue::Vec3("diffuseColorUniform" + side, diffuseColor, Stock));
  out.push_back(vtkPhongUniformValue::Float("opacityUniform" + side, opacity, Stock));
  out.push_back(vtkPhongUniformValue::Float("ambientIntensity" + side, ambient, Stock));
  out.push_back(vtkPhongUniformValue::Float("diffuseIntensity" + side, diffuse, Stock));
  if (this->ThePlan.Has(vtkPhongFeature::Specular))
  {
    out.push_back(vtkPhongUniformValue::Float("specularIntensity" + side, specular, Stock));
    out.push_back(vtkPhongUniformValue::Vec3("specularColorUniform" + side, specularColor, Stock));
    out.push_back(vtkPhongUniformValue::Float("specularPowerUniform" + side,
      static_cast<float>(this->Log.Bounded(
        shininess, vtkPhongProblemLog::LargestValue,
        [&](std::ostream& os) { os << "The " << this->SideName << " material's shininess"; },
        this->Report)),
      Stock));
  }
}

//------------------------------------------------------------------------------
vtkPhongMaterialUniforms::RGB vtkPhongMaterialUniforms::CheckedColor(
  const double* color, double scale, const char* which)
{
  RGB out;
  for (int c = 0; c < 3; ++c)
  {
    const double value = this->Log.Finite(color[c], this->Report,
      [&](std::ostream& os)
      {
        os << "The " << this->SideName << " material's " << which << " colour component "
           << color[c] << " is not finite; it is treated as 0.";
      });
    out[c] = static_cast<float>(this->Log.Bounded(
      value * scale, vtkPhongProblemLog::LargestValue,
      [&](std::ostream& os)
      { os << "The " << this->SideName << " material's " << which << " colour component"; },
      this->Report));
  }
  return out;
}

//------------------------------------------------------------------------------
float vtkPhongMaterialUniforms::CheckedCoefficient(double value, const char* which)
{
  const double finite = this->Log.Finite(value, this->Report,
    [&](std::ostream& os)
    {
      os << "The " << this->SideName << " material's " << which << " coefficient " << value
         << " is not finite; it is treated as 0.";
    });
  return static_cast<float>(this->Log.Bounded(
    finite, vtkPhongProblemLog::LargestValue,
    [&](std::ostream& os)
    { os << "The " << this->SideName << " material's " << which << " coefficient"; },
    this->Report));
}

//------------------------------------------------------------------------------
// The ready-made products of MATERIAL_UNIFORMS (front material only: that variant has no
// back material), which vtkPhongShaderTemplate decides from VTK's shader: given always, used
// by that variant alone.
void vtkPhongMaterialUniforms::AddProducts(vtkPhongUniformValues& out) const
{
  vtkProperty* front = this->ThePlan.FrontMaterial;
  const double specularScale = vtkPhongMaterial::LobeNormalization(
    vtkPhongMaterial::LightingModelOf(front), vtkPhongMaterial::ShininessOf(front));
  auto product = [&](const char* name, double coefficient, const double* color, double scale)
  {
    const double scales[3] = { scale, scale, scale };
    float value[3];
    vtkPhongMaterial::FiniteProduct(coefficient, color, scales, value);
    out.push_back(vtkPhongUniformValue::Vec3(name, value, vtkPhongUniformValue::Source::Material));
  };
  product("phongMaterialAmbient", front->GetAmbient(), front->GetAmbientColor(), 1.0);
  product("phongMaterialDiffuse", front->GetDiffuse(), front->GetDiffuseColor(), 1.0);
  product("phongMaterialSpecular", front->GetSpecular(), front->GetSpecularColor(), specularScale);
}
