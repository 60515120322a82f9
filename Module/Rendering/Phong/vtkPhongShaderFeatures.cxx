#include "vtkPhongShaderFeatures.h"

#include <array>

namespace
{
// In the order of vtkPhongFeature.
constexpr std::array<const char*, static_cast<std::size_t>(vtkPhongFeature::Count)> FeatureNames = {
  "AMBIENT", "ATTENUATION", "BACK_MATERIAL", "DEBUG_BUDGET", "DEBUG_NORMAL", "DEBUG_NORMAL_VC",
  "DEBUG_POSITION_VC", "DIFFUSE", "DIFFUSE_OR_SPECULAR", "DIFFUSE_PER_FRAGMENT", "DIRECTIONAL",
  "EMISSION", "GEOMETRY_PASS_THROUGH", "INTERPOLATED_DOTS", "LIGHT_SUMS", "LOBE_BLINN",
  "LOBE_PHONG", "MATERIAL_UNIFORMS", "NARROW_LOBE", "NORMAL_FALLBACK", "ONE_SIDED", "PARALLEL",
  "PER_VERTEX", "POINT", "POINT_ATTENUATION", "POSITIONAL", "POSITIONAL_AMBIENT",
  "SEPARATE_SPECULAR_COLORS", "SHADING_NORMAL", "SHADOW_MAPS", "SMOOTH_TERMINATOR",
  "SOFT_SPOT_EDGE", "SPECULAR", "SPECULAR_ANTI_ALIASING", "SPOT", "SPOT_ATTENUATION",
  "SPOT_FALLOFF", "SUMS_PER_FRAGMENT", "SUMS_PER_VERTEX", "TWO_SIDED", "UNIFORM_CONSTANTS",
  "VIEW_VECTOR", "WHOLE_SHININESS"
};
static_assert(FeatureNames.back() != nullptr, "every vtkPhongFeature has a name");
}

//------------------------------------------------------------------------------
const char* vtkPhongFeatureSet::GetName(vtkPhongFeature feature)
{
  return FeatureNames[static_cast<std::size_t>(feature)];
}

//------------------------------------------------------------------------------
bool vtkPhongFeatureSet::FindByName(const std::string& name, vtkPhongFeature& feature)
{
  for (std::size_t index = 0; index < FeatureNames.size(); ++index)
  {
    if (name == FeatureNames[index])
    {
      feature = static_cast<vtkPhongFeature>(index);
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
std::string vtkPhongFeatureSet::GetNames() const
{
  std::string names;
  for (std::size_t index = 0; index < FeatureNames.size(); ++index)
  {
    if (this->Bits.test(index))
    {
      names += FeatureNames[index];
      names += ' ';
    }
  }
  return names;
}
