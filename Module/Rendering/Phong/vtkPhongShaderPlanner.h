/**
 * @class   vtkPhongShaderPlanner
 * @brief   decides which lighting code a primitive needs: the plan and its signature
 *
 * The first of the shader path's three concerns (plan, template, uniforms), which
 * vtkPhongMapperCore calls. MakePlan()
 * reads the renderer's lights, the actor's materials and what the mapper knows about the
 * primitive, and sets the features (vtkPhongShaderFeatures.h) of the shader it needs, in
 * named steps: whether vtkPhong handles the primitive at all, the lights by kind, the terms
 * with non-zero coefficients, the light features, the material features, the interpolation,
 * the normal. The signature summarises the plan: equal signatures mean identical lighting
 * code.
 *
 * Private to the module.
 *
 * @sa vtkPhongMapperCore
 */

#ifndef vtkPhongShaderPlanner_h
#define vtkPhongShaderPlanner_h

#include "vtkPhongGouraudBound.h" // for vtkPhongGouraudBound::Mode
#include "vtkPhongShaderPlan.h"   // for the plan

#include <cstddef> // for std::size_t
#include <string>  // for std::string
#include <vector>  // for std::vector

class vtkActor;
class vtkLight;
class vtkPhongProblemLog;
class vtkRenderer;

class vtkPhongShaderPlanner
{
public:
  using Plan = vtkPhongShaderPlan;
  using PrimitiveState = vtkPhongPrimitiveState;
  using Options = vtkPhongPlanOptions;

  /**
   * Lights that contribute nothing, standing in for the light kinds a scene lacks in the
   * all-features variant, whose code needs at least one light of each kind.
   */
  struct PlaceholderLights
  {
    vtkLight* Directional = nullptr;
    vtkLight* Point = nullptr;
    vtkLight* Spot = nullptr;
  };

  vtkPhongShaderPlanner(const PlaceholderLights& placeholders, vtkPhongProblemLog& log);

  Plan MakePlan(
    vtkRenderer* ren, vtkActor* actor, const PrimitiveState& state, const Options& options);

  /**
   * How many directional lights the varyings of INTERPOLATED_DOTS (docs/shaders.md) can carry
   * in the current OpenGL context: two vec4 per four lights, within the fragment inputs the
   * context offers less 32 components kept for VTK's own (position, normal, texture
   * coordinates, colours), and at most 64 (the unrolled light loops). Call with the context
   * current.
   */
  static std::size_t MaximumInterpolatedDotLights();

  /**
   * Whether the plan's fragment shader may take its light and material values as constants
   * (UNIFORM_CONSTANTS, SetConstants): under an error budget, in the final or BudgetUse
   * view of the specialized shader, with 1 to 64 lights (the unrolled loops), and where their
   * charge fits. Where the vertices sum the lights, the fragment shader still reads the
   * material's values.
   */
  static bool MayTakeConstants(const Plan& plan, const Options& options);

  /**
   * Write `values` (vtkPhongLightUniforms::Values and vtkPhongMaterialUniforms::Values of this
   * plan) into the plan as its fragment shader's constants: the feature, the values and their
   * exact bits in the signature, so that other values make another program. The same floats, but
   * the compiler may specialize code on them (a pow with a constant exponent as products): the plan
   * is charged the rounding another program makes its own way
   * (vtkPhongErrorBudget::ProgramRoundingError; already in WHOLE_SHININESS's charge). False,
   * leaving the plan as it is, where that does not fit the budget (MayTakeConstants checks it) or a
   * value is not finite.
   */
  static bool SetConstants(vtkPhongUniformValues values, const Options& options, Plan& plan);

private:
  // The terms of the equation the variant evaluates.
  struct Terms
  {
    bool Ambient = false;
    bool Diffuse = false;
    bool Specular = false;
    bool Emission = false;
    bool PositionalAmbient = false;
    bool LightSums = false; ///< any per-light sum: diffuse, specular or positional ambient
  };

  static double ConstantsCharge(const Plan& plan);
  static bool IsLeftToVTK(vtkActor* actor, const PrimitiveState& state);
  static void SortLightsByKind(const std::vector<vtkLight*>& lights, Plan& plan);
  void PickDebugLight(const std::vector<vtkLight*>& lights, const Options& options, Plan& plan);
  void AddPlaceholderLights(Plan& plan) const;
  static Terms ChooseTerms(const Plan& plan, bool haveLights, bool allFeatures);
  static void SetTermFeatures(const Terms& terms, Plan& plan);
  static void SetLightFeatures(const Terms& terms, bool allFeatures, Plan& plan);
  static bool HasSeparateSpecularColors(const Terms& terms, bool allFeatures, const Plan& plan);
  static void SetMaterialFeatures(const Terms& terms, bool allFeatures, Plan& plan);
  static bool DrawnUnderShadowMaps(vtkActor* actor);
  /// A whole shininess the lobe may raise by squaring (0: none) and that squaring's charge.
  struct Squaring
  {
    int Shininess = 0;
    double Error = 0.0;
    bool Fits(const Plan& plan, const Options& options) const;
  };
  static Squaring SquaringOf(const Terms& terms, const Options& options, const Plan& plan);
  static vtkPhongGouraudBound::Mode BudgetChoosesMode(vtkRenderer* ren, vtkActor* actor,
    const Terms& terms, const PrimitiveState& state, const Options& options,
    const Squaring& squaring, Plan& plan);
  static bool SetInterpolationFeatures(const Terms& terms, const PrimitiveState& state,
    bool geometryView, vtkPhongGouraudBound::Mode budgetMode, vtkRenderer* ren, Plan& plan);
  static void SetNormalFeatures(
    const Terms& terms, const PrimitiveState& state, bool perVertex, bool allFeatures, Plan& plan);
  static void SetInterpolatedDotsFeature(
    const PrimitiveState& state, bool allowed, std::size_t maximumLights, Plan& plan);
  static void SetWholeShininessFeature(
    const Squaring& squaring, const Options& options, Plan& plan);
  static std::string MakeSignature(const Plan& plan, bool allFeatures);

  PlaceholderLights Placeholders;
  vtkPhongProblemLog& Log;
  std::size_t InterpolatedDotLights = 0; ///< MaximumInterpolatedDotLights(), once known
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongShaderPlanner.h
