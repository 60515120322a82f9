#include "vtkPhongShaderTemplate.h"

#include "vtkObject.h"
#include "vtkPhongShadowMaps.h"
#include "vtkShaderProgram.h"

#include "vtkPhongFS.h"
#include "vtkPhongGS.h"
#include "vtkPhongLightingLib.h"
#include "vtkPhongVS.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <sstream>

namespace
{
using Feature = vtkPhongFeature;

// Strip leading blanks, for matching template directives.
std::string TrimLeft(const std::string& line)
{
  const auto first = line.find_first_not_of(" \t");
  return first == std::string::npos ? std::string() : line.substr(first);
}

bool StartsWith(const std::string& text, const char* prefix)
{
  return text.compare(0, std::char_traits<char>::length(prefix), prefix) == 0;
}

// Mesa unrolls a loop of up to about 16 iterations by itself; beyond, llvmpipe reads the
// uniform arrays of a rolled loop per fragment through gathers, which made 32 directional lights
// cost 1.2x their unrolled code. The light loops are unrolled here, up to this many lights.
constexpr int MaximumUnrolledLights = 64;

// The iteration count of a light loop header "for (int i = 0; i < N; ++i)", or -1.
int LightLoopCount(const std::string& line)
{
  const std::string head = "for (int i = 0; i < ";
  const std::string trimmed = TrimLeft(line);
  if (!StartsWith(trimmed, head.c_str()))
  {
    return -1;
  }
  std::size_t digits = 0;
  const std::string rest = trimmed.substr(head.size());
  while (digits < rest.size() && std::isdigit(static_cast<unsigned char>(rest[digits])))
  {
    ++digits;
  }
  if (digits == 0 || rest.compare(digits, 6, "; ++i)") != 0)
  {
    return -1;
  }
  return std::stoi(rest.substr(0, digits));
}

// Replace each light loop of resolved GLSL (a header line, a "{" line, the body, the matching
// "}" line) by one block per light that declares i as a constant.
std::string UnrollLightLoops(const std::string& source)
{
  std::vector<std::string> lines;
  std::istringstream input(source);
  for (std::string line; std::getline(input, line);)
  {
    lines.push_back(line);
  }
  std::string output;
  for (std::size_t n = 0; n < lines.size(); ++n)
  {
    const int count = LightLoopCount(lines[n]);
    std::size_t end = n + 1;
    int depth = 0;
    for (; count >= 0 && end < lines.size(); ++end)
    {
      depth += static_cast<int>(std::count(lines[end].begin(), lines[end].end(), '{')) -
        static_cast<int>(std::count(lines[end].begin(), lines[end].end(), '}'));
      if (depth == 0)
      {
        break;
      }
    }
    if (count < 0 || count > MaximumUnrolledLights || end >= lines.size() ||
      TrimLeft(lines[n + 1]) != "{")
    {
      output += lines[n] + '\n';
      continue;
    }
    for (int i = 0; i < count; ++i)
    {
      output += lines[n + 1] + '\n' + "    const int i = " + std::to_string(i) + ";\n";
      for (std::size_t body = n + 2; body <= end; ++body)
      {
        output += lines[body] + '\n';
      }
    }
    n = end;
  }
  return output;
}

// How often "variable =" occurs in the source.
std::size_t CountAssignments(const std::string& source, const char* variable)
{
  std::size_t count = 0;
  const std::string assignment = std::string(variable) + " =";
  for (std::size_t at = source.find(assignment); at != std::string::npos;
       at = source.find(assignment, at + 1))
  {
    ++count;
  }
  return count;
}
}

//------------------------------------------------------------------------------
vtkPhongShaderTemplate::vtkPhongShaderTemplate(vtkObject* reporter)
  : Reporter(reporter)
{
}

//------------------------------------------------------------------------------
const char* vtkPhongShaderTemplate::Get(const char* name)
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
std::string vtkPhongShaderTemplate::Resolve(
  const char* templateText, const char* section, const Plan& plan) const
{
  Reading reading;
  reading.Section = section;
  reading.SectionLine = std::string("//PHONG_SECTION ") + section;
  std::istringstream input(templateText);
  std::string line;
  std::string output;
  while (std::getline(input, line))
  {
    ++reading.LineNumber;
    const bool kept = !this->ReadDirective(TrimLeft(line), plan, reading) && reading.InSection &&
      (reading.Active.empty() || reading.Active.back());
    if (kept)
    {
      this->FillPlaceholders(line, plan, reading.LineNumber);
      output += line;
      output += '\n';
    }
  }
  if (!reading.SectionFound)
  {
    vtkErrorWithObjectMacro(this->Reporter, "Template has no section " << section << ".");
  }
  else if (reading.InSection && !reading.Active.empty())
  {
    vtkErrorWithObjectMacro(
      this->Reporter, "Template section " << section << " ends with an open //PHONG_IF.");
  }
  return UnrollLightLoops(output);
}

//------------------------------------------------------------------------------
// Follow a //PHONG_SECTION, //PHONG_IF or //PHONG_ENDIF line; false for any other line.
bool vtkPhongShaderTemplate::ReadDirective(
  const std::string& trimmed, const Plan& plan, Reading& reading) const
{
  if (StartsWith(trimmed, "//PHONG_SECTION "))
  {
    if (reading.InSection && !reading.Active.empty())
    {
      vtkErrorWithObjectMacro(
        this->Reporter, "Template section " << reading.Section << " ends with an open //PHONG_IF.");
    }
    reading.InSection = (trimmed == reading.SectionLine);
    reading.SectionFound = reading.SectionFound || reading.InSection;
    reading.Active.clear();
    return true;
  }
  if (!reading.InSection)
  {
    return false;
  }
  const bool enclosingActive = reading.Active.empty() || reading.Active.back();
  if (StartsWith(trimmed, "//PHONG_IF "))
  {
    std::string condition = TrimLeft(trimmed.substr(11));
    condition.erase(condition.find_last_not_of(" \t\r") + 1);
    reading.Active.push_back(
      enclosingActive && this->FeatureCondition(condition, plan, reading.LineNumber));
    return true;
  }
  if (StartsWith(trimmed, "//PHONG_ENDIF"))
  {
    if (reading.Active.empty())
    {
      vtkErrorWithObjectMacro(
        this->Reporter, "Unbalanced //PHONG_ENDIF at template line " << reading.LineNumber << ".");
    }
    else
    {
      reading.Active.pop_back();
    }
    return true;
  }
  return false;
}

//------------------------------------------------------------------------------
// Whether a //PHONG_IF condition ("FEATURE" or "!FEATURE") holds for the plan.
bool vtkPhongShaderTemplate::FeatureCondition(
  const std::string& condition, const Plan& plan, int lineNumber) const
{
  const bool negate = !condition.empty() && condition[0] == '!';
  const std::string name = negate ? condition.substr(1) : condition;
  vtkPhongFeature feature;
  if (!vtkPhongFeatureSet::FindByName(name, feature))
  {
    vtkErrorWithObjectMacro(this->Reporter,
      "Unknown feature '" << name << "' in //PHONG_IF at template line " << lineNumber << ".");
    return negate;
  }
  return plan.Has(feature) != negate;
}

//------------------------------------------------------------------------------
// The statements raising `x` to the whole power n into `power` (phongWholePower): through the
// bits of n from the lowest, a product into the power for each bit set and a squaring
// between bits; n = 30 gives 4 squarings and 4 products.
std::string vtkPhongShaderTemplate::WholePowerSteps(int n)
{
  std::string steps;
  for (int k = n; k > 0; k >>= 1)
  {
    steps += (k & 1) ? "power *= x; " : "";
    steps += k > 1 ? "x *= x; " : "";
  }
  return steps;
}

//------------------------------------------------------------------------------
void vtkPhongShaderTemplate::FillPlaceholders(
  std::string& line, const Plan& plan, int lineNumber) const
{
  const std::pair<const char*, std::size_t> placeholders[] = {
    { "@DIRECTIONAL_COUNT@", plan.DirectionalLights.size() },
    { "@POINT_COUNT@", plan.PointLights.size() },
    { "@SPOT_COUNT@", plan.SpotLights.size() },
    { "@DIRECTIONAL_VEC4_COUNT@", (plan.DirectionalLights.size() + 3) / 4 },
    { "@SHADOW_FACTOR_COUNT@", static_cast<std::size_t>(plan.ShadowFactorCount) },
  };
  const auto replace = [&line](const std::string& name, const std::string& value)
  {
    for (auto at = line.find(name); at != std::string::npos; at = line.find(name, at))
    {
      line.replace(at, name.size(), value);
    }
  };
  for (const auto& placeholder : placeholders)
  {
    replace(placeholder.first, std::to_string(placeholder.second));
  }
  const std::string steps = "@WHOLE_POWER_STEPS@";
  if (line.find(steps) != std::string::npos) // one line of the template: made only there
  {
    replace(steps, WholePowerSteps(plan.WholeShininess));
  }
  if (line.find('@') != std::string::npos)
  {
    vtkErrorWithObjectMacro(
      this->Reporter, "Unknown placeholder in template line " << lineNumber << ": " << line);
  }
}

//------------------------------------------------------------------------------
void vtkPhongShaderTemplate::Substitute(
  std::map<vtkShader::Type, vtkShader*>& shaders, const Plan& givenPlan) const
{
  // When VTK's Color::Impl (already substituted) takes every material colour from its
  // uniforms, the lighting code uses ready-made products instead (MATERIAL_UNIFORMS in
  // vtkPhongFS.glsl). Whatever changes VTK's colour code (mapped scalars, a back-face
  // property) makes VTK rebuild the shader, and this is decided again.
  Plan plan = givenPlan;
  if (UsesUniformColors(shaders[vtkShader::Fragment]->GetSource()) &&
    !plan.Has(Feature::BackMaterial))
  {
    plan.Features.Set(Feature::MaterialUniforms);
  }
  // Like the colours, vtkShadowMapPass's factors are seen in the source (vtkPhongShadowMaps.h);
  // per-vertex sums cannot read them.
  plan.ShadowFactorCount =
    vtkPhongShadowMaps::CountFactors(shaders[vtkShader::Fragment]->GetSource());
  plan.Features.Set(
    Feature::ShadowMaps, plan.ShadowFactorCount > 0 && plan.Has(Feature::SumsPerFragment));
  if (plan.Has(Feature::InterpolatedDots) && !ShadesWithVertexNormal(shaders))
  {
    plan.Features.Set(Feature::InterpolatedDots, false);
  }
  if (plan.Has(Feature::OneSided) && FlipsNormalByDepth(shaders[vtkShader::Fragment]->GetSource()))
  {
    plan.Features.Set(Feature::OneSided, false);
  }
  DeclareInvariantPosition(shaders);
  const bool perVertex = plan.Has(Feature::SumsPerVertex);
  const std::string sums = this->Resolve(vtkPhongLightingLib, "Sums", plan);
  const bool fragmentLights = !perVertex || plan.Has(Feature::DiffusePerFragment);
  this->SubstituteFragment(shaders[vtkShader::Fragment], sums,
    fragmentLights ? this->Resolve(vtkPhongLightingLib, "Lights", plan) : std::string(), plan);
  if (perVertex)
  {
    // The vertices light with the light directions themselves: the interpolated dot products
    // are the fragments' inputs.
    Plan vertexPlan = plan;
    vertexPlan.Features.Set(Feature::InterpolatedDots, false);
    this->SubstitutePerVertex(
      shaders, sums, this->Resolve(vtkPhongLightingLib, "Lights", vertexPlan), plan);
  }
  if (plan.Has(Feature::InterpolatedDots))
  {
    this->SubstituteVertexDots(shaders[vtkShader::Vertex], plan);
  }
}

//------------------------------------------------------------------------------
bool vtkPhongShaderTemplate::FlipsNormalByDepth(const std::string& fragmentSource)
{
  return fragmentSource.find(
           "if (normalVCVSOutput.z < 0) { normalVCVSOutput = -normalVCVSOutput; }") !=
    std::string::npos;
}

//------------------------------------------------------------------------------
// Whether the fragment's normal is VTK's vertex normal, interpolated, normalized and flipped
// on back faces, and nothing else (INTERPOLATED_DOTS relies on it): VTK's own normal code,
// each variable assigned only there, and no geometry shader in between.
bool vtkPhongShaderTemplate::ShadesWithVertexNormal(std::map<vtkShader::Type, vtkShader*>& shaders)
{
  vtkShader* geometry = shaders[vtkShader::Geometry];
  if (geometry && !geometry->GetSource().empty())
  {
    return false;
  }
  const std::string vertex = shaders[vtkShader::Vertex]->GetSource();
  const std::string fragment = shaders[vtkShader::Fragment]->GetSource();
  return CountAssignments(vertex, "normalVCVSOutput") == 1 &&
    vertex.find("normalVCVSOutput = normalMatrix * normalMC;") != std::string::npos &&
    CountAssignments(fragment, "normalVCVSOutput") == 2 &&
    fragment.find("vec3 normalVCVSOutput = normalize(normalVCVSOutput);") != std::string::npos &&
    fragment.find("if (gl_FrontFacing == false) { normalVCVSOutput = -normalVCVSOutput; }") !=
    std::string::npos;
}

//------------------------------------------------------------------------------
void vtkPhongShaderTemplate::SubstituteVertexDots(vtkShader* vertexShader, const Plan& plan) const
{
  std::string vertex = vertexShader->GetSource();
  vtkShaderProgram::Substitute(vertex, "//VTK::Light::Dec",
    this->Resolve(vtkPhongVS, "DotsDec", plan) + "//VTK::Light::Dec", false);
  vtkShaderProgram::Substitute(vertex, "//VTK::Light::Impl",
    this->Resolve(vtkPhongVS, "DotsImpl", plan) + "  //VTK::Light::Impl", false);
  vertexShader->SetSource(vertex);
}

//------------------------------------------------------------------------------
// The depth pre-pass draws with two programs, the depth-only one and the lit one, and the lit
// draw's GL_LEQUAL test passes only where both computed the same depth: GLSL promises that
// for the same expression over the same inputs only when the output is invariant (without
// it, a compiler may schedule the position differently once the lit outputs are dropped).
void vtkPhongShaderTemplate::DeclareInvariantPosition(
  std::map<vtkShader::Type, vtkShader*>& shaders)
{
  for (vtkShader::Type type : { vtkShader::Vertex, vtkShader::Geometry })
  {
    vtkShader* shader = shaders[type];
    std::string source = shader ? shader->GetSource() : std::string();
    if (vtkShaderProgram::Substitute(
          source, "//VTK::System::Dec", "//VTK::System::Dec\ninvariant gl_Position;", false))
    {
      shader->SetSource(source);
    }
  }
}

//------------------------------------------------------------------------------
// Whether VTK's colour code takes each material colour from its uniform, assigned once: VTK's
// edges, back faces and lighting-map passes (substituted before the lighting) reassign them,
// and then the variables must be read.
bool vtkPhongShaderTemplate::UsesUniformColors(const std::string& fragmentSource)
{
  auto assignedOnceAs = [&fragmentSource](const char* variable, const char* definition)
  {
    return CountAssignments(fragmentSource, variable) == 1 &&
      fragmentSource.find(definition) != std::string::npos;
  };
  return assignedOnceAs(
           "ambientColor", "vec3 ambientColor = ambientIntensity * ambientColorUniform;") &&
    assignedOnceAs("diffuseColor", "vec3 diffuseColor = diffuseIntensity * diffuseColorUniform;") &&
    assignedOnceAs(
      "specularColor", "vec3 specularColor = specularIntensity * specularColorUniform;");
}

//------------------------------------------------------------------------------
void vtkPhongShaderTemplate::SubstituteFragment(vtkShader* fragmentShader, const std::string& sums,
  const std::string& lights, const Plan& plan) const
{
  std::string fragment = fragmentShader->GetSource();
  if (plan.Has(Feature::ShadingNormal))
  {
    // phongIsUnitLength reads a float's bits: core in GLSL 3.30, an extension for VTK's 1.50.
    vtkShaderProgram::Substitute(fragment, "//VTK::System::Dec",
      "//VTK::System::Dec\n#extension GL_ARB_shader_bit_encoding : enable", false);
  }
  const std::string declarations = sums + lights + this->Resolve(vtkPhongFS, "Dec", plan);
  vtkShaderProgram::Substitute(
    fragment, "//VTK::Light::Dec", declarations + "//VTK::Light::Dec", false);
  const std::string uniformFlow = this->Resolve(vtkPhongFS, "UniformFlow", plan);
  if (!uniformFlow.empty())
  {
    vtkShaderProgram::Substitute(
      fragment, "//VTK::UniformFlow::Impl", uniformFlow + "  //VTK::UniformFlow::Impl", false);
  }
  const std::string shadows = plan.Has(Feature::ShadowMaps)
    ? vtkPhongShadowMaps::CopyFactors(plan.ShadowFactorCount)
    : std::string();
  vtkShaderProgram::Substitute(fragment, "//VTK::Light::Impl",
    shadows + this->Resolve(vtkPhongFS, "Impl", plan) + "  //VTK::Light::Impl", false);
  // VTK multiplies gl_FragData[0] by the texture colour at TCoord::Impl; what
  // must escape the texture (emission, specular) is added right after it.
  vtkShaderProgram::Substitute(fragment, "//VTK::TCoord::Impl",
    "//VTK::TCoord::Impl\n" + this->Resolve(vtkPhongFS, "PostTexture", plan), false);
  if (plan.Has(Feature::UniformConstants))
  {
    DeclareConstants(fragment, plan);
  }
  fragmentShader->SetSource(fragment);
}

//------------------------------------------------------------------------------
// Under UNIFORM_CONSTANTS the fragment shader declares the plan's light and material values as
// constants holding the values the uniforms would (llvmpipe pays for every uniform a fragment
// reads: 8 directional lights' directions and colours cost about a third of the frame on sphere
// 256, docs/results/performance.md). The same floats and arithmetic, though a compiler may
// specialize code on them (the planner charges that rounding). A value the fragment shader does
// not declare (VTK's back material without one, a light value only the vertex shader reads)
// stays a uniform there.
void vtkPhongShaderTemplate::DeclareConstants(std::string& fragment, const Plan& plan)
{
  for (const vtkPhongUniformValue& uniform : plan.Constants)
  {
    const std::string type = uniform.ElementType();
    const std::size_t count = uniform.Count();
    // Each element as its type's constructor of its components: vec3(x, y, z), float(x).
    std::string values;
    for (std::size_t i = 0; i < count; ++i)
    {
      std::string components;
      for (int c = 0; c < uniform.Components; ++c)
      {
        components +=
          (c > 0 ? ", " : "") + FloatLiteral(uniform.Values[i * uniform.Components + c]);
      }
      values += (i > 0 ? ", " : "") + type + "(" + components + ")";
    }
    const std::string declared = type + " " + uniform.Name;
    if (uniform.IsArray)
    {
      const std::string size = "[" + std::to_string(count) + "]";
      values = type + size + "(" + values + ")";
      vtkShaderProgram::Substitute(fragment, "uniform " + declared + size + ";",
        "const " + declared + size + " = " + values + ";", false);
    }
    else
    {
      vtkShaderProgram::Substitute(
        fragment, "uniform " + declared + ";", "const " + declared + " = " + values + ";", false);
    }
  }
}

//------------------------------------------------------------------------------
std::string vtkPhongShaderTemplate::FloatLiteral(float value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.9g", static_cast<double>(value));
  std::string literal(text);
  if (literal.find_first_of(".e") == std::string::npos)
  {
    literal += ".0";
  }
  return literal;
}

//------------------------------------------------------------------------------
// True per-vertex Gouraud: the light sums move to the vertex shader, and a geometry shader
// (wide lines, ...) passes them through.
void vtkPhongShaderTemplate::SubstitutePerVertex(std::map<vtkShader::Type, vtkShader*>& shaders,
  const std::string& sums, const std::string& lights, const Plan& plan) const
{
  std::string vertex = shaders[vtkShader::Vertex]->GetSource();
  vtkShaderProgram::Substitute(vertex, "//VTK::Light::Dec",
    sums + lights + this->Resolve(vtkPhongVS, "Dec", plan) + "//VTK::Light::Dec", false);
  vtkShaderProgram::Substitute(vertex, "//VTK::Light::Impl",
    this->Resolve(vtkPhongVS, "Impl", plan) + "  //VTK::Light::Impl", false);
  shaders[vtkShader::Vertex]->SetSource(vertex);

  std::string geometry = shaders[vtkShader::Geometry]->GetSource();
  if (!geometry.empty())
  {
    vtkShaderProgram::Substitute(geometry, "//VTK::Light::Dec",
      this->Resolve(vtkPhongGS, "Dec", plan) + "//VTK::Light::Dec", false);
    vtkShaderProgram::Substitute(geometry, "//VTK::Light::Impl",
      this->Resolve(vtkPhongGS, "Impl", plan) + "    //VTK::Light::Impl", false);
    shaders[vtkShader::Geometry]->SetSource(geometry);
  }
}
