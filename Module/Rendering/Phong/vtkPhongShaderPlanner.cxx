#include "vtkPhongShaderPlanner.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCollectionIterator.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightingMapPass.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkPhongErrorBudget.h"
#include "vtkPhongGouraudBound.h"
#include "vtkPhongLightCulling.h"
#include "vtkPhongLightGeometry.h"
#include "vtkPhongLightingSettings.h"
#include "vtkPhongMaterial.h"
#include "vtkPhongOpenGL.h"
#include "vtkPhongProblemLog.h"
#include "vtkPhongProperty.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShadowMapPass.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

namespace
{
using View = vtkPhongLightingSettings; // for its DebugViews values
using Feature = vtkPhongFeature;

bool IsPositive(double value)
{
  return value > 0.0; // false for NaN too
}

// A light parameter as the uniforms upload it: finite and >= 0, else 0.
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

// Whether a spot's light falls off inside its cone: its exponent is not 1.
bool HasSpotFalloff(vtkLight* light)
{
  return Sanitized(light->GetExponent()) != 1.0;
}

// A component of a light colour times its intensity exactly as vtkPhongLightUniforms uploads
// it, float included.
float UploadedColorComponent(double color, double intensity)
{
  return static_cast<float>(vtkPhongLightGeometry::UploadedColor(color, intensity));
}

// Whether a light's specular colour, as uploaded, differs from its diffuse colour. vtkLight's
// SetColor sets both (VTK's shaders read only the diffuse one); only SetDiffuseColor or
// SetSpecularColor part them. Compared after the upload's clamping and cast, so the variant
// that shares one array draws bit for bit the picture of the one with two.
bool HasOwnSpecularColor(vtkLight* light)
{
  const double intensity = light->GetIntensity();
  const double* diffuse = light->GetDiffuseColor();
  const double* specular = light->GetSpecularColor();
  for (int c = 0; c < 3; ++c)
  {
    if (UploadedColorComponent(diffuse[c], intensity) !=
      UploadedColorComponent(specular[c], intensity))
    {
      return true;
    }
  }
  return false;
}

bool Any(const std::vector<vtkLight*>& lights, bool (*test)(vtkLight*))
{
  return std::any_of(lights.begin(), lights.end(), test);
}

// The views that light as the final picture does (BudgetUse then replaces the colour).
bool IsLitLikeFinal(int view)
{
  return view == View::Final || view == View::BudgetUse;
}

// The debug views that show geometry rather than light.
bool IsGeometryView(int view)
{
  return view == View::ShadingNormal || view == View::PositionVC || view == View::NormalVC;
}
}

//------------------------------------------------------------------------------
vtkPhongShaderPlanner::vtkPhongShaderPlanner(
  const PlaceholderLights& placeholders, vtkPhongProblemLog& log)
  : Placeholders(placeholders)
  , Log(log)
{
}

//------------------------------------------------------------------------------
vtkPhongShaderPlanner::Plan vtkPhongShaderPlanner::MakePlan(
  vtkRenderer* ren, vtkActor* actor, const PrimitiveState& state, const Options& options)
{
  Plan plan;
  vtkProperty* front = actor->GetProperty();
  if (IsLeftToVTK(actor, state))
  {
    return plan;
  }
  const std::vector<vtkLight*> switchedOn = vtkPhongLightGeometry::SwitchedOn(ren);
  // VTK lights a primitive when it has at least one light, and draws it unlit (its colours
  // as they are) without. The equation still holds without lights (emission and ka*Ca*Ia):
  // surfaces VTK would light show that only when the user asks (LightingWithoutLights).
  const bool lit = state.LightComplexity > 0;
  const bool litWithoutLights = options.LightingWithoutLights && !lit && switchedOn.empty() &&
    front->GetLighting() && state.IsTriangles;
  const bool geometryView = IsGeometryView(options.DebugView);
  if ((!lit && !litWithoutLights) || (litWithoutLights && geometryView))
  {
    // VTK provides no normal or view-space position to an unlit primitive.
    return plan;
  }
  plan.Handled = true;
  const bool twoSided = ren->GetTwoSidedLighting() != 0;
  plan.FrontMaterial = front;
  plan.BackMaterial =
    (twoSided && actor->GetBackfaceProperty()) ? actor->GetBackfaceProperty() : front;
  if (options.DepthOnly)
  {
    // The depth pre-pass draws what the lit draw will, with no feature: the fragment shader
    // keeps VTK's colour (its opacity decides the discard), depth and clipping code and
    // computes no light.
    plan.DepthOnly = true;
    plan.Signature = "| depth only";
    return plan;
  }
  plan.DebugView = options.DebugView;
  SortLightsByKind(switchedOn, plan);
  this->PickDebugLight(switchedOn, options, plan);

  if (IsLitLikeFinal(options.DebugView))
  {
    // Under an error budget, culling takes at most half of it.
    const double cullingBound = options.ErrorBudget > 0.0
      ? std::min(options.LightCullingBound, 0.5 * options.ErrorBudget)
      : options.LightCullingBound;
    plan.CulledLights = vtkPhongLightCulling::Cull(ren, state.BoundsWC, plan.FrontMaterial,
      plan.BackMaterial, cullingBound, plan.PointLights, plan.SpotLights, plan.ErrorBound);
  }

  const bool allFeatures = !options.Specialize;
  if (allFeatures)
  {
    this->AddPlaceholderLights(plan);
  }
  Terms terms = ChooseTerms(plan, !switchedOn.empty(), allFeatures);
  // VTK draws a surface's edges by mixing the edge colour into ambientColor (and diffuseColor
  // to black): the ambient term must be there to show it, whatever the material's Ambient.
  terms.Ambient = terms.Ambient || (state.DrawingEdges && IsLitLikeFinal(plan.DebugView));
  SetTermFeatures(terms, plan);
  SetLightFeatures(terms, allFeatures, plan);
  SetMaterialFeatures(terms, allFeatures, plan);
  const Squaring squaring = SquaringOf(terms, options, plan);
  const auto budgetMode = BudgetChoosesMode(ren, actor, terms, state, options, squaring, plan);
  plan.BudgetMode = static_cast<int>(budgetMode);
  plan.Features.Set(Feature::DebugBudget, plan.DebugView == View::BudgetUse);
  const bool perVertex =
    SetInterpolationFeatures(terms, state, geometryView, budgetMode, ren, plan);
  plan.Features.Set(
    Feature::SpecularAntiAliasing, terms.Specular && !perVertex && options.SpecularAntiAliasing);
  SetWholeShininessFeature(squaring, options, plan);
  plan.BudgetShare = options.ErrorBudget > 0.0 ? plan.ErrorBound / options.ErrorBudget : 0.0;
  SetNormalFeatures(terms, state, perVertex, allFeatures, plan);
  if (this->InterpolatedDotLights == 0)
  {
    this->InterpolatedDotLights = MaximumInterpolatedDotLights();
  }
  SetInterpolatedDotsFeature(
    state, options.InterpolatedDots && !allFeatures, this->InterpolatedDotLights, plan);
  plan.Signature = MakeSignature(plan, allFeatures);
  return plan;
}

//------------------------------------------------------------------------------
// The passes vtkPhong does not light: vertex visibility, selection highlight, PBR, and VTK's
// lighting map passes (which need VTK's own light code to be present).
bool vtkPhongShaderPlanner::IsLeftToVTK(vtkActor* actor, const PrimitiveState& state)
{
  if (state.DrawingVertices || state.DrawingSelection ||
    actor->GetProperty()->GetInterpolation() == VTK_PBR)
  {
    return true;
  }
  vtkInformation* keys = actor->GetPropertyKeys();
  return keys &&
    (keys->Has(vtkLightingMapPass::RENDER_NORMALS()) ||
      keys->Has(vtkLightingMapPass::RENDER_LUMINANCE()));
}

//------------------------------------------------------------------------------
void vtkPhongShaderPlanner::SortLightsByKind(const std::vector<vtkLight*>& lights, Plan& plan)
{
  for (vtkLight* light : lights)
  {
    if (!light->GetPositional())
    {
      plan.DirectionalLights.push_back(light);
    }
    else if (light->GetConeAngle() < 90.0)
    {
      plan.SpotLights.push_back(light);
    }
    else
    {
      plan.PointLights.push_back(light);
    }
  }
}

//------------------------------------------------------------------------------
void vtkPhongShaderPlanner::PickDebugLight(
  const std::vector<vtkLight*>& lights, const Options& options, Plan& plan)
{
  if (options.DebugView != View::SingleLight)
  {
    return;
  }
  if (options.DebugLightIndex >= 0 && options.DebugLightIndex < static_cast<int>(lights.size()))
  {
    plan.DebugLight = lights[options.DebugLightIndex];
    return;
  }
  this->Log.Report(
    [&](std::ostream& os)
    {
      os << "DebugLightIndex " << options.DebugLightIndex << " names no light: the renderer has "
         << lights.size() << " switched-on lights; the single-light view is black.";
    });
}

//------------------------------------------------------------------------------
void vtkPhongShaderPlanner::AddPlaceholderLights(Plan& plan) const
{
  if (plan.DirectionalLights.empty())
  {
    plan.DirectionalLights.push_back(this->Placeholders.Directional);
  }
  if (plan.PointLights.empty())
  {
    plan.PointLights.push_back(this->Placeholders.Point);
  }
  if (plan.SpotLights.empty())
  {
    plan.SpotLights.push_back(this->Placeholders.Spot);
  }
}

//------------------------------------------------------------------------------
// A term has code when the debug view shows it and a material (front or back) has a non-zero
// coefficient for it; the all-features variant keeps every term. Light values that are zero
// have no code either: the ambient light of positional lights that give none.
vtkPhongShaderPlanner::Terms vtkPhongShaderPlanner::ChooseTerms(
  const Plan& plan, bool haveLights, bool allFeatures)
{
  const int view = plan.DebugView;
  const bool finalView = IsLitLikeFinal(view);
  const bool singleLight = view == View::SingleLight;
  vtkProperty* front = plan.FrontMaterial;
  vtkProperty* back = plan.BackMaterial;
  const bool all = allFeatures;
  const bool lights = haveLights || all;

  Terms terms;
  terms.Ambient = (finalView || view == View::AmbientTerm || singleLight) &&
    (all || IsPositive(front->GetAmbient()) || IsPositive(back->GetAmbient()));
  terms.Diffuse = (finalView || view == View::DiffuseTerm || singleLight) && lights &&
    (all || IsPositive(front->GetDiffuse()) || IsPositive(back->GetDiffuse()));
  terms.Specular = (finalView || view == View::SpecularTerm || singleLight) && lights &&
    (all || IsPositive(front->GetSpecular()) || IsPositive(back->GetSpecular()));
  terms.Emission = (finalView || view == View::EmissionTerm) &&
    (all || vtkPhongProperty::SafeDownCast(front) || vtkPhongProperty::SafeDownCast(back));
  const bool positional = !plan.PointLights.empty() || !plan.SpotLights.empty();
  terms.PositionalAmbient = terms.Ambient && positional &&
    (all || Any(plan.PointLights, HasAmbientLight) || Any(plan.SpotLights, HasAmbientLight));
  terms.LightSums = terms.Diffuse || terms.Specular || terms.PositionalAmbient;
  return terms;
}

//------------------------------------------------------------------------------
void vtkPhongShaderPlanner::SetTermFeatures(const Terms& terms, Plan& plan)
{
  vtkPhongFeatureSet& features = plan.Features;
  features.Set(Feature::Ambient, terms.Ambient);
  features.Set(Feature::Diffuse, terms.Diffuse);
  features.Set(Feature::Specular, terms.Specular);
  features.Set(Feature::DiffuseOrSpecular, terms.Diffuse || terms.Specular);
  features.Set(Feature::Emission, terms.Emission);
  features.Set(Feature::PositionalAmbient, terms.PositionalAmbient);
  features.Set(Feature::LightSums, terms.LightSums);
}

//------------------------------------------------------------------------------
// One code path per light kind present, and within it only the light values that are not
// neutral: the distance attenuation of lights with (c, l, q) = (1, 0, 0) and the falloff of
// spots with exponent 1 have no code.
void vtkPhongShaderPlanner::SetLightFeatures(const Terms& terms, bool allFeatures, Plan& plan)
{
  vtkPhongFeatureSet& features = plan.Features;
  const bool positional = !plan.PointLights.empty() || !plan.SpotLights.empty();
  const bool point = terms.LightSums && !plan.PointLights.empty();
  const bool spot = terms.LightSums && !plan.SpotLights.empty();
  features.Set(
    Feature::Directional, (terms.Diffuse || terms.Specular) && !plan.DirectionalLights.empty());
  features.Set(Feature::Point, point);
  features.Set(Feature::Spot, spot);
  features.Set(Feature::Positional, terms.LightSums && positional);
  const auto attenuated = &vtkPhongLightCulling::IsAttenuated;
  const bool pointAttenuation = point && (allFeatures || Any(plan.PointLights, attenuated));
  const bool spotAttenuation = spot && (allFeatures || Any(plan.SpotLights, attenuated));
  features.Set(Feature::PointAttenuation, pointAttenuation);
  features.Set(Feature::SpotAttenuation, spotAttenuation);
  features.Set(Feature::Attenuation, pointAttenuation || spotAttenuation);
  features.Set(Feature::SpotFalloff, spot && (allFeatures || Any(plan.SpotLights, HasSpotFalloff)));
  features.Set(
    Feature::SeparateSpecularColors, HasSeparateSpecularColors(terms, allFeatures, plan));
}

//------------------------------------------------------------------------------
// Whether the specular sums need light colours of their own. Every uniform array the lights'
// loops read costs each fragment on llvmpipe (8 directional lights at 1280x1024: 74.7 ms with
// a diffuse and a specular array, 64.3 ms with one), and VTK's neutral state is a specular
// colour equal to the diffuse one (vtkLight::SetColor sets both). So, like attenuation leaving
// (1, 0, 0), a specular colour leaving the diffuse colour is structure: without it the
// specular sums read the diffuse arrays, which hold the same values. Without the diffuse term
// there are no diffuse arrays, and the specular arrays are the only ones read anyway.
// The test runs over the lights in the shader (after culling): a culled light's colours are
// never uploaded. The single-light view uploads black for every light but the one shown.
bool vtkPhongShaderPlanner::HasSeparateSpecularColors(
  const Terms& terms, bool allFeatures, const Plan& plan)
{
  if (!terms.Specular)
  {
    return false;
  }
  if (allFeatures || !terms.Diffuse)
  {
    return true;
  }
  auto ownSpecular = [&plan](vtkLight* light)
  {
    const bool shown = plan.DebugView != View::SingleLight || light == plan.DebugLight;
    return shown && HasOwnSpecularColor(light);
  };
  auto anyOwn = [&](bool used, const std::vector<vtkLight*>& lights)
  { return used && std::any_of(lights.begin(), lights.end(), ownSpecular); };
  const vtkPhongFeatureSet& features = plan.Features;
  return anyOwn(features.Has(Feature::Directional), plan.DirectionalLights) ||
    anyOwn(features.Has(Feature::Point), plan.PointLights) ||
    anyOwn(features.Has(Feature::Spot), plan.SpotLights);
}

//------------------------------------------------------------------------------
void vtkPhongShaderPlanner::SetMaterialFeatures(const Terms& terms, bool allFeatures, Plan& plan)
{
  vtkPhongFeatureSet& features = plan.Features;
  auto* phongFront = vtkPhongProperty::SafeDownCast(plan.FrontMaterial);
  if (terms.Specular)
  {
    const int model = vtkPhongMaterial::LightingModelOf(plan.FrontMaterial);
    const bool blinn =
      model == vtkPhongProperty::BlinnPhong || model == vtkPhongProperty::NormalizedBlinnPhong;
    features.Set(Feature::LobeBlinn, blinn);
    features.Set(Feature::LobePhong, !blinn);
    features.Set(Feature::SmoothTerminator, phongFront && phongFront->GetSmoothTerminator());
    // A float cosine near 1 resolves 6e-8, which costs the lobe n * 6e-8 of itself: above
    // n = 1e3 (6e-5) the lobe comes from a difference vector (vtkPhongLightingLib.glsl).
    constexpr double NarrowShininess = 1.0e3;
    features.Set(Feature::NarrowLobe,
      allFeatures || vtkPhongMaterial::ShininessOf(plan.FrontMaterial) > NarrowShininess ||
        vtkPhongMaterial::ShininessOf(plan.BackMaterial) > NarrowShininess);
  }
  features.Set(Feature::SoftSpotEdge,
    features.Has(Feature::Spot) && (allFeatures || (phongFront && phongFront->GetSoftSpotEdge())));
  features.Set(Feature::BackMaterial, plan.BackMaterial != plan.FrontMaterial);
}

//------------------------------------------------------------------------------
// Under an error budget, where the surface's light sums go (vtkPhongErrorBudget): per vertex
// only on a smooth surface (point normals that are VTK's, any interpolation but flat) under
// directional lights only, without vtkShadowMapPass (per-vertex sums cannot read its
// factors) or specular anti-aliasing (the budget is defined against the unfiltered model),
// in the final view (or the BudgetUse view of it), with what light culling left of the budget.
vtkPhongGouraudBound::Mode vtkPhongShaderPlanner::BudgetChoosesMode(vtkRenderer* ren,
  vtkActor* actor, const Terms& terms, const PrimitiveState& state, const Options& options,
  const Squaring& squaring, Plan& plan)
{
  using Mode = vtkPhongGouraudBound::Mode;
  vtkPhongGouraudBound* triangles = state.Triangles;
  const bool smooth = state.ShadesWithPointNormals() && !state.NormalsMayBeInvalid &&
    plan.FrontMaterial->GetInterpolation() != VTK_FLAT;
  const bool shadowed = DrawnUnderShadowMaps(actor);
  if (!triangles || !(options.ErrorBudget > 0.0) || !IsLitLikeFinal(options.DebugView) ||
    !terms.LightSums || terms.PositionalAmbient || !smooth || shadowed || !options.Specialize ||
    options.SpecularAntiAliasing)
  {
    return Mode::PerFragment;
  }
  // Per fragment, would the lobes be squared? Then the specular sums per vertex pay only for
  // many lobes (vtkPhongErrorBudget::ChooseMode).
  double bound = 0.0;
  triangles->Chosen = vtkPhongErrorBudget::ChooseMode(ren, actor, plan, *triangles, state.BoundsWC,
    options.ErrorBudget - plan.ErrorBound, triangles->Chosen, squaring.Fits(plan, options), bound);
  plan.ErrorBound += bound;
  return triangles->Chosen;
}

//------------------------------------------------------------------------------
// vtkShadowMapPass lists itself in each prop's render passes while it draws them.
bool vtkPhongShaderPlanner::DrawnUnderShadowMaps(vtkActor* actor)
{
  vtkInformation* keys = actor->GetPropertyKeys();
  vtkInformationObjectBaseVectorKey* passes = vtkOpenGLRenderPass::RenderPasses();
  const int count = keys && keys->Has(passes) ? keys->Length(passes) : 0;
  for (int i = 0; i < count; ++i)
  {
    if (vtkShadowMapPass::SafeDownCast(keys->Get(passes, i)))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
// Where the light sums are evaluated (per vertex for vtkPhongProperty's true Gouraud on
// surfaces with point normals, or where the error budget chose it), and the view and
// sidedness. Returns whether per vertex.
bool vtkPhongShaderPlanner::SetInterpolationFeatures(const Terms& terms,
  const PrimitiveState& state, bool geometryView, vtkPhongGouraudBound::Mode budgetMode,
  vtkRenderer* ren, Plan& plan)
{
  vtkPhongFeatureSet& features = plan.Features;
  vtkProperty* front = plan.FrontMaterial;
  auto* phongFront = vtkPhongProperty::SafeDownCast(front);
  vtkCamera* camera = ren->GetActiveCamera();
  features.Set(Feature::Parallel, camera && camera->GetParallelProjection());

  const bool perVertex = budgetMode != vtkPhongGouraudBound::Mode::PerFragment ||
    (terms.LightSums && phongFront && phongFront->GetPerVertexGouraud() &&
      front->GetInterpolation() == VTK_GOURAUD && state.HasPointNormals &&
      !state.NormalsFromShape && !geometryView);
  features.Set(Feature::PerVertex, perVertex);
  features.Set(Feature::SumsPerVertex, terms.LightSums && perVertex);
  features.Set(Feature::SumsPerFragment, terms.LightSums && !perVertex);
  features.Set(Feature::DiffusePerFragment,
    terms.Diffuse && budgetMode == vtkPhongGouraudBound::Mode::SpecularPerVertex);
  features.Set(Feature::GeometryPassThrough, perVertex && state.HasGeometryShader);
  features.Set(Feature::TwoSided, ren->GetTwoSidedLighting() != 0);
  return perVertex;
}

//------------------------------------------------------------------------------
void vtkPhongShaderPlanner::SetNormalFeatures(
  const Terms& terms, const PrimitiveState& state, bool perVertex, bool allFeatures, Plan& plan)
{
  vtkPhongFeatureSet& features = plan.Features;
  const int view = plan.DebugView;
  features.Set(Feature::DebugNormal, view == View::ShadingNormal);
  features.Set(Feature::DebugNormalVC, view == View::NormalVC);
  features.Set(Feature::DebugPositionVC, view == View::PositionVC);

  const bool normalView = view == View::ShadingNormal || view == View::NormalVC;
  const bool shadingNormal =
    (terms.LightSums && !perVertex) || normalView || features.Has(Feature::DiffusePerFragment);
  features.Set(Feature::ShadingNormal, shadingNormal);
  features.Set(Feature::OneSided, shadingNormal && !features.Has(Feature::TwoSided));
  // Zero, NaN or infinite normals in the data take the face's geometric normal
  // from screen-space derivatives, which cost every fragment: only when the
  // mapper found such normals. Otherwise a cheap guard covers normals that
  // cancel out when interpolated.
  features.Set(Feature::NormalFallback,
    shadingNormal && (state.NormalsMayBeInvalid || allFeatures) &&
      (state.HasPointNormals || state.HasCellNormals) && !state.NormalsFromShape);
  features.Set(Feature::ViewVector, shadingNormal);
}

//------------------------------------------------------------------------------
// Per-fragment directional lights can take N.L and L.V from dot products evaluated at the
// vertices (INTERPOLATED_DOTS, vtkPhongLightingLib.glsl): exact, and it saves each fragment a
// uniform read and two dot products per light (8 directional lights on the 130k-triangle
// sphere at 1280x1024: the lighting's 30 ms drops by a fifth, docs/results/performance.md).
// Only where the shading normal is VTK's interpolated vertex normal, normalized and flipped:
// no cell normals, impostors, geometry shader, normal fallback or shader code of the user's
// (which may change the normal; vtkPhongShaderTemplate also checks VTK's normal code), with
// the Phong lobe (the Blinn halfway vector needs L itself) and as many lights as the varyings
// carry; `allowed`: the mapper's InterpolatedDotProducts, and not the all-features variant.
// Not with a narrow lobe (NARROW_LOBE: from dot products the lobe's t = 1 - R.V carries their
// rounding, 2e-3 of the colour at n = 1e4).
void vtkPhongShaderPlanner::SetInterpolatedDotsFeature(
  const PrimitiveState& state, bool allowed, std::size_t maximumLights, Plan& plan)
{
  const vtkPhongFeatureSet& features = plan.Features;
  // The per-fragment diffuse sum beside per-vertex specular sums takes N.L alone: any lobe.
  const bool lobeFromDots = features.Has(Feature::DiffusePerFragment) ||
    (features.Has(Feature::SumsPerFragment) && !features.Has(Feature::NarrowLobe) &&
      !features.Has(Feature::LobeBlinn));
  plan.Features.Set(Feature::InterpolatedDots,
    allowed && state.ShadesWithPointNormals() && lobeFromDots &&
      features.Has(Feature::Directional) && !features.Has(Feature::NormalFallback) &&
      plan.DirectionalLights.size() <= maximumLights);
}

//------------------------------------------------------------------------------
std::size_t vtkPhongShaderPlanner::MaximumInterpolatedDotLights()
{
  constexpr GLint keptForVTK = 32;
  GLint components = 60; // the least an OpenGL 3.2 context offers
  glGetIntegerv(GL_MAX_FRAGMENT_INPUT_COMPONENTS, &components);
  const GLint lights = 4 * std::max(0, (components - keptForVTK) / 8);
  return static_cast<std::size_t>(std::min(lights, 64));
}

//------------------------------------------------------------------------------
// Under an error budget, a whole shininess n from 2 to 1e3 (both faces alike) raises the
// lobe's cosine by squaring: at most 19 products where llvmpipe's pow takes a logarithm
// and an exponential. Its rounding, and the rounding a program other than the exact one makes
// its own way (vtkPhongErrorBudget::WholePowerError), is charged to the budget, and the
// squaring used only where that fits what is left. Not in the exact mode (its
// shaders stay those of a mapper without a budget), nor with specular anti-aliasing, whose
// shininess varies per fragment, nor above 1e3 (NARROW_LOBE). Each shininess is its own
// program, compiled once and cached.
void vtkPhongShaderPlanner::SetWholeShininessFeature(
  const Squaring& squaring, const Options& options, Plan& plan)
{
  const bool whole = squaring.Fits(plan, options);
  plan.Features.Set(Feature::WholeShininess, whole);
  plan.WholeShininess = whole ? squaring.Shininess : 0;
  plan.ErrorBound += whole ? squaring.Error : 0.0;
}

//------------------------------------------------------------------------------
// The shininess SetWholeShininessFeature may square and its charge, made once per plan: the
// mode's choice asks whether the squaring would fit before it spends its own bound.
vtkPhongShaderPlanner::Squaring vtkPhongShaderPlanner::SquaringOf(
  const Terms& terms, const Options& options, const Plan& plan)
{
  const double n = vtkPhongMaterial::ShininessOf(plan.FrontMaterial);
  const bool whole = options.ErrorBudget > 0.0 && options.Specialize && terms.Specular &&
    !plan.Has(Feature::NarrowLobe) && !options.SpecularAntiAliasing && n >= 2.0 && n <= 1.0e3 &&
    n == std::floor(n) && vtkPhongMaterial::ShininessOf(plan.BackMaterial) == n;
  Squaring squaring;
  if (whole)
  {
    squaring.Shininess = static_cast<int>(n);
    squaring.Error = vtkPhongErrorBudget::WholePowerError(plan, squaring.Shininess);
  }
  return squaring;
}

//------------------------------------------------------------------------------
// Whether the squaring's charge fits what is left of the budget.
bool vtkPhongShaderPlanner::Squaring::Fits(const Plan& plan, const Options& options) const
{
  return this->Shininess > 0 && plan.ErrorBound + this->Error <= options.ErrorBudget;
}

//------------------------------------------------------------------------------
bool vtkPhongShaderPlanner::MayTakeConstants(const Plan& plan, const Options& options)
{
  const std::size_t lights =
    plan.DirectionalLights.size() + plan.PointLights.size() + plan.SpotLights.size();
  return plan.Handled && !plan.DepthOnly && options.ErrorBudget > 0.0 && options.Specialize &&
    IsLitLikeFinal(plan.DebugView) && lights > 0 && lights <= 64 &&
    plan.ErrorBound + ConstantsCharge(plan) <= options.ErrorBudget;
}

//------------------------------------------------------------------------------
// The rounding another program makes its own way; the squaring's charge covers it already.
double vtkPhongShaderPlanner::ConstantsCharge(const Plan& plan)
{
  return plan.Has(Feature::WholeShininess) ? 0.0 : vtkPhongErrorBudget::ProgramRoundingError(plan);
}

//------------------------------------------------------------------------------
bool vtkPhongShaderPlanner::SetConstants(
  vtkPhongUniformValues values, const Options& options, Plan& plan)
{
  const double charge = ConstantsCharge(plan);
  std::ostringstream bits;
  bits << std::hex;
  for (const vtkPhongUniformValue& uniform : values)
  {
    for (float value : uniform.Values)
    {
      if (!std::isfinite(value))
      {
        return false;
      }
      std::uint32_t word;
      std::memcpy(&word, &value, sizeof(word));
      bits << word << ' ';
    }
  }
  plan.Features.Set(Feature::UniformConstants);
  plan.Constants = std::move(values);
  plan.ErrorBound += charge;
  plan.BudgetShare = plan.ErrorBound / options.ErrorBudget;
  plan.Signature = MakeSignature(plan, false) + " | constants " + bits.str();
  return true;
}

//------------------------------------------------------------------------------
std::string vtkPhongShaderPlanner::MakeSignature(const Plan& plan, bool allFeatures)
{
  const vtkPhongFeatureSet& features = plan.Features;
  auto countIf = [](bool used, const std::vector<vtkLight*>& lights)
  { return used ? lights.size() : 0; };
  std::ostringstream signature;
  signature << features.GetNames() << "| directional "
            << countIf(features.Has(Feature::Directional), plan.DirectionalLights) << " point "
            << countIf(features.Has(Feature::Point), plan.PointLights) << " spot "
            << countIf(features.Has(Feature::Spot), plan.SpotLights) << " | view " << plan.DebugView
            << (plan.WholeShininess > 0 ? " | shininess " + std::to_string(plan.WholeShininess)
                                        : std::string())
            << (allFeatures ? " | all features" : "");
  return signature.str();
}
