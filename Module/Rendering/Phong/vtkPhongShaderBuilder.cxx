#include "vtkPhongShaderBuilder.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCollectionIterator.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightingMapPass.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPhongPolyDataMapper.h"
#include "vtkPhongProperty.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTransform.h"

#include "vtkPhongFS.h"
#include "vtkPhongGS.h"
#include "vtkPhongLightingLib.h"
#include "vtkPhongVS.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkPhongShaderBuilder);

namespace
{
using RGB = std::array<float, 3>;
using View = vtkPhongPolyDataMapper; // for its DebugViews values

const char* LightKindName(vtkLight* light)
{
  if (light->LightTypeIsHeadlight())
  {
    return "headlight";
  }
  return light->LightTypeIsCameraLight() ? "camera light" : "scene light";
}

double ShininessOf(vtkProperty* material)
{
  auto* phong = vtkPhongProperty::SafeDownCast(material);
  return phong ? phong->GetShininess() : material->GetSpecularPower();
}

int LightingModelOf(vtkProperty* material)
{
  auto* phong = vtkPhongProperty::SafeDownCast(material);
  return phong ? phong->GetLightingModel() : vtkPhongProperty::Phong;
}

// The energy normalization of the lobe, folded into the specular colour on the CPU.
double LobeNormalization(int lightingModel, double shininess)
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

bool IsPositive(double value)
{
  return value > 0.0; // false for NaN too
}

// The value a light parameter is uploaded with: finite and >= 0, else 0 (the
// problem is reported where the value is uploaded).
double Sanitized(double value)
{
  return (value >= 0.0 && std::isfinite(value)) ? value : 0.0;
}

// Whether a light adds ambient light: its ambient colour times its intensity is not black.
bool HasAmbientLight(vtkLight* light)
{
  const double* color = light->GetAmbientColor();
  return IsPositive(Sanitized(light->GetIntensity())) &&
    (IsPositive(Sanitized(color[0])) || IsPositive(Sanitized(color[1])) ||
      IsPositive(Sanitized(color[2])));
}

// Whether a positional light fades with distance: (c, l, q) is not (1, 0, 0).
bool IsAttenuated(vtkLight* light)
{
  const double* values = light->GetAttenuationValues();
  return Sanitized(values[0]) != 1.0 || Sanitized(values[1]) != 0.0 || Sanitized(values[2]) != 0.0;
}

// Whether a spot's light falls off inside its cone: its exponent is not 1.
bool HasSpotFalloff(vtkLight* light)
{
  return Sanitized(light->GetExponent()) != 1.0;
}

// Strip leading blanks, for matching template directives.
std::string TrimLeft(const std::string& line)
{
  const auto first = line.find_first_not_of(" \t");
  return first == std::string::npos ? std::string() : line.substr(first);
}
}

//------------------------------------------------------------------------------
vtkPhongShaderBuilder::vtkPhongShaderBuilder()
{
  this->PlaceholderDirectional->SetIntensity(0.0);
  this->PlaceholderPoint->SetIntensity(0.0);
  this->PlaceholderPoint->PositionalOn();
  this->PlaceholderPoint->SetConeAngle(180.0);
  this->PlaceholderSpot->SetIntensity(0.0);
  this->PlaceholderSpot->PositionalOn();
  this->PlaceholderSpot->SetConeAngle(45.0);
  this->PlaceholderSpot->SetExponent(2.0);
  this->PlaceholderSpot->SetAttenuationValues(1.0, 0.1, 0.1);
  this->PlaceholderPoint->SetAttenuationValues(1.0, 0.1, 0.1);
  this->PlaceholderPoint->SetAmbientColor(1.0, 1.0, 1.0);
}

//------------------------------------------------------------------------------
vtkPhongShaderBuilder::~vtkPhongShaderBuilder() = default;

//------------------------------------------------------------------------------
void vtkPhongShaderBuilder::AddProblem(const std::string& problem)
{
  this->Problems.insert(problem);
}

//------------------------------------------------------------------------------
std::string vtkPhongShaderBuilder::TakeProblems()
{
  std::string text;
  for (const auto& problem : this->Problems)
  {
    text += problem + "\n";
  }
  this->Problems.clear();
  return text;
}

//------------------------------------------------------------------------------
vtkPhongShaderBuilder::Plan vtkPhongShaderBuilder::MakePlan(
  vtkRenderer* ren, vtkActor* actor, const PrimitiveState& state, const Options& options)
{
  Plan plan;
  vtkProperty* front = actor->GetProperty();
  if (state.DrawingVertices || state.DrawingSelection || front->GetInterpolation() == VTK_PBR)
  {
    return plan;
  }
  vtkInformation* keys = actor->GetPropertyKeys();
  if (keys &&
    (keys->Has(vtkLightingMapPass::RENDER_NORMALS()) ||
      keys->Has(vtkLightingMapPass::RENDER_LUMINANCE())))
  {
    return plan;
  }

  std::vector<vtkLight*> switchedOn;
  vtkLightCollection* lights = ren->GetLights();
  vtkCollectionSimpleIterator it;
  vtkLight* light;
  for (lights->InitTraversal(it); (light = lights->GetNextLight(it));)
  {
    if (light->GetSwitch())
    {
      switchedOn.push_back(light);
    }
  }

  // VTK lights a primitive when it has at least one light; the equation still
  // holds without lights (emission and ka*Ca*Ia), for surfaces VTK would light.
  const bool lit = state.LightComplexity > 0;
  const bool litWithoutLights =
    !lit && switchedOn.empty() && front->GetLighting() && state.IsTriangles;
  if (!lit && !litWithoutLights)
  {
    return plan;
  }
  const bool geometryView = options.DebugView == View::ShadingNormal ||
    options.DebugView == View::PositionVC || options.DebugView == View::NormalVC;
  if (litWithoutLights && geometryView)
  {
    return plan; // VTK provides no normal or view-space position to an unlit primitive
  }
  plan.Handled = true;
  plan.DebugView = options.DebugView;

  for (vtkLight* switchedOnLight : switchedOn)
  {
    if (!switchedOnLight->GetPositional())
    {
      plan.DirectionalLights.push_back(switchedOnLight);
    }
    else if (switchedOnLight->GetConeAngle() < 90.0)
    {
      plan.SpotLights.push_back(switchedOnLight);
    }
    else
    {
      plan.PointLights.push_back(switchedOnLight);
    }
  }
  if (options.DebugView == View::SingleLight)
  {
    if (options.DebugLightIndex >= 0 &&
      options.DebugLightIndex < static_cast<int>(switchedOn.size()))
    {
      plan.DebugLight = switchedOn[options.DebugLightIndex];
    }
    else
    {
      std::ostringstream problem;
      problem << "DebugLightIndex " << options.DebugLightIndex
              << " names no light: the renderer has " << switchedOn.size()
              << " switched-on lights; the single-light view is black.";
      this->AddProblem(problem.str());
    }
  }

  const bool twoSided = ren->GetTwoSidedLighting() != 0;
  vtkProperty* back =
    (twoSided && actor->GetBackfaceProperty()) ? actor->GetBackfaceProperty() : front;
  plan.FrontMaterial = front;
  plan.BackMaterial = back;

  const int view = options.DebugView;
  const bool wantAmbient =
    view == View::Final || view == View::AmbientTerm || view == View::SingleLight;
  const bool wantDiffuse =
    view == View::Final || view == View::DiffuseTerm || view == View::SingleLight;
  const bool wantSpecular =
    view == View::Final || view == View::SpecularTerm || view == View::SingleLight;
  const bool wantEmission = view == View::Final || view == View::EmissionTerm;
  const bool haveLights = !switchedOn.empty();

  auto& flags = plan.Flags;
  // The all-features variant keeps every optional term and needs a light of each kind: the
  // kinds the scene lacks get a placeholder that adds nothing.
  const bool all = !options.Specialize;
  if (all)
  {
    if (plan.DirectionalLights.empty())
    {
      plan.DirectionalLights.push_back(this->PlaceholderDirectional);
    }
    if (plan.PointLights.empty())
    {
      plan.PointLights.push_back(this->PlaceholderPoint);
    }
    if (plan.SpotLights.empty())
    {
      plan.SpotLights.push_back(this->PlaceholderSpot);
    }
  }
  const bool ambient =
    wantAmbient && (all || IsPositive(front->GetAmbient()) || IsPositive(back->GetAmbient()));
  const bool diffuse = wantDiffuse && (haveLights || all) &&
    (all || IsPositive(front->GetDiffuse()) || IsPositive(back->GetDiffuse()));
  const bool specular = wantSpecular && (haveLights || all) &&
    (all || IsPositive(front->GetSpecular()) || IsPositive(back->GetSpecular()));
  const bool emission = wantEmission &&
    (all || vtkPhongProperty::SafeDownCast(front) || vtkPhongProperty::SafeDownCast(back));
  const bool positional = !plan.PointLights.empty() || !plan.SpotLights.empty();
  // Light values that are zero have no code, as a zero material coefficient has none: the
  // ambient light of positional lights that give none, the distance attenuation of lights
  // with (c, l, q) = (1, 0, 0), the falloff of spots with exponent 1.
  auto any = [](const std::vector<vtkLight*>& lights, bool (*test)(vtkLight*))
  { return std::any_of(lights.begin(), lights.end(), test); };
  const bool positionalAmbient = ambient && positional &&
    (all || any(plan.PointLights, HasAmbientLight) || any(plan.SpotLights, HasAmbientLight));
  const bool lightSums = diffuse || specular || positionalAmbient;

  auto set = [&flags](const char* flag, bool on)
  {
    if (on)
    {
      flags.insert(flag);
    }
  };
  set("AMBIENT", ambient);
  set("DIFFUSE", diffuse);
  set("SPECULAR", specular);
  set("DIFFUSE_OR_SPECULAR", diffuse || specular);
  set("EMISSION", emission);
  set("POSITIONAL_AMBIENT", positionalAmbient);
  set("LIGHT_SUMS", lightSums);
  set("DIRECTIONAL", (diffuse || specular) && !plan.DirectionalLights.empty());
  set("POINT", lightSums && !plan.PointLights.empty());
  set("SPOT", lightSums && !plan.SpotLights.empty());
  set("POSITIONAL", lightSums && positional);
  const bool pointAttenuation =
    flags.count("POINT") && (all || any(plan.PointLights, IsAttenuated));
  const bool spotAttenuation = flags.count("SPOT") && (all || any(plan.SpotLights, IsAttenuated));
  set("POINT_ATTENUATION", pointAttenuation);
  set("SPOT_ATTENUATION", spotAttenuation);
  set("ATTENUATION", pointAttenuation || spotAttenuation);
  set("SPOT_FALLOFF", flags.count("SPOT") && (all || any(plan.SpotLights, HasSpotFalloff)));

  auto* phongFront = vtkPhongProperty::SafeDownCast(front);
  if (specular)
  {
    const int model = LightingModelOf(front);
    const bool blinn =
      model == vtkPhongProperty::BlinnPhong || model == vtkPhongProperty::NormalizedBlinnPhong;
    set("LOBE_BLINN", blinn);
    set("LOBE_PHONG", !blinn);
    set("SMOOTH_TERMINATOR", phongFront && phongFront->GetSmoothTerminator());
  }
  set("SOFT_SPOT_EDGE",
    flags.count("SPOT") && (all || (phongFront && phongFront->GetSoftSpotEdge())));

  vtkCamera* camera = ren->GetActiveCamera();
  set("PARALLEL", camera && camera->GetParallelProjection());

  const bool perVertex = lightSums && phongFront && phongFront->GetPerVertexGouraud() &&
    front->GetInterpolation() == VTK_GOURAUD && state.HasPointNormals && !state.NormalsFromShape &&
    !geometryView;
  set("PER_VERTEX", perVertex);
  set("SUMS_PER_VERTEX", lightSums && perVertex);
  set("SUMS_PER_FRAGMENT", lightSums && !perVertex);
  set("GEOMETRY_PASS_THROUGH", perVertex && state.HasGeometryShader);
  set("TWO_SIDED", twoSided);
  set("BACK_MATERIAL", back != front);
  set("DEBUG_NORMAL", view == View::ShadingNormal);
  set("DEBUG_NORMAL_VC", view == View::NormalVC);
  set("DEBUG_POSITION_VC", view == View::PositionVC);

  const bool normalView = view == View::ShadingNormal || view == View::NormalVC;
  const bool shadingNormal = (lightSums && !perVertex) || normalView;
  set("SHADING_NORMAL", shadingNormal);
  set("ONE_SIDED", shadingNormal && !twoSided);
  // Zero, NaN or infinite normals in the data take the face's geometric normal
  // from screen-space derivatives, which cost every fragment: only when the
  // mapper found such normals. Otherwise a cheap guard covers normals that
  // cancel out when interpolated.
  const bool normalFallback = shadingNormal && (state.NormalsMayBeInvalid || all) &&
    (state.HasPointNormals || state.HasCellNormals) && !state.NormalsFromShape;
  set("NORMAL_FALLBACK", normalFallback);
  set("VIEW_VECTOR", shadingNormal);

  std::ostringstream signature;
  for (const auto& flag : flags)
  {
    signature << flag << ' ';
  }
  signature << "| directional " << (flags.count("DIRECTIONAL") ? plan.DirectionalLights.size() : 0)
            << " point " << (flags.count("POINT") ? plan.PointLights.size() : 0) << " spot "
            << (flags.count("SPOT") ? plan.SpotLights.size() : 0) << " | view " << view
            << (all ? " | all features" : "");
  plan.Signature = signature.str();
  return plan;
}

//------------------------------------------------------------------------------
std::string vtkPhongShaderBuilder::ResolveTemplate(
  const char* templateText, const char* section, const Plan& plan)
{
  const std::map<std::string, std::string> placeholders = {
    { "@DIRECTIONAL_COUNT@", std::to_string(plan.DirectionalLights.size()) },
    { "@POINT_COUNT@", std::to_string(plan.PointLights.size()) },
    { "@SPOT_COUNT@", std::to_string(plan.SpotLights.size()) },
  };
  const std::string sectionLine = std::string("//PHONG_SECTION ") + section;

  std::istringstream input(templateText);
  std::string line;
  std::string output;
  bool inSection = false;
  bool sectionFound = false;
  std::vector<bool> active; // one entry per open //PHONG_IF
  int lineNumber = 0;
  while (std::getline(input, line))
  {
    ++lineNumber;
    const std::string trimmed = TrimLeft(line);
    if (trimmed.compare(0, 16, "//PHONG_SECTION ") == 0)
    {
      if (inSection && !active.empty())
      {
        vtkErrorMacro("Template section " << section << " ends with an open //PHONG_IF.");
      }
      inSection = (trimmed == sectionLine);
      sectionFound = sectionFound || inSection;
      active.clear();
      continue;
    }
    if (!inSection)
    {
      continue;
    }
    const bool enclosingActive = active.empty() || active.back();
    if (trimmed.compare(0, 11, "//PHONG_IF ") == 0)
    {
      std::string condition = TrimLeft(trimmed.substr(11));
      condition.erase(condition.find_last_not_of(" \t\r") + 1);
      const bool negate = !condition.empty() && condition[0] == '!';
      const bool present = plan.Has(negate ? condition.c_str() + 1 : condition.c_str());
      active.push_back(enclosingActive && (negate ? !present : present));
      continue;
    }
    if (trimmed.compare(0, 13, "//PHONG_ENDIF") == 0)
    {
      if (active.empty())
      {
        vtkErrorMacro("Unbalanced //PHONG_ENDIF at template line " << lineNumber << ".");
      }
      else
      {
        active.pop_back();
      }
      continue;
    }
    if (!enclosingActive)
    {
      continue;
    }
    for (const auto& placeholder : placeholders)
    {
      for (auto at = line.find(placeholder.first); at != std::string::npos;
           at = line.find(placeholder.first, at))
      {
        line.replace(at, placeholder.first.size(), placeholder.second);
      }
    }
    if (line.find('@') != std::string::npos)
    {
      vtkErrorMacro("Unknown placeholder in template line " << lineNumber << ": " << line);
    }
    output += line;
    output += '\n';
  }
  if (!sectionFound)
  {
    vtkErrorMacro("Template has no section " << section << ".");
  }
  else if (inSection && !active.empty())
  {
    vtkErrorMacro("Template section " << section << " ends with an open //PHONG_IF.");
  }
  return output;
}

//------------------------------------------------------------------------------
const char* vtkPhongShaderBuilder::GetTemplate(const char* name)
{
  const std::string file(name ? name : "");
  if (file == "vtkPhongLightingLib")
  {
    return vtkPhongLightingLib;
  }
  if (file == "vtkPhongFS")
  {
    return vtkPhongFS;
  }
  if (file == "vtkPhongVS")
  {
    return vtkPhongVS;
  }
  if (file == "vtkPhongGS")
  {
    return vtkPhongGS;
  }
  return nullptr;
}

//------------------------------------------------------------------------------
void vtkPhongShaderBuilder::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, const Plan& givenPlan)
{
  // When VTK's Color::Impl (already substituted) takes every material colour from its
  // uniforms, the lighting code uses ready-made products instead (MATERIAL_UNIFORMS in
  // vtkPhongFS.glsl). Whatever changes VTK's colour code (mapped scalars, a back-face
  // property) makes VTK rebuild the shader, and this is decided again.
  Plan plan = givenPlan;
  {
    // Uniform colours, assigned once: VTK's edges, back faces and lighting-map passes
    // (substituted before the lighting) reassign them, and then the variables must be read.
    const std::string colorCode = shaders[vtkShader::Fragment]->GetSource();
    auto assignedOnceAs = [&colorCode](const char* variable, const char* definition)
    {
      size_t count = 0;
      const std::string assignment = std::string(variable) + " =";
      for (size_t at = colorCode.find(assignment); at != std::string::npos;
           at = colorCode.find(assignment, at + 1))
      {
        ++count;
      }
      return count == 1 && colorCode.find(definition) != std::string::npos;
    };
    const bool uniformColors = assignedOnceAs("ambientColor",
                                 "vec3 ambientColor = ambientIntensity * ambientColorUniform;") &&
      assignedOnceAs(
        "diffuseColor", "vec3 diffuseColor = diffuseIntensity * diffuseColorUniform;") &&
      assignedOnceAs(
        "specularColor", "vec3 specularColor = specularIntensity * specularColorUniform;");
    if (uniformColors && !plan.Has("BACK_MATERIAL"))
    {
      plan.Flags.insert("MATERIAL_UNIFORMS");
    }
  }
  const bool perVertex = plan.Has("SUMS_PER_VERTEX");
  const std::string sums = this->ResolveTemplate(vtkPhongLightingLib, "Sums", plan);
  const std::string lights = this->ResolveTemplate(vtkPhongLightingLib, "Lights", plan);

  std::string fragment = shaders[vtkShader::Fragment]->GetSource();
  std::string fragmentDec =
    sums + (perVertex ? std::string() : lights) + this->ResolveTemplate(vtkPhongFS, "Dec", plan);
  vtkShaderProgram::Substitute(
    fragment, "//VTK::Light::Dec", fragmentDec + "//VTK::Light::Dec", false);
  const std::string uniformFlow = this->ResolveTemplate(vtkPhongFS, "UniformFlow", plan);
  if (!uniformFlow.empty())
  {
    vtkShaderProgram::Substitute(
      fragment, "//VTK::UniformFlow::Impl", uniformFlow + "  //VTK::UniformFlow::Impl", false);
  }
  vtkShaderProgram::Substitute(fragment, "//VTK::Light::Impl",
    this->ResolveTemplate(vtkPhongFS, "Impl", plan) + "  //VTK::Light::Impl", false);
  // VTK multiplies gl_FragData[0] by the texture colour at TCoord::Impl; what
  // must escape the texture (emission, specular) is added right after it.
  vtkShaderProgram::Substitute(fragment, "//VTK::TCoord::Impl",
    "//VTK::TCoord::Impl\n" + this->ResolveTemplate(vtkPhongFS, "PostTexture", plan), false);
  shaders[vtkShader::Fragment]->SetSource(fragment);

  if (perVertex)
  {
    std::string vertex = shaders[vtkShader::Vertex]->GetSource();
    vtkShaderProgram::Substitute(vertex, "//VTK::Light::Dec",
      sums + lights + this->ResolveTemplate(vtkPhongVS, "Dec", plan) + "//VTK::Light::Dec", false);
    vtkShaderProgram::Substitute(vertex, "//VTK::Light::Impl",
      this->ResolveTemplate(vtkPhongVS, "Impl", plan) + "  //VTK::Light::Impl", false);
    shaders[vtkShader::Vertex]->SetSource(vertex);

    std::string geometry = shaders[vtkShader::Geometry]->GetSource();
    if (!geometry.empty())
    {
      vtkShaderProgram::Substitute(geometry, "//VTK::Light::Dec",
        this->ResolveTemplate(vtkPhongGS, "Dec", plan) + "//VTK::Light::Dec", false);
      vtkShaderProgram::Substitute(geometry, "//VTK::Light::Impl",
        this->ResolveTemplate(vtkPhongGS, "Impl", plan) + "    //VTK::Light::Impl", false);
      shaders[vtkShader::Geometry]->SetSource(geometry);
    }
  }
}

namespace
{
// Light values as uploaded: colours premultiplied by the intensity, checked.
struct LightValues
{
  RGB Ambient = { 0.f, 0.f, 0.f };
  RGB Diffuse = { 0.f, 0.f, 0.f };
  RGB Specular = { 0.f, 0.f, 0.f };
};

// The light's position and focal point in view coordinates, in double
// precision so far-away scenes (coordinates offset by 1e7) lose nothing before
// the final cast to float.
struct LightGeometry
{
  double PositionVC[3] = { 0.0, 0.0, 0.0 };
  double DirectionVC[3] = { 0.0, 0.0, -1.0 }; // from the light towards its focal point
  bool HasDirection = true;
};

LightGeometry GeometryOf(vtkLight* light, vtkMatrix4x4* worldToView, vtkTransform* userTransform)
{
  LightGeometry geometry;
  double position[4] = { 0.0, 0.0, 0.0, 1.0 };
  double focalPoint[4] = { 0.0, 0.0, 0.0, 1.0 };
  light->GetTransformedPosition(position);
  light->GetTransformedFocalPoint(focalPoint);
  double positionVC[4];
  worldToView->MultiplyPoint(position, positionVC);
  double direction[3];
  vtkMath::Subtract(focalPoint, position, direction);
  double directionVC[3];
  for (int row = 0; row < 3; ++row)
  {
    directionVC[row] = worldToView->GetElement(row, 0) * direction[0] +
      worldToView->GetElement(row, 1) * direction[1] +
      worldToView->GetElement(row, 2) * direction[2];
  }
  // VTK applies its user light transform (used in VR) to all but scene lights.
  if (userTransform && !light->LightTypeIsSceneLight())
  {
    userTransform->TransformPoint(positionVC, positionVC);
    userTransform->TransformVector(directionVC, directionVC);
  }
  for (int i = 0; i < 3; ++i)
  {
    geometry.PositionVC[i] = positionVC[i] / (positionVC[3] != 0.0 ? positionVC[3] : 1.0);
  }
  const double length = vtkMath::Norm(directionVC);
  geometry.HasDirection = length > 0.0 && std::isfinite(length);
  if (geometry.HasDirection)
  {
    for (int i = 0; i < 3; ++i)
    {
      geometry.DirectionVC[i] = directionVC[i] / length;
    }
  }
  return geometry;
}

template <typename T>
void AppendRGB(std::vector<float>& packed, const T& rgb)
{
  packed.insert(packed.end(),
    { static_cast<float>(rgb[0]), static_cast<float>(rgb[1]), static_cast<float>(rgb[2]) });
}

void SetVec3Array(vtkShaderProgram* program, const char* name, const std::vector<float>& values)
{
  if (!values.empty())
  {
    program->SetUniform3fv(name, static_cast<int>(values.size() / 3),
      reinterpret_cast<const float(*)[3]>(values.data()));
  }
}
}

//------------------------------------------------------------------------------
void vtkPhongShaderBuilder::SetLightUniforms(
  vtkShaderProgram* program, vtkRenderer* ren, const Plan& plan)
{
  const bool singleLight = plan.DebugView == View::SingleLight;

  // A light's colours times its intensity, zero for lights hidden by the
  // single-light view; non-finite or negative values are reported and zeroed.
  auto valuesOf = [&](vtkLight* light, int index)
  {
    LightValues values;
    if (singleLight && light != plan.DebugLight)
    {
      return values;
    }
    double intensity = light->GetIntensity();
    if (!(intensity >= 0.0) || !std::isfinite(intensity))
    {
      std::ostringstream problem;
      problem << "Light " << index << " (" << LightKindName(light) << ") has intensity "
              << intensity << "; lights need a finite intensity >= 0, so it is treated as 0.";
      this->AddProblem(problem.str());
      intensity = 0.0;
    }
    auto scaled = [&](const double* color, const char* which, RGB& out)
    {
      for (int c = 0; c < 3; ++c)
      {
        double value = color[c];
        if (!(value >= 0.0) || !std::isfinite(value))
        {
          std::ostringstream problem;
          problem << "Light " << index << " (" << LightKindName(light) << ") has " << which
                  << " colour component " << value
                  << "; colours must be finite and >= 0, so it is treated as 0.";
          this->AddProblem(problem.str());
          value = 0.0;
        }
        out[c] = static_cast<float>(value * intensity);
      }
    };
    scaled(light->GetAmbientColor(), "ambient", values.Ambient);
    scaled(light->GetDiffuseColor(), "diffuse", values.Diffuse);
    scaled(light->GetSpecularColor(), "specular", values.Specular);
    return values;
  };

  vtkCamera* camera = ren->GetActiveCamera();
  vtkMatrix4x4* worldToView = camera->GetModelViewTransformMatrix();
  vtkOpenGLRenderer* oglRenderer = vtkOpenGLRenderer::SafeDownCast(ren);
  vtkTransform* userTransform = oglRenderer ? oglRenderer->GetUserLightTransform() : nullptr;

  // Index lights as the renderer lists its switched-on lights, for messages.
  std::map<vtkLight*, int> lightIndex;
  {
    int index = 0;
    vtkCollectionSimpleIterator it;
    vtkLight* light;
    vtkLightCollection* lights = ren->GetLights();
    for (lights->InitTraversal(it); (light = lights->GetNextLight(it));)
    {
      if (light->GetSwitch())
      {
        lightIndex[light] = index++;
      }
    }
  }

  // Ia plus the ambient light of directional lights, which is the same everywhere.
  double ambientLight[3] = { 0.0, 0.0, 0.0 };
  if (!singleLight)
  {
    const double* ia = ren->GetAmbient();
    for (int c = 0; c < 3; ++c)
    {
      if (!(ia[c] >= 0.0) || !std::isfinite(ia[c]))
      {
        std::ostringstream problem;
        problem << "The renderer's ambient light component " << ia[c]
                << " is not a finite value >= 0; it is treated as 0.";
        this->AddProblem(problem.str());
      }
      else
      {
        ambientLight[c] = ia[c];
      }
    }
  }

  std::vector<float> toLight, diffuse, specular;
  for (vtkLight* light : plan.DirectionalLights)
  {
    const LightValues values = valuesOf(light, lightIndex[light]);
    for (int c = 0; c < 3; ++c)
    {
      ambientLight[c] += values.Ambient[c];
    }
    const LightGeometry geometry = GeometryOf(light, worldToView, userTransform);
    if (!geometry.HasDirection)
    {
      std::ostringstream problem;
      problem << "Directional light " << lightIndex[light] << " (" << LightKindName(light)
              << ") has its focal point at its position and so no direction; it shines "
                 "along the view direction.";
      this->AddProblem(problem.str());
    }
    const double towardsLight[3] = { -geometry.DirectionVC[0], -geometry.DirectionVC[1],
      -geometry.DirectionVC[2] };
    AppendRGB(toLight, towardsLight);
    AppendRGB(diffuse, values.Diffuse);
    AppendRGB(specular, values.Specular);
  }
  if (plan.Has("DIRECTIONAL"))
  {
    SetVec3Array(program, "phongDirectionalLightToLightVC", toLight);
    SetVec3Array(program, "phongDirectionalLightDiffuse", diffuse);
    SetVec3Array(program, "phongDirectionalLightSpecular", specular);
  }
  if (program->IsUniformUsed("phongAmbientLight"))
  {
    program->SetUniform3f("phongAmbientLight", ambientLight);
  }
  if (program->IsUniformUsed("phongAmbientTerm"))
  {
    // ka*Ca times that light, the material's values as SetMaterialUniforms checks (and
    // reports) them.
    vtkProperty* material = plan.FrontMaterial;
    const double ka = std::isfinite(material->GetAmbient()) ? material->GetAmbient() : 0.0;
    const double* ca = material->GetAmbientColor();
    float term[3];
    for (int c = 0; c < 3; ++c)
    {
      term[c] = static_cast<float>(ka * (std::isfinite(ca[c]) ? ca[c] : 0.0) * ambientLight[c]);
    }
    program->SetUniform3f("phongAmbientTerm", term);
  }

  // Attenuation coefficients as uploaded: finite and >= 0.
  auto attenuationOf = [&](vtkLight* light)
  {
    RGB attenuation;
    const double* values = light->GetAttenuationValues();
    for (int c = 0; c < 3; ++c)
    {
      double value = values[c];
      if (!(value >= 0.0) || !std::isfinite(value))
      {
        std::ostringstream problem;
        problem << "Positional light " << lightIndex[light] << " has attenuation coefficient "
                << value << "; coefficients must be finite and >= 0, so it is treated as 0.";
        this->AddProblem(problem.str());
        value = 0.0;
      }
      attenuation[c] = static_cast<float>(value);
    }
    return attenuation;
  };

  auto uploadPositional =
    [&](const std::vector<vtkLight*>& kindLights, const char* prefix, bool isSpot)
  {
    std::vector<float> position, attenuation, ambient, axis, cosCutoff, exponent, cosInner;
    diffuse.clear();
    specular.clear();
    auto* phongFront = vtkPhongProperty::SafeDownCast(plan.FrontMaterial);
    // Without the soft edge option the band has no width (a hard edge), also in the
    // all-features variant, which evaluates the smoothstep anyway.
    const double edgeWidth =
      (phongFront && phongFront->GetSoftSpotEdge()) ? phongFront->GetSpotEdgeWidth() : 0.0;
    for (vtkLight* light : kindLights)
    {
      const LightValues values = valuesOf(light, lightIndex[light]);
      const LightGeometry geometry = GeometryOf(light, worldToView, userTransform);
      AppendRGB(position, geometry.PositionVC);
      AppendRGB(attenuation, attenuationOf(light));
      AppendRGB(ambient, values.Ambient);
      AppendRGB(diffuse, values.Diffuse);
      AppendRGB(specular, values.Specular);
      if (isSpot)
      {
        if (!geometry.HasDirection)
        {
          std::ostringstream problem;
          problem << "Spot light " << lightIndex[light]
                  << " has its focal point at its position and so no axis; it points along "
                     "the view direction.";
          this->AddProblem(problem.str());
        }
        AppendRGB(axis, geometry.DirectionVC);
        const double cone = std::max(light->GetConeAngle(), 0.0);
        cosCutoff.push_back(static_cast<float>(std::cos(vtkMath::RadiansFromDegrees(cone))));
        if (!(light->GetExponent() >= 0.0) || !std::isfinite(light->GetExponent()))
        {
          std::ostringstream problem;
          problem << "Spot light " << lightIndex[light] << " has exponent " << light->GetExponent()
                  << "; spot exponents must be finite and >= 0, so it is treated as 0.";
          this->AddProblem(problem.str());
        }
        exponent.push_back(static_cast<float>(Sanitized(light->GetExponent())));
        // smoothstep needs its two edges apart; a zero-width band is a hard edge.
        const double inner = std::cos(vtkMath::RadiansFromDegrees(std::max(cone - edgeWidth, 0.0)));
        cosInner.push_back(static_cast<float>(std::max(inner, cosCutoff.back() + 1.0e-6)));
      }
    }
    const std::string name(prefix);
    SetVec3Array(program, (name + "PositionVC").c_str(), position);
    if (plan.Has(isSpot ? "SPOT_ATTENUATION" : "POINT_ATTENUATION"))
    {
      SetVec3Array(program, (name + "Attenuation").c_str(), attenuation);
    }
    if (plan.Has("POSITIONAL_AMBIENT"))
    {
      SetVec3Array(program, (name + "Ambient").c_str(), ambient);
    }
    if (plan.Has("DIFFUSE"))
    {
      SetVec3Array(program, (name + "Diffuse").c_str(), diffuse);
    }
    if (plan.Has("SPECULAR"))
    {
      SetVec3Array(program, (name + "Specular").c_str(), specular);
    }
    if (isSpot)
    {
      const int count = static_cast<int>(cosCutoff.size());
      SetVec3Array(program, (name + "AxisVC").c_str(), axis);
      program->SetUniform1fv((name + "CosCutoff").c_str(), count, cosCutoff.data());
      if (plan.Has("SPOT_FALLOFF"))
      {
        program->SetUniform1fv((name + "Exponent").c_str(), count, exponent.data());
      }
      if (plan.Has("SOFT_SPOT_EDGE"))
      {
        program->SetUniform1fv((name + "CosInner").c_str(), count, cosInner.data());
      }
    }
  };
  if (plan.Has("POINT"))
  {
    uploadPositional(plan.PointLights, "phongPointLight", false);
  }
  if (plan.Has("SPOT"))
  {
    uploadPositional(plan.SpotLights, "phongSpotLight", true);
  }

  if (plan.Has("EMISSION"))
  {
    auto emissionOf = [](vtkProperty* material)
    {
      auto* phong = vtkPhongProperty::SafeDownCast(material);
      RGB emission = { 0.f, 0.f, 0.f };
      if (phong)
      {
        for (int c = 0; c < 3; ++c)
        {
          emission[c] = static_cast<float>(phong->GetEmission()[c]);
        }
      }
      return emission;
    };
    program->SetUniform3f("phongEmission", emissionOf(plan.FrontMaterial).data());
    if (plan.Has("BACK_MATERIAL"))
    {
      program->SetUniform3f("phongEmissionBF", emissionOf(plan.BackMaterial).data());
    }
  }
  if (program->IsUniformUsed("phongShininessBF"))
  {
    program->SetUniformf("phongShininessBF", static_cast<float>(ShininessOf(plan.BackMaterial)));
  }
}

//------------------------------------------------------------------------------
void vtkPhongShaderBuilder::SetMaterialUniforms(vtkShaderProgram* program, const Plan& plan)
{
  // VTK uploaded SpecularPower (clamped to 128), the raw specular colour and
  // the colours as they are; replace them with the contract's values.
  auto upload = [&](vtkProperty* material, const char* suffix, bool report)
  {
    const std::string side(suffix);
    const char* sideName = side.empty() ? "front" : "back";
    auto checkedColor = [&](const double* color, const char* which, double scale)
    {
      RGB out;
      for (int c = 0; c < 3; ++c)
      {
        double value = color[c];
        if (!std::isfinite(value))
        {
          if (report)
          {
            std::ostringstream problem;
            problem << "The " << sideName << " material's " << which << " colour component "
                    << value << " is not finite; it is treated as 0.";
            this->AddProblem(problem.str());
          }
          value = 0.0;
        }
        out[c] = static_cast<float>(value * scale);
      }
      return out;
    };
    auto checkedCoefficient = [&](double value, const char* which)
    {
      if (!std::isfinite(value))
      {
        if (report)
        {
          std::ostringstream problem;
          problem << "The " << sideName << " material's " << which << " coefficient " << value
                  << " is not finite; it is treated as 0.";
          this->AddProblem(problem.str());
        }
        return 0.f;
      }
      return static_cast<float>(value);
    };
    const double shininess = ShininessOf(material);
    const double normalization = LobeNormalization(LightingModelOf(plan.FrontMaterial), shininess);

    // The selection of material per face is VTK's (Color::Impl); only values change here.
    // Every value is checked (and a problem reported) whether or not the variant reads it.
    const RGB ambientColor = checkedColor(material->GetAmbientColor(), "ambient", 1.0);
    const RGB diffuseColor = checkedColor(material->GetDiffuseColor(), "diffuse", 1.0);
    const RGB specularColor = checkedColor(material->GetSpecularColor(), "specular", normalization);
    const float opacity = checkedCoefficient(material->GetOpacity(), "opacity");
    const float ambient = checkedCoefficient(material->GetAmbient(), "ambient");
    const float diffuse = checkedCoefficient(material->GetDiffuse(), "diffuse");
    const float specular = checkedCoefficient(material->GetSpecular(), "specular");
    auto set3 = [&](const char* name, const RGB& value)
    {
      if (program->IsUniformUsed((name + side).c_str()))
      {
        program->SetUniform3f((name + side).c_str(), value.data());
      }
    };
    auto set1 = [&](const char* name, float value)
    {
      if (program->IsUniformUsed((name + side).c_str()))
      {
        program->SetUniformf((name + side).c_str(), value);
      }
    };
    set3("ambientColorUniform", ambientColor);
    set3("diffuseColorUniform", diffuseColor);
    set1("opacityUniform", opacity);
    set1("ambientIntensity", ambient);
    set1("diffuseIntensity", diffuse);
    if (plan.Has("SPECULAR"))
    {
      set1("specularIntensity", specular);
      set3("specularColorUniform", specularColor);
      set1("specularPowerUniform", static_cast<float>(shininess));
    }
  };
  upload(plan.FrontMaterial, "", true);
  // The ready-made products of MATERIAL_UNIFORMS (front material only: that variant has
  // no back material).
  auto product = [&](const char* name, double coefficient, const double* color, double scale)
  {
    if (program->IsUniformUsed(name))
    {
      float value[3];
      const double k = std::isfinite(coefficient) ? coefficient : 0.0;
      for (int c = 0; c < 3; ++c)
      {
        value[c] = static_cast<float>(k * (std::isfinite(color[c]) ? color[c] : 0.0) * scale);
      }
      program->SetUniform3f(name, value);
    }
  };
  vtkProperty* front = plan.FrontMaterial;
  product("phongMaterialAmbient", front->GetAmbient(), front->GetAmbientColor(), 1.0);
  product("phongMaterialDiffuse", front->GetDiffuse(), front->GetDiffuseColor(), 1.0);
  product("phongMaterialSpecular", front->GetSpecular(), front->GetSpecularColor(),
    LobeNormalization(LightingModelOf(front), ShininessOf(front)));
  // VTK declares back-face uniforms when the actor has a back property; with one-sided
  // lighting the contract uses the front material on both faces.
  upload(plan.BackMaterial, "BF", plan.BackMaterial != plan.FrontMaterial);
}

//------------------------------------------------------------------------------
void vtkPhongShaderBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Pending problems: " << this->Problems.size() << "\n";
}
