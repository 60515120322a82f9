/**
 * @file    vtkPhongShaderFeatures.h
 * @brief   the typed feature flags of a lighting shader variant
 *
 * vtkPhongFeature names each optional piece of the lighting code (a term, a light kind, an
 * interpolation, a debug view); vtkPhongFeatureSet is the set a plan holds. The GLSL templates
 * of glsl/ name the same features in their //PHONG_IF lines, in upper case with underscores
 * (LightSums is LIGHT_SUMS): GetName() and FindByName() translate, so a misspelt feature is a
 * compile error in C++ and an error message in a template (TestPhongShaderSpecialization
 * resolves every template section and fails on it).
 *
 * The features are listed in the order of their template names, so the names of a set come
 * out sorted, as they appear in the shader signature.
 *
 * Not wrapped: an implementation detail of the mappers.
 *
 * @sa vtkPhongShaderPlan.h vtkPhongShaderPlanner
 */

#ifndef vtkPhongShaderFeatures_h
#define vtkPhongShaderFeatures_h

#include "vtkRenderingPhongModule.h" // for export macro

#include <bitset> // for std::bitset
#include <string> // for std::string

enum class vtkPhongFeature : unsigned char
{
  Ambient,
  Attenuation,
  BackMaterial,
  DebugBudget, ///< the BudgetUse view: one colour per primitive, its mode and budget share
  DebugNormal,
  DebugNormalVC,
  DebugPositionVC,
  Diffuse,
  DiffuseOrSpecular,
  DiffusePerFragment, ///< with the sums per vertex, the directional diffuse sum per fragment
  Directional,
  Emission,
  GeometryPassThrough,
  InterpolatedDots, ///< directional lights' N.L and L.V from dot products interpolated from the
                    ///< vertices
  LightSums,
  LobeBlinn,
  LobePhong,
  MaterialUniforms,
  NarrowLobe, ///< the specular lobe from a difference vector, exact at shininess above 1e3
  NormalFallback,
  OneSided,
  Parallel,
  PerVertex,
  Point,
  PointAttenuation,
  Positional,
  PositionalAmbient,
  SeparateSpecularColors, ///< the specular sums read their own light colours, not the diffuse ones
  ShadingNormal,
  ShadowMaps, ///< vtkShadowMapPass's factors multiply each light (set from the shader source)
  SmoothTerminator,
  SoftSpotEdge,
  Specular,
  SpecularAntiAliasing, ///< the specular lobe widened by the normal's variation over the pixel
  Spot,
  SpotAttenuation,
  SpotFalloff,
  SumsPerFragment,
  SumsPerVertex,
  TwoSided,
  UniformConstants, ///< light and material values written into the fragment shader as constants
  ViewVector,
  WholeShininess, ///< under an error budget, the lobe's whole shininess raised by squaring
  Count           ///< not a feature: the number of features
};

class VTKRENDERINGPHONG_EXPORT vtkPhongFeatureSet
{
public:
  void Set(vtkPhongFeature feature, bool on = true)
  {
    this->Bits.set(static_cast<std::size_t>(feature), on);
  }
  bool Has(vtkPhongFeature feature) const
  {
    return this->Bits.test(static_cast<std::size_t>(feature));
  }
  bool operator==(const vtkPhongFeatureSet& other) const { return this->Bits == other.Bits; }

  /**
   * The names of the features in the set, each followed by a space, in name order.
   */
  std::string GetNames() const;

  /**
   * The template name of a feature (LIGHT_SUMS for LightSums).
   */
  static const char* GetName(vtkPhongFeature feature);

  /**
   * The feature a template name stands for; false when no feature has that name.
   */
  static bool FindByName(const std::string& name, vtkPhongFeature& feature);

private:
  std::bitset<static_cast<std::size_t>(vtkPhongFeature::Count)> Bits;
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongShaderFeatures.h
