/**
 * @file   vtkOpenMeshNormalsFanRules.h
 * @brief  what cuts a vertex's fan of faces, and how a fan's sum becomes its normal (private)
 *
 * vtkOpenMeshNormalsExecution cuts the fans of the topology it keeps;
 * vtkOpenMeshNormalsPointByPoint decides, one point at a time, whether a fan
 * would be cut at all. Both apply these rules, so that the two paths give the
 * same output bit for bit.
 *
 * Neither wrapped nor installed.
 */

#ifndef vtkOpenMeshNormalsFanRules_h
#define vtkOpenMeshNormalsFanRules_h

#include "vtkOpenMeshNormalsBuffers.h"

namespace vtkOpenMeshNormalsDetail
{
// Writes a unit normal, or +z where no normal is defined.
inline void StoreNormal(const Vector& sum, float* out)
{
  const double length = std::sqrt(Dot(sum, sum));
  if (length > 0.0 && std::isfinite(length))
  {
    out[0] = static_cast<float>(sum[0] / length);
    out[1] = static_cast<float>(sum[1] / length);
    out[2] = static_cast<float>(sum[2] / length);
  }
  else
  {
    out[0] = 0.f;
    out[1] = 0.f;
    out[2] = 1.f;
  }
}

// Whether the edge between two neighbouring faces of a fan is sharp (the same
// test as vtkPolyDataNormals: the unit normals' dot product at most
// cos(FeatureAngle)). Faces without a normal (zero area, not finite) never are.
inline bool IsSharpEdge(
  bool validF, const Vector& unitF, bool validG, const Vector& unitG, double cosFeatureAngle)
{
  return validF && validG && Dot(unitF, unitG) <= cosFeatureAngle;
}

// A fan that the feature angle leaves whole but whose faces' mean direction is farther than
// the feature angle from one of them: a singular vertex (a cone's apex), whose averaged
// normal would represent none of its faces. faceOf(i), for i in [0, count), gives the valid
// flag and unit normal of the fan's i-th face.
template <typename FaceOf>
bool IsSingularFan(Index count, const FaceOf& faceOf, double cosFeatureAngle)
{
  Vector mean = { 0.0, 0.0, 0.0 };
  for (Index i = 0; i < count; ++i)
  {
    const auto face = faceOf(i);
    if (face.first)
    {
      for (int c = 0; c < 3; ++c)
      {
        mean[c] += (*face.second)[c];
      }
    }
  }
  const double length = std::sqrt(Dot(mean, mean));
  if (!(length > 0.0))
  {
    return false;
  }
  for (Index i = 0; i < count; ++i)
  {
    const auto face = faceOf(i);
    if (face.first && Dot(mean, *face.second) <= cosFeatureAngle * length)
    {
      return true;
    }
  }
  return false;
}
}

#endif
