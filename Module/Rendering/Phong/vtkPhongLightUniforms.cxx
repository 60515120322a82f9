#include "vtkPhongLightUniforms.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPhongLightingSettings.h"
#include "vtkPhongMaterial.h"
#include "vtkPhongProblemLog.h"
#include "vtkPhongProperty.h"
#include "vtkTransform.h"

#include <algorithm>
#include <cmath>

namespace
{
using Feature = vtkPhongFeature;
using Source = vtkPhongUniformValue::Source;

const char* LightKindName(vtkLight* light)
{
  if (light->LightTypeIsHeadlight())
  {
    return "headlight";
  }
  return light->LightTypeIsCameraLight() ? "camera light" : "scene light";
}

template <typename T>
void AppendRGB(std::vector<float>& packed, const T& rgb)
{
  packed.insert(packed.end(),
    { static_cast<float>(rgb[0]), static_cast<float>(rgb[1]), static_cast<float>(rgb[2]) });
}

}

//------------------------------------------------------------------------------
vtkPhongLightUniforms::vtkPhongLightUniforms(
  vtkShaderProgram* program, vtkRenderer* ren, const Plan& plan, vtkPhongProblemLog& log)
  : Program(program)
  , Renderer(ren)
  , ThePlan(plan)
  , Log(log)
{
  int index = 0;
  for (vtkLight* light : vtkPhongLightGeometry::SwitchedOn(ren))
  {
    this->LightIndex[light] = index++;
  }
}

//------------------------------------------------------------------------------
void vtkPhongLightUniforms::Upload()
{
  vtkPhongUniformValue::Upload(this->Program, this->Values());
}

//------------------------------------------------------------------------------
vtkPhongUniformValues vtkPhongLightUniforms::Values()
{
  vtkPhongUniformValues arrays;
  std::fill(std::begin(this->AmbientLight), std::end(this->AmbientLight), 0.0);
  this->ReadSceneAmbient();
  this->AddDirectional(arrays);
  if (this->ThePlan.Has(Feature::Point))
  {
    this->AddPositional(this->ThePlan.PointLights, "phongPointLight", false, arrays);
  }
  if (this->ThePlan.Has(Feature::Spot))
  {
    this->AddPositional(this->ThePlan.SpotLights, "phongSpotLight", true, arrays);
  }
  this->AddAmbient(arrays); // after the directional lights, which add their ambient colours
  this->AddEmission(arrays);
  return arrays;
}

//------------------------------------------------------------------------------
// The light's index among the renderer's switched-on lights (0 for the all-features
// variant's placeholders, which are not the renderer's).
int vtkPhongLightUniforms::IndexOf(vtkLight* light) const
{
  auto found = this->LightIndex.find(light);
  return found == this->LightIndex.end() ? 0 : found->second;
}

//------------------------------------------------------------------------------
// A light's colours times its intensity, zero for lights hidden by the single-light view.
vtkPhongLightUniforms::LightValues vtkPhongLightUniforms::ValuesOf(vtkLight* light)
{
  LightValues values;
  if (this->ThePlan.DebugView == vtkPhongLightingSettings::SingleLight &&
    light != this->ThePlan.DebugLight)
  {
    return values;
  }
  const double intensity = this->Log.NonNegative(light->GetIntensity(),
    [&](std::ostream& os)
    {
      os << "Light " << this->IndexOf(light) << " (" << LightKindName(light) << ") has intensity "
         << light->GetIntensity()
         << "; lights need a finite intensity >= 0, so it is treated as 0.";
    });
  values.Ambient = this->ScaledColor(light, light->GetAmbientColor(), intensity, "ambient");
  values.Diffuse = this->ScaledColor(light, light->GetDiffuseColor(), intensity, "diffuse");
  values.Specular = this->ScaledColor(light, light->GetSpecularColor(), intensity, "specular");
  return values;
}

//------------------------------------------------------------------------------
vtkPhongLightUniforms::RGB vtkPhongLightUniforms::ScaledColor(
  vtkLight* light, const double* color, double intensity, const char* which)
{
  RGB scaled;
  for (int c = 0; c < 3; ++c)
  {
    const double value = this->Log.NonNegative(color[c],
      [&](std::ostream& os)
      {
        os << "Light " << this->IndexOf(light) << " (" << LightKindName(light) << ") has " << which
           << " colour component " << color[c]
           << "; colours must be finite and >= 0, so it is treated as 0.";
      });
    scaled[c] =
      static_cast<float>(this->Log.Bounded(value * intensity, vtkPhongProblemLog::LargestValue,
        [&](std::ostream& os)
        {
          os << "Light " << this->IndexOf(light) << " (" << LightKindName(light) << ") " << which
             << " colour times intensity";
        }));
  }
  return scaled;
}

//------------------------------------------------------------------------------
// Ia, the renderer's ambient light (none in the single-light view).
void vtkPhongLightUniforms::ReadSceneAmbient()
{
  if (this->ThePlan.DebugView == vtkPhongLightingSettings::SingleLight)
  {
    return;
  }
  const double* ia = this->Renderer->GetAmbient();
  for (int c = 0; c < 3; ++c)
  {
    const double component = this->Log.NonNegative(ia[c],
      [&](std::ostream& os)
      {
        os << "The renderer's ambient light component " << ia[c]
           << " is not a finite value >= 0; it is treated as 0.";
      });
    this->AmbientLight[c] = this->Log.Bounded(component, vtkPhongProblemLog::LargestValue,
      [](std::ostream& os) { os << "The renderer's ambient light component"; });
  }
}

//------------------------------------------------------------------------------
// Directional lights: the direction towards the light, the colours, and their ambient
// colours added to the ambient light, which is the same everywhere.
void vtkPhongLightUniforms::AddDirectional(vtkPhongUniformValues& out)
{
  std::vector<float> toLight, diffuse, specular;
  for (vtkLight* light : this->ThePlan.DirectionalLights)
  {
    const LightValues values = this->ValuesOf(light);
    for (int c = 0; c < 3; ++c)
    {
      this->AmbientLight[c] += values.Ambient[c];
    }
    const vtkPhongLightGeometry geometry = vtkPhongLightGeometry::InView(light, this->Renderer);
    if (!geometry.HasDirection)
    {
      this->Log.Report(
        [&](std::ostream& os)
        {
          os << "Directional light " << this->IndexOf(light) << " (" << LightKindName(light)
             << ") has its focal point at its position and so no direction; it shines "
                "along the view direction.";
        });
    }
    const double towardsLight[3] = { -geometry.DirectionVC[0], -geometry.DirectionVC[1],
      -geometry.DirectionVC[2] };
    AppendRGB(toLight, towardsLight);
    AppendRGB(diffuse, values.Diffuse);
    AppendRGB(specular, values.Specular);
  }
  if (this->ThePlan.Has(Feature::Directional))
  {
    out.push_back(
      vtkPhongUniformValue::Vec3Array("phongDirectionalLightToLightVC", std::move(toLight)));
    this->AddColors("phongDirectionalLight", diffuse, specular, out);
  }
}

//------------------------------------------------------------------------------
// The diffuse and specular colours of one light kind. Without SEPARATE_SPECULAR_COLORS every
// light's specular colour, as uploaded, is its diffuse colour (vtkPhongShaderPlanner compares
// the same floats), the specular sums read the diffuse array, and no specular array exists.
void vtkPhongLightUniforms::AddColors(const std::string& prefix, const std::vector<float>& diffuse,
  const std::vector<float>& specular, vtkPhongUniformValues& out) const
{
  if (this->ThePlan.Has(Feature::Diffuse))
  {
    out.push_back(vtkPhongUniformValue::Vec3Array(prefix + "Diffuse", diffuse));
  }
  if (this->ThePlan.Has(Feature::SeparateSpecularColors))
  {
    out.push_back(vtkPhongUniformValue::Vec3Array(prefix + "Specular", specular));
  }
}

//------------------------------------------------------------------------------
// The ambient light as the fragment shader takes it: alone, or times the material's ka*Ca
// (MATERIAL_UNIFORMS, which vtkPhongShaderTemplate decides from VTK's shader; both are given,
// and the program uses one).
void vtkPhongLightUniforms::AddAmbient(vtkPhongUniformValues& out) const
{
  if (!this->ThePlan.Has(Feature::Ambient))
  {
    return;
  }
  out.push_back(vtkPhongUniformValue::Vec3("phongAmbientLight", this->AmbientLight));
  // The material's values as vtkPhongMaterialUniforms checks (and reports) them.
  vtkProperty* material = this->ThePlan.FrontMaterial;
  float term[3];
  vtkPhongMaterial::FiniteProduct(
    material->GetAmbient(), material->GetAmbientColor(), this->AmbientLight, term);
  out.push_back(vtkPhongUniformValue::Vec3("phongAmbientTerm", term, Source::Material));
}

//------------------------------------------------------------------------------
// Attenuation coefficients as uploaded: finite and >= 0.
vtkPhongLightUniforms::RGB vtkPhongLightUniforms::AttenuationOf(vtkLight* light)
{
  RGB attenuation;
  const double* values = light->GetAttenuationValues();
  for (int c = 0; c < 3; ++c)
  {
    const double coefficient = this->Log.NonNegative(values[c],
      [&](std::ostream& os)
      {
        os << "Positional light " << this->IndexOf(light) << " has attenuation coefficient "
           << values[c] << "; coefficients must be finite and >= 0, so it is treated as 0.";
      });
    attenuation[c] =
      static_cast<float>(this->Log.Bounded(coefficient, vtkPhongProblemLog::LargestAttenuation,
        [&](std::ostream& os)
        { os << "Positional light " << this->IndexOf(light) << " attenuation coefficient"; }));
  }
  return attenuation;
}

//------------------------------------------------------------------------------
// A spot's axis, cone, falloff exponent and soft edge.
void vtkPhongLightUniforms::AddSpot(
  vtkLight* light, const vtkPhongLightGeometry& geometry, PositionalArrays& arrays)
{
  if (!geometry.HasDirection)
  {
    this->Log.Report(
      [&](std::ostream& os)
      {
        os << "Spot light " << this->IndexOf(light)
           << " has its focal point at its position and so no axis; it points along "
              "the view direction.";
      });
  }
  AppendRGB(arrays.AxisVC, geometry.DirectionVC);
  // cos() of a NaN or infinite cone would make every fragment's spot test NaN.
  const double cone = this->Log.NonNegative(light->GetConeAngle(),
    [&](std::ostream& os)
    {
      os << "Spot light " << this->IndexOf(light) << " has cone angle " << light->GetConeAngle()
         << "; cone angles must be finite and >= 0, so it is treated as 0.";
    });
  arrays.CosCutoff.push_back(static_cast<float>(std::cos(vtkMath::RadiansFromDegrees(cone))));
  const double exponent = this->Log.NonNegative(light->GetExponent(),
    [&](std::ostream& os)
    {
      os << "Spot light " << this->IndexOf(light) << " has exponent " << light->GetExponent()
         << "; spot exponents must be finite and >= 0, so it is treated as 0.";
    });
  arrays.Exponent.push_back(
    static_cast<float>(this->Log.Bounded(exponent, vtkPhongProblemLog::LargestValue,
      [&](std::ostream& os) { os << "Spot light " << this->IndexOf(light) << " exponent"; })));
  // Without the soft edge option the band has no width (a hard edge), also in the
  // all-features variant, which evaluates the smoothstep anyway.
  auto* phongFront = vtkPhongProperty::SafeDownCast(this->ThePlan.FrontMaterial);
  const double edgeWidth =
    (phongFront && phongFront->GetSoftSpotEdge()) ? phongFront->GetSpotEdgeWidth() : 0.0;
  // smoothstep needs its two edges apart; a zero-width band is a hard edge.
  const double inner = std::cos(vtkMath::RadiansFromDegrees(std::max(cone - edgeWidth, 0.0)));
  arrays.CosInner.push_back(static_cast<float>(std::max(inner, arrays.CosCutoff.back() + 1.0e-6)));
}

//------------------------------------------------------------------------------
void vtkPhongLightUniforms::AddPositional(
  const std::vector<vtkLight*>& lights, const char* prefix, bool isSpot, vtkPhongUniformValues& out)
{
  PositionalArrays arrays;
  for (vtkLight* light : lights)
  {
    const LightValues values = this->ValuesOf(light);
    const vtkPhongLightGeometry geometry = vtkPhongLightGeometry::InView(light, this->Renderer);
    double positionVC[3];
    for (int i = 0; i < 3; ++i)
    {
      positionVC[i] =
        this->Log.Bounded(geometry.PositionVC[i], vtkPhongProblemLog::LargestCoordinate,
          [&](std::ostream& os)
          { os << "Light " << this->IndexOf(light) << " position component (view coordinates)"; });
    }
    AppendRGB(arrays.PositionVC, positionVC);
    AppendRGB(arrays.Attenuation, this->AttenuationOf(light));
    AppendRGB(arrays.Ambient, values.Ambient);
    AppendRGB(arrays.Diffuse, values.Diffuse);
    AppendRGB(arrays.Specular, values.Specular);
    if (isSpot)
    {
      this->AddSpot(light, geometry, arrays);
    }
  }
  const std::string name(prefix);
  const Plan& plan = this->ThePlan;
  out.push_back(vtkPhongUniformValue::Vec3Array(name + "PositionVC", std::move(arrays.PositionVC)));
  if (plan.Has(isSpot ? Feature::SpotAttenuation : Feature::PointAttenuation))
  {
    out.push_back(
      vtkPhongUniformValue::Vec3Array(name + "Attenuation", std::move(arrays.Attenuation)));
  }
  if (plan.Has(Feature::PositionalAmbient))
  {
    out.push_back(vtkPhongUniformValue::Vec3Array(name + "Ambient", std::move(arrays.Ambient)));
  }
  this->AddColors(name, arrays.Diffuse, arrays.Specular, out);
  if (isSpot)
  {
    this->AddSpotArrays(name, arrays, out);
  }
}

//------------------------------------------------------------------------------
void vtkPhongLightUniforms::AddSpotArrays(
  const std::string& prefix, PositionalArrays& arrays, vtkPhongUniformValues& out) const
{
  out.push_back(vtkPhongUniformValue::Vec3Array(prefix + "AxisVC", std::move(arrays.AxisVC)));
  out.push_back(
    vtkPhongUniformValue::FloatArray(prefix + "CosCutoff", std::move(arrays.CosCutoff)));
  if (this->ThePlan.Has(Feature::SpotFalloff))
  {
    out.push_back(
      vtkPhongUniformValue::FloatArray(prefix + "Exponent", std::move(arrays.Exponent)));
  }
  if (this->ThePlan.Has(Feature::SoftSpotEdge))
  {
    out.push_back(
      vtkPhongUniformValue::FloatArray(prefix + "CosInner", std::move(arrays.CosInner)));
  }
}

//------------------------------------------------------------------------------
// Ke of each side, and the back side's shininess (VTK has no uniform for it).
void vtkPhongLightUniforms::AddEmission(vtkPhongUniformValues& out)
{
  const Plan& plan = this->ThePlan;
  if (plan.Has(Feature::Emission))
  {
    auto emissionOf = [this](vtkProperty* material, const char* side)
    {
      auto* phong = vtkPhongProperty::SafeDownCast(material);
      RGB emission = { 0.f, 0.f, 0.f };
      for (int c = 0; phong && c < 3; ++c)
      {
        emission[c] = static_cast<float>(this->Log.Bounded(phong->GetEmission()[c],
          vtkPhongProblemLog::LargestValue,
          [side](std::ostream& os) { os << "The " << side << " material's emission component"; }));
      }
      return emission;
    };
    out.push_back(vtkPhongUniformValue::Vec3(
      "phongEmission", emissionOf(plan.FrontMaterial, "front"), Source::Material));
    if (plan.Has(Feature::BackMaterial))
    {
      out.push_back(vtkPhongUniformValue::Vec3(
        "phongEmissionBF", emissionOf(plan.BackMaterial, "back"), Source::Material));
    }
  }
  if (plan.Has(Feature::TwoSided))
  {
    const double shininess = vtkPhongMaterial::ShininessOf(plan.BackMaterial);
    out.push_back(vtkPhongUniformValue::Float("phongShininessBF",
      static_cast<float>(std::min(shininess, vtkPhongProblemLog::LargestValue)), Source::Material));
  }
}
