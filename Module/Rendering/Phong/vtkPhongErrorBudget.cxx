#include "vtkPhongErrorBudget.h"

#include "vtkActor.h"
#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPhongAttenuation.h"
#include "vtkPhongLightCulling.h"
#include "vtkPhongLightGeometry.h"
#include "vtkPhongMaterial.h"
#include "vtkPhongProperty.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>

namespace
{
using Vector = std::array<double, 3>;

// The rounding of float lighting against the double model, for lights whose largest
// contributions add up to `contributions`: 0.01 level plus 2e-5 of them.
double RoundingMargin(double contributions)
{
  return 0.01 / 255.0 + 2.0e-5 * contributions;
}

// The largest over channels of weight[c] * colour[c] * intensity.
double Strength(const double weight[3], const double* color, double intensity)
{
  double largest = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    largest =
      std::max(largest, weight[c] * vtkPhongLightGeometry::UploadedColor(color[c], intensity));
  }
  return largest;
}

// The model-to-view matrix and its scale s (view units per model unit), or false when its
// linear part A does not keep angles (A^T A is not s^2 I to 1e-6): per-vertex bounds are in
// the angles of the model's normals.
bool SimilarityToView(vtkRenderer* ren, vtkActor* actor, vtkMatrix4x4* modelToView, double& scale)
{
  vtkMatrix4x4::Multiply4x4(
    ren->GetActiveCamera()->GetModelViewTransformMatrix(), actor->GetMatrix(), modelToView);
  double gram[3][3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      gram[i][j] = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        gram[i][j] += modelToView->GetElement(k, i) * modelToView->GetElement(k, j);
      }
    }
  }
  const double squared = gram[0][0];
  if (!(squared > 0.0) || !std::isfinite(squared))
  {
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      if (std::abs(gram[i][j] - (i == j ? squared : 0.0)) > 1.0e-6 * squared)
      {
        return false;
      }
    }
  }
  scale = std::sqrt(squared);
  return true;
}

// A view-coordinate direction in model coordinates (A^-1 v, unit): the dot products with
// the model's normals keep their angles under a similarity.
Vector ToModel(vtkMatrix4x4* viewToModel, const double directionVC[3])
{
  Vector v;
  for (int i = 0; i < 3; ++i)
  {
    v[i] = viewToModel->GetElement(i, 0) * directionVC[0] +
      viewToModel->GetElement(i, 1) * directionVC[1] +
      viewToModel->GetElement(i, 2) * directionVC[2];
  }
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (double& component : v)
  {
    component /= length;
  }
  return v;
}
}

//------------------------------------------------------------------------------
vtkPhongErrorBudget::Mode vtkPhongErrorBudget::ChooseMode(vtkRenderer* ren, vtkActor* actor,
  const vtkPhongShaderPlan& plan, vtkPhongGouraudBound& triangles, const double boundsWC[6],
  double available, Mode last, bool squared, double& bound)
{
  bound = 0.0;
  vtkPhongGouraudBound::Scene scene;
  if (!plan.SpotLights.empty() || !MakeScene(ren, actor, plan, scene) ||
    !PerVertexIsCheaper(ren, boundsWC, triangles, scene.TwoSided))
  {
    return Mode::PerFragment;
  }
  const double share = available - FloatMargin(scene);
  // No mode takes a bound above the share: the bound may stop once both modes pass it.
  const vtkPhongGouraudBound::Bounds bounds = triangles.Bound(scene, share);
  // A mode at least as cheap as the last one must fit within 0.8 of the share to be taken,
  // within all of it to be kept.
  const auto fits = [&](double modeBound, Mode mode)
  { return modeBound <= (last >= mode ? 1.0 : 0.8) * share; };
  if (fits(bounds.PerVertex, Mode::PerVertex))
  {
    bound = bounds.PerVertex;
    return Mode::PerVertex;
  }
  if (fits(bounds.SpecularPerVertex, Mode::SpecularPerVertex) &&
    SpecularPerVertexPays(scene, squared))
  {
    bound = bounds.SpecularPerVertex;
    return Mode::SpecularPerVertex;
  }
  return Mode::PerFragment;
}

//------------------------------------------------------------------------------
// The specular sums per vertex save each fragment the lobes, and cost it the interpolated
// normal's scale and more inputs (llvmpipe, sphere 256 at 1280 x 1024, docs/results/
// performance.md). Against lobes raised by pow: 1.0x exact at one light, 0.85x at 8, so from
// two lobes. Against lobes squared per fragment: 1.03-1.06x at 8 directional lights, 1.0x at
// 16, 0.81x at 24, so from 20.
bool vtkPhongErrorBudget::SpecularPerVertexPays(
  const vtkPhongGouraudBound::Scene& scene, bool squared)
{
  std::size_t lobes = 0;
  for (const auto& light : scene.Lights)
  {
    lobes += light.Specular > 0.0 ? 1 : 0;
  }
  return lobes >= (squared ? 20 : 2);
}

//------------------------------------------------------------------------------
double vtkPhongErrorBudget::FloatMargin(const vtkPhongGouraudBound::Scene& scene)
{
  double largest = 0.0;
  for (const auto& light : scene.Lights)
  {
    // A(d) <= 1 / c (c > 0: AddPointLights).
    largest += (light.Diffuse + light.Specular) / light.AttenuationMC.Coefficients[0];
  }
  return RoundingMargin(largest);
}

//------------------------------------------------------------------------------
bool vtkPhongErrorBudget::MakeScene(vtkRenderer* ren, vtkActor* actor,
  const vtkPhongShaderPlan& plan, vtkPhongGouraudBound::Scene& scene)
{
  vtkProperty* front = plan.FrontMaterial;
  vtkProperty* back = plan.BackMaterial;
  const double shininess = vtkPhongMaterial::ShininessOf(front);
  vtkNew<vtkMatrix4x4> modelToView, viewToModel;
  double viewPerModel = 1.0;
  if (shininess != vtkPhongMaterial::ShininessOf(back) ||
    !SimilarityToView(ren, actor, modelToView, viewPerModel))
  {
    return false;
  }
  vtkMatrix4x4::Invert(modelToView, viewToModel);
  const int model = vtkPhongMaterial::LightingModelOf(front);
  scene.Shininess = shininess;
  scene.Blinn =
    model == vtkPhongProperty::BlinnPhong || model == vtkPhongProperty::NormalizedBlinnPhong;
  auto* phongFront = vtkPhongProperty::SafeDownCast(front);
  scene.SmoothTerminator = phongFront && phongFront->GetSmoothTerminator();
  scene.TwoSided = ren->GetTwoSidedLighting() != 0;
  vtkCamera* camera = ren->GetActiveCamera();
  scene.Parallel = camera->GetParallelProjection() != 0;
  const double toEyeVC[3] = { 0.0, 0.0, 1.0 };
  scene.ToEyeMC = ToModel(viewToModel, toEyeVC);
  const double eye[4] = { 0.0, 0.0, 0.0, 1.0 };
  double eyeMC[4];
  viewToModel->MultiplyPoint(eye, eyeMC);
  for (int i = 0; i < 3; ++i)
  {
    scene.EyeMC[i] = eyeMC[i] / eyeMC[3];
  }

  double weights[3][3];
  vtkPhongLightCulling::MaterialWeights(front, back, weights);
  for (vtkLight* light : plan.DirectionalLights)
  {
    const vtkPhongLightGeometry geometry = vtkPhongLightGeometry::InView(light, ren);
    const double toLightVC[3] = { -geometry.DirectionVC[0], -geometry.DirectionVC[1],
      -geometry.DirectionVC[2] };
    vtkPhongGouraudBound::Scene::Light bounded;
    bounded.ToLightMC = ToModel(viewToModel, toLightVC);
    bounded.Diffuse = Strength(weights[1], light->GetDiffuseColor(), light->GetIntensity());
    bounded.Specular = Strength(weights[2], light->GetSpecularColor(), light->GetIntensity());
    scene.Lights.push_back(bounded);
  }
  return AddPointLights(ren, plan, viewToModel, viewPerModel, weights, scene);
}

//------------------------------------------------------------------------------
// Point lights, their attenuation as the shader takes it (vtkPhongAttenuation::Of) in model
// units: the view's distances are the model's times the similarity's scale `viewPerModel`. A
// constant term of 0 leaves the scene unbounded (false): the attenuation then has no largest
// value for the float margin (FloatMargin).
bool vtkPhongErrorBudget::AddPointLights(vtkRenderer* ren, const vtkPhongShaderPlan& plan,
  vtkMatrix4x4* viewToModel, double viewPerModel, const double weights[3][3],
  vtkPhongGouraudBound::Scene& scene)
{
  for (vtkLight* light : plan.PointLights)
  {
    const vtkPhongAttenuation attenuation = vtkPhongAttenuation::Of(light);
    if (!(attenuation.Coefficients[0] > 0.0))
    {
      return false;
    }
    const vtkPhongLightGeometry geometry = vtkPhongLightGeometry::InView(light, ren);
    const double positionVC[4] = { geometry.PositionVC[0], geometry.PositionVC[1],
      geometry.PositionVC[2], 1.0 };
    double positionMC[4];
    viewToModel->MultiplyPoint(positionVC, positionMC);
    vtkPhongGouraudBound::Scene::Light bounded;
    bounded.Positional = true;
    bounded.ToLightMC = { { 0.0, 0.0, 1.0 } };
    for (int i = 0; i < 3; ++i)
    {
      bounded.PositionMC[i] = positionMC[i] / positionMC[3];
    }
    bounded.Diffuse = Strength(weights[1], light->GetDiffuseColor(), light->GetIntensity());
    bounded.Specular = Strength(weights[2], light->GetSpecularColor(), light->GetIntensity());
    bounded.AttenuationMC = attenuation.Scaled(viewPerModel);
    scene.Lights.push_back(bounded);
  }
  return true;
}

//------------------------------------------------------------------------------
// Per-vertex lighting costs vertices x sides x lights, per-fragment lighting fragments x
// lights; a vertex-light-side is taken to cost twice a fragment-light (an estimate: the
// crossover near 2 pixels a triangle). The fragments are taken as the screen area of the
// surface's bounding sphere, within the viewport, so sub-pixel meshes stay per fragment.
bool vtkPhongErrorBudget::PerVertexIsCheaper(
  vtkRenderer* ren, const double boundsWC[6], const vtkPhongGouraudBound& triangles, bool twoSided)
{
  vtkCamera* camera = ren->GetActiveCamera();
  int* size = ren->GetSize();
  if (!vtkMath::AreBoundsInitialized(boundsWC) || size[1] <= 0)
  {
    return false;
  }
  const vtkBoundingBox box(boundsWC);
  double centre[3];
  box.GetCenter(centre);
  const double radius = 0.5 * box.GetDiagonalLength();
  double halfHeight = camera->GetParallelScale(); // world units over half the viewport
  if (!camera->GetParallelProjection())
  {
    const double distance =
      std::sqrt(vtkMath::Distance2BetweenPoints(centre, camera->GetPosition()));
    halfHeight = distance * std::tan(vtkMath::RadiansFromDegrees(0.5 * camera->GetViewAngle()));
  }
  if (!(halfHeight > 0.0))
  {
    return false;
  }
  const double radiusPixels = radius / halfHeight * 0.5 * size[1];
  const double fragments =
    std::min(vtkMath::Pi() * radiusPixels * radiusPixels, double(size[0]) * double(size[1]));
  const double vertexWork =
    2.0 * static_cast<double>(triangles.GetNumberOfPoints()) * (twoSided ? 2.0 : 1.0);
  return vertexWork <= fragments;
}

//------------------------------------------------------------------------------
double vtkPhongErrorBudget::WholePowerError(const vtkPhongShaderPlan& plan, int n)
{
  if (n < 1)
  {
    return 0.0;
  }
  // The roundings, each raised to the factors it enters: n in all (the header).
  const double u = std::ldexp(1.0, -24);
  const double gamma = n * u / (1.0 - n * u);
  double specular = 0.0, lights = 0.0;
  LargestContributions(plan, specular, lights);
  // The products' own rounding; then, since the program is not the exact mode's, the rounding
  // both programs share but each makes its own way: the cosine's (8 u, which the lobe
  // multiplies by up to n) and the lighting's, the per-vertex modes' float margin (FloatMargin).
  const double error = (gamma + 8.0 * n * u) * specular + RoundingMargin(lights);
  return std::isfinite(error) ? error : HUGE_VAL;
}

//------------------------------------------------------------------------------
double vtkPhongErrorBudget::ProgramRoundingError(const vtkPhongShaderPlan& plan)
{
  double specular = 0.0, lights = 0.0;
  LargestContributions(plan, specular, lights);
  const double error = RoundingMargin(lights);
  return std::isfinite(error) ? error : HUGE_VAL;
}

//------------------------------------------------------------------------------
// The lights' largest contributions (intensity, colours, largest attenuation, the materials'
// weights and the lobe's normalization): the specular ones, and all.
void vtkPhongErrorBudget::LargestContributions(
  const vtkPhongShaderPlan& plan, double& specular, double& lights)
{
  double weights[3][3];
  vtkPhongLightCulling::MaterialWeights(plan.FrontMaterial, plan.BackMaterial, weights);
  specular = 0.0;
  lights = 0.0;
  const auto add = [&](vtkLight* light, bool positional)
  {
    // A(d) = 1 / max(c + l d + q d^2, 1e-20) <= 1 / c for d, l, q >= 0.
    const double* attenuation = light->GetAttenuationValues();
    const bool attenuated =
      positional && !(attenuation[0] == 1.0 && attenuation[1] == 0.0 && attenuation[2] == 0.0);
    const double largestAttenuation = !attenuated ? 1.0
      : attenuation[0] > 0.0 && attenuation[1] >= 0.0 && attenuation[2] >= 0.0
      ? 1.0 / attenuation[0]
      : HUGE_VAL;
    // The specular sums take the light's specular colour, or its diffuse one where VTK's
    // colours do not differ (vtkPhongLightUniforms): the larger of the two, as uploaded.
    const double intensity = light->GetIntensity();
    const double lobe = std::max(Strength(weights[2], light->GetSpecularColor(), intensity),
      Strength(weights[2], light->GetDiffuseColor(), intensity));
    const double diffuse = Strength(weights[1], light->GetDiffuseColor(), intensity);
    specular += largestAttenuation * lobe;
    lights += largestAttenuation * (lobe + diffuse);
  };
  for (vtkLight* light : plan.DirectionalLights)
  {
    add(light, false);
  }
  for (auto* positional : { &plan.PointLights, &plan.SpotLights })
  {
    for (vtkLight* light : *positional)
    {
      add(light, true);
    }
  }
}
