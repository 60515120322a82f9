/**
 * @class   vtkPhongShaderTemplate
 * @brief   writes a plan's lighting code from the GLSL templates of glsl/ into VTK's shaders
 *
 * The second of the shader path's three concerns (plan, template, uniforms), which
 * vtkPhongMapperCore calls. The files
 * of glsl/ are templates: sections (//PHONG_SECTION name) whose lines between
 * "//PHONG_IF FEATURE" (or "!FEATURE") and "//PHONG_ENDIF" are kept only when the plan has
 * (or lacks) the feature, and whose @DIRECTIONAL_COUNT@, @POINT_COUNT@, @SPOT_COUNT@ become
 * the plan's light counts. Resolve() keeps what a plan needs; Substitute() puts the resolved
 * sections at VTK's //VTK::Light::*, //VTK::UniformFlow::Impl and //VTK::TCoord::Impl tags.
 *
 * Malformed templates (an unknown feature, an unbalanced //PHONG_IF, an unknown placeholder,
 * a missing section) are reported through the error macro of the object given at
 * construction.
 *
 * Private to the module.
 *
 * @sa vtkPhongMapperCore vtkPhongShaderFeatures.h
 */

#ifndef vtkPhongShaderTemplate_h
#define vtkPhongShaderTemplate_h

#include "vtkPhongShaderPlan.h"      // for the plan
#include "vtkRenderingPhongModule.h" // for the export macro
#include "vtkShader.h"               // for vtkShader::Type

#include <map>    // for std::map
#include <string> // for std::string
#include <vector> // for std::vector

class vtkObject;

class vtkPhongShaderTemplate
{
public:
  using Plan = vtkPhongShaderPlan;

  explicit vtkPhongShaderTemplate(vtkObject* reporter);

  /**
   * The embedded template of a file of glsl/ by its name without extension; nullptr for
   * another name.
   */
  static const char* Get(const char* name);

  /**
   * The lines of the named section that the plan keeps, placeholders filled in.
   */
  std::string Resolve(const char* templateText, const char* section, const Plan& plan) const;

  /**
   * The GLSL statements of phongWholePower that raise x to the whole power n by squaring into
   * `power`: for each bit of n from the lowest, "power *= x; " where it is set and "x *= x; "
   * before the next. Exported for TestPhongErrorBudget, which checks their rounding.
   */
  VTKRENDERINGPHONG_EXPORT static std::string WholePowerSteps(int n);

  /**
   * Substitute a handled plan's lighting code into the vertex, geometry and fragment shaders.
   */
  void Substitute(std::map<vtkShader::Type, vtkShader*>& shaders, const Plan& plan) const;

  /**
   * Whether VTK's fragment code turns the normal towards the viewer by its depth (VTK 9.7's
   * lines: `if (normalVCVSOutput.z < 0) ...`) rather than by the side drawn: then one-sided
   * lighting keeps the normal VTK gives, since un-flipping by gl_FrontFacing would turn a
   * wide line's quads away at random.
   */
  static bool FlipsNormalByDepth(const std::string& fragmentSource);

  /**
   * A float as a GLSL literal that reads back as the same float (nine significant digits,
   * always with a decimal point or an exponent). Exported for TestPhongUniformConstants.
   */
  VTKRENDERINGPHONG_EXPORT static std::string FloatLiteral(float value);

private:
  // The state of Resolve() while it reads a template line by line.
  struct Reading
  {
    const char* Section = nullptr;
    std::string SectionLine; ///< the //PHONG_SECTION line that opens Section
    bool InSection = false;
    bool SectionFound = false;
    std::vector<bool> Active; ///< one entry per open //PHONG_IF
    int LineNumber = 0;
  };

  bool ReadDirective(const std::string& trimmed, const Plan& plan, Reading& reading) const;
  bool FeatureCondition(const std::string& condition, const Plan& plan, int lineNumber) const;
  void FillPlaceholders(std::string& line, const Plan& plan, int lineNumber) const;
  static void DeclareInvariantPosition(std::map<vtkShader::Type, vtkShader*>& shaders);
  static bool UsesUniformColors(const std::string& fragmentSource);
  void SubstituteFragment(vtkShader* fragmentShader, const std::string& sums,
    const std::string& lights, const Plan& plan) const;
  void SubstitutePerVertex(std::map<vtkShader::Type, vtkShader*>& shaders, const std::string& sums,
    const std::string& lights, const Plan& plan) const;
  static bool ShadesWithVertexNormal(std::map<vtkShader::Type, vtkShader*>& shaders);
  void SubstituteVertexDots(vtkShader* vertexShader, const Plan& plan) const;
  static void DeclareConstants(std::string& fragment, const Plan& plan);

  vtkObject* Reporter;
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongShaderTemplate.h
