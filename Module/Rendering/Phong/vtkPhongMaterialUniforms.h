/**
 * @class   vtkPhongMaterialUniforms
 * @brief   uploads a plan's material values: the contract's, where VTK's differ
 *
 * One of the two uniform halves of the shader path (plan, template, uniforms). VTK's
 * mapper has already uploaded the material of each side (SetPropertyShaderParameters); this
 * replaces what the lighting contract defines otherwise: the shininess unclamped (VTK clamps
 * SpecularPower to 128), the specular colour times the lobe's energy normalization, non-finite
 * colours and coefficients as 0 (reported once), the front material on both faces with
 * one-sided lighting, and the ready-made products k*C of the MATERIAL_UNIFORMS variant.
 * Values() gives them as they are uploaded (vtkPhongUniformValue), for UNIFORM_CONSTANTS.
 *
 * Private to the module.
 *
 * @sa vtkPhongMapperCore vtkPhongLightUniforms
 */

#ifndef vtkPhongMaterialUniforms_h
#define vtkPhongMaterialUniforms_h

#include "vtkPhongShaderPlan.h" // for the plan

#include <array> // for std::array

class vtkPhongProblemLog;
class vtkProperty;
class vtkShaderProgram;

class vtkPhongMaterialUniforms
{
public:
  using Plan = vtkPhongShaderPlan;

  /// `program` may be null when only Values() is called.
  vtkPhongMaterialUniforms(vtkShaderProgram* program, const Plan& plan, vtkPhongProblemLog& log);

  /// Upload the material values and the BudgetUse view's colour.
  void Upload();

  /// Every material value of the plan, front side first (the BudgetUse colour aside: it is the
  /// plan's, not the material's).
  vtkPhongUniformValues Values();

private:
  using RGB = std::array<float, 3>;

  void AddSide(vtkProperty* material, const char* suffix, bool report, vtkPhongUniformValues& out);
  RGB CheckedColor(const double* color, double scale, const char* which);
  static RGB BudgetUseColor(const Plan& plan);
  float CheckedCoefficient(double value, const char* which);
  void AddProducts(vtkPhongUniformValues& out) const;

  vtkShaderProgram* Program;
  const Plan& ThePlan;
  vtkPhongProblemLog& Log;
  // The side being uploaded: its uniform name suffix, its name in messages, and whether its
  // problems are reported (the back side is the front material with one-sided lighting).
  std::string Side;
  const char* SideName = "front";
  bool Report = true;
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongMaterialUniforms.h
