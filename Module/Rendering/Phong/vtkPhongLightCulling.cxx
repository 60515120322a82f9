#include "vtkPhongLightCulling.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPhongAttenuation.h"
#include "vtkPhongLightGeometry.h"
#include "vtkPhongMaterial.h"
#include "vtkPhongProblemLog.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>

namespace
{
// A light or material value as the uniforms upload it: non-finite or negative light values
// are 0 (vtkPhongLightUniforms); material values may be negative, so their size counts.
double LightValue(double value)
{
  return (value >= 0.0 && std::isfinite(value)) ? value : 0.0;
}

double Size(double value)
{
  return std::isfinite(value) ? std::abs(value) : 0.0;
}

// Whether every parameter of the light is one the uniforms take as it is: a light with a
// value they substitute (and report) is never culled, so that its report is not lost.
bool IsPlain(vtkLight* light)
{
  auto within = [](double value, double largest) { return value >= 0.0 && value <= largest; };
  const double largest = vtkPhongProblemLog::LargestValue;
  bool plain = within(light->GetIntensity(), largest) && within(light->GetExponent(), largest) &&
    std::isfinite(light->GetConeAngle());
  for (int c = 0; c < 3; ++c)
  {
    plain = plain && within(light->GetAmbientColor()[c], largest) &&
      within(light->GetDiffuseColor()[c], largest) &&
      within(light->GetSpecularColor()[c], largest) &&
      within(light->GetAttenuationValues()[c], vtkPhongProblemLog::LargestAttenuation) &&
      within(light->GetAmbientColor()[c] * light->GetIntensity(), largest) &&
      within(light->GetDiffuseColor()[c] * light->GetIntensity(), largest) &&
      within(light->GetSpecularColor()[c] * light->GetIntensity(), largest) &&
      std::isfinite(light->GetPosition()[c]) && std::isfinite(light->GetFocalPoint()[c]);
  }
  return plain;
}

// The smallest distance from p to the box (0 inside it).
double DistanceToBox(const double p[3], const double box[6])
{
  double squared = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double below = box[2 * i] - p[i], above = p[i] - box[2 * i + 1];
    const double outside = std::max({ below, above, 0.0 });
    squared += outside * outside;
  }
  return std::sqrt(squared);
}

// How near the light the shader may find a point of the box even where it lies `d` away: its
// float distance rounds. 1e-6 of the largest coordinate (float resolves 6e-8 of it).
double FloatReach(const double positionVC[3], const double box[6])
{
  double largest = 1.0;
  for (int i = 0; i < 3; ++i)
  {
    largest = std::max(
      { largest, std::abs(positionVC[i]), std::abs(box[2 * i]), std::abs(box[2 * i + 1]) });
  }
  return 1.0e-6 * largest;
}

// The largest spot factor pow(cos_phi, exponent) (or 0 outside the cone) over the box's
// bounding sphere, the shader's least distance to the box being `nearest`. Where that may be 0
// (a light at a point of the box, to float's resolution) the shader takes L = N and
// cos_phi = -N.axis, up to 1: then 1. The sphere seen from the light spans a half-angle
// asin(r / distance); the smallest angle to the axis is the centre's minus that. Outside the
// cone only by a margin (0.01 degrees) counts as outside: the shader compares cosines in float.
double SpotFactorBound(vtkLight* light, const double positionVC[3], const double axisVC[3],
  const double box[6], double nearest)
{
  double center[3], toCenter[3];
  double radius = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    center[i] = 0.5 * (box[2 * i] + box[2 * i + 1]);
    radius += 0.25 * (box[2 * i + 1] - box[2 * i]) * (box[2 * i + 1] - box[2 * i]);
    toCenter[i] = center[i] - positionVC[i];
  }
  radius = std::sqrt(radius);
  const double distance = vtkMath::Norm(toCenter);
  const double axisLength = vtkMath::Norm(axisVC);
  if (!(distance > radius) || !(axisLength > 0.0) || nearest == 0.0)
  {
    return 1.0; // the light is inside the sphere, may be at the box, or has no axis
  }
  const double cosAngle =
    std::max(-1.0, std::min(1.0, vtkMath::Dot(toCenter, axisVC) / (distance * axisLength)));
  const double angle = vtkMath::DegreesFromRadians(std::acos(cosAngle));
  const double spread = vtkMath::DegreesFromRadians(std::asin(radius / distance));
  const double nearestAngle = std::max(angle - spread, 0.0);
  const double cone = std::max(light->GetConeAngle(), 0.0);
  if (nearestAngle > cone + 0.01)
  {
    return 0.0;
  }
  const double exponent =
    std::min(LightValue(light->GetExponent()), vtkPhongProblemLog::LargestValue);
  if (exponent == 0.0 || nearestAngle >= 90.0)
  {
    return 1.0;
  }
  return std::pow(std::cos(vtkMath::RadiansFromDegrees(nearestAngle)), exponent);
}
}

//------------------------------------------------------------------------------
int vtkPhongLightCulling::Cull(vtkRenderer* ren, const double boundsWC[6], vtkProperty* front,
  vtkProperty* back, double bound, std::vector<vtkLight*>& points, std::vector<vtkLight*>& spots,
  double& spent)
{
  spent = 0.0;
  double boxVC[6];
  if (!(bound > 0.0) || (points.empty() && spots.empty()) ||
    !TransformBox(boundsWC, ren->GetActiveCamera()->GetModelViewTransformMatrix(), boxVC))
  {
    return 0;
  }
  double weights[3][3];
  MaterialWeights(front, back, weights);
  struct Candidate
  {
    vtkLight* Light;
    double Bound;
  };
  std::vector<Candidate> candidates;
  for (auto* lights : { &points, &spots })
  {
    const bool isSpot = lights == &spots;
    for (vtkLight* light : *lights)
    {
      // VTK moves headlights and camera lights by its user light transform (VR) in view
      // coordinates; those are left alone, and so are lights with values to report.
      if (vtkPhongLightGeometry::IsUserTransformed(light, ren) || !IsPlain(light))
      {
        continue;
      }
      const vtkPhongLightGeometry geometry = vtkPhongLightGeometry::InView(light, ren);
      const double noAxis[3] = { 0.0, 0.0, 0.0 };
      const double* axisVC = geometry.HasDirection ? geometry.DirectionVC : noAxis;
      const double b =
        ContributionBound(light, isSpot, geometry.PositionVC, axisVC, boxVC, weights);
      if (std::isfinite(b))
      {
        candidates.push_back({ light, b });
      }
    }
  }
  // The smallest first, while their sum stays within the bound.
  std::stable_sort(candidates.begin(), candidates.end(),
    [](const Candidate& a, const Candidate& b) { return a.Bound < b.Bound; });
  std::vector<vtkLight*> dropped;
  double sum = 0.0;
  for (const Candidate& candidate : candidates)
  {
    if (sum + candidate.Bound > bound)
    {
      break;
    }
    sum += candidate.Bound;
    dropped.push_back(candidate.Light);
  }
  spent = sum;
  for (auto* lights : { &points, &spots })
  {
    lights->erase(std::remove_if(lights->begin(), lights->end(),
                    [&](vtkLight* light)
                    { return std::find(dropped.begin(), dropped.end(), light) != dropped.end(); }),
      lights->end());
  }
  return static_cast<int>(dropped.size());
}

//------------------------------------------------------------------------------
double vtkPhongLightCulling::ContributionBound(vtkLight* light, bool isSpot,
  const double lightPositionVC[3], const double spotAxisVC[3], const double boxVC[6],
  const double materialWeight[3][3])
{
  const double* colors[3] = { light->GetAmbientColor(), light->GetDiffuseColor(),
    light->GetSpecularColor() };
  double largest = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    double channel = 0.0;
    for (int term = 0; term < 3; ++term)
    {
      channel += materialWeight[term][c] *
        vtkPhongLightGeometry::UploadedColor(colors[term][c], light->GetIntensity());
    }
    largest = std::max(largest, channel);
  }
  if (largest == 0.0)
  {
    return 0.0;
  }
  // The nearest point's distance, less what the shader's float distance may lose.
  const double nearest =
    std::max(DistanceToBox(lightPositionVC, boxVC) - FloatReach(lightPositionVC, boxVC), 0.0);
  const double spot =
    isSpot ? SpotFactorBound(light, lightPositionVC, spotAxisVC, boxVC, nearest) : 1.0;
  // The attenuation falls with the distance: at most its value at the nearest point.
  return spot == 0.0 ? 0.0 : spot * largest * vtkPhongAttenuation::Of(light).At(nearest);
}

//------------------------------------------------------------------------------
bool vtkPhongLightCulling::IsAttenuated(vtkLight* light)
{
  return !vtkPhongAttenuation::Of(light).IsNone();
}

//------------------------------------------------------------------------------
// Colours from scalars or textures replace Ca and Cd and are at most 1 (8-bit colours), so
// those count as max(1, the material's). The lobe normalization is folded into Cs as the
// material uniforms do (with the front material's lobe on both sides).
void vtkPhongLightCulling::MaterialWeights(
  vtkProperty* front, vtkProperty* back, double weights[3][3])
{
  const int model = vtkPhongMaterial::LightingModelOf(front);
  for (int term = 0; term < 3; ++term)
  {
    for (int c = 0; c < 3; ++c)
    {
      weights[term][c] = 0.0;
    }
  }
  for (vtkProperty* material : { front, back })
  {
    const double normalization =
      vtkPhongMaterial::LobeNormalization(model, vtkPhongMaterial::ShininessOf(material));
    const double k[3] = { Size(material->GetAmbient()), Size(material->GetDiffuse()),
      Size(material->GetSpecular()) * Size(normalization) };
    const double* colors[3] = { material->GetAmbientColor(), material->GetDiffuseColor(),
      material->GetSpecularColor() };
    for (int term = 0; term < 3; ++term)
    {
      for (int c = 0; c < 3; ++c)
      {
        const double color =
          term < 2 ? std::max(1.0, Size(colors[term][c])) : Size(colors[term][c]);
        weights[term][c] = std::max(weights[term][c], k[term] * color);
      }
    }
  }
}

//------------------------------------------------------------------------------
bool vtkPhongLightCulling::TransformBox(
  const double bounds[6], vtkMatrix4x4* matrix, double transformed[6])
{
  if (!vtkMath::AreBoundsInitialized(bounds))
  {
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    transformed[2 * i] = VTK_DOUBLE_MAX;
    transformed[2 * i + 1] = -VTK_DOUBLE_MAX;
  }
  for (int corner = 0; corner < 8; ++corner)
  {
    const double point[4] = { bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)],
      bounds[4 + ((corner >> 2) & 1)], 1.0 };
    double moved[4];
    matrix->MultiplyPoint(point, moved);
    for (int i = 0; i < 3; ++i)
    {
      const double v = moved[i] / (moved[3] != 0.0 ? moved[3] : 1.0);
      transformed[2 * i] = std::min(transformed[2 * i], v);
      transformed[2 * i + 1] = std::max(transformed[2 * i + 1], v);
    }
  }
  return std::all_of(transformed, transformed + 6, [](double v) { return std::isfinite(v); });
}
