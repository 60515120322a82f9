/**
 * @class   vtkPhongLightUniforms
 * @brief   uploads a plan's light values: directional, positional, ambient and emission
 *
 * One of the two uniform halves of the shader path (plan, template, uniforms). Light
 * colours go up premultiplied by the light's intensity; directions and positions in view
 * coordinates, computed in double precision so far-away scenes lose nothing before the final
 * cast to float; the ambient light Ia plus the directional lights' ambient colours as one sum.
 * Non-finite or negative parameters are uploaded as 0 and reported once (vtkPhongProblemLog).
 * The single-light debug view zeroes every light but the one shown.
 *
 * Values() gives every value as it is uploaded (vtkPhongUniformValue): what vtkPhongMapperCore
 * compares from frame to frame and, under UNIFORM_CONSTANTS, what the template writes into the
 * fragment shader (vtkPhongShaderTemplate).
 *
 * Private to the module.
 *
 * @sa vtkPhongMapperCore vtkPhongMaterialUniforms
 */

#ifndef vtkPhongLightUniforms_h
#define vtkPhongLightUniforms_h

#include "vtkPhongLightGeometry.h" // for vtkPhongLightGeometry
#include "vtkPhongShaderPlan.h"    // for the plan

#include <array>  // for std::array
#include <map>    // for std::map
#include <string> // for std::string
#include <vector> // for std::vector

class vtkLight;
class vtkPhongProblemLog;
class vtkProperty;
class vtkRenderer;
class vtkShaderProgram;

class vtkPhongLightUniforms
{
public:
  using Plan = vtkPhongShaderPlan;

  /// `program` may be null when only Values() is called.
  vtkPhongLightUniforms(
    vtkShaderProgram* program, vtkRenderer* ren, const Plan& plan, vtkPhongProblemLog& log);

  /// Upload every light value of the plan to the program.
  void Upload();

  /// Every light value of the plan: the per-light arrays (directional, point and spot lights),
  /// the ambient light and the emission, in upload order.
  vtkPhongUniformValues Values();

private:
  using RGB = std::array<float, 3>;

  // Colours times intensity, as uploaded.
  struct LightValues
  {
    RGB Ambient = { 0.f, 0.f, 0.f };
    RGB Diffuse = { 0.f, 0.f, 0.f };
    RGB Specular = { 0.f, 0.f, 0.f };
  };

  // The uniform arrays of one positional light kind, a light after another.
  struct PositionalArrays
  {
    std::vector<float> PositionVC, Attenuation, Ambient, Diffuse, Specular;
    std::vector<float> AxisVC, CosCutoff, Exponent, CosInner; ///< spots only
  };

  LightValues ValuesOf(vtkLight* light);
  RGB ScaledColor(vtkLight* light, const double* color, double intensity, const char* which);
  int IndexOf(vtkLight* light) const;
  void ReadSceneAmbient();
  void AddDirectional(vtkPhongUniformValues& out);
  void AddColors(const std::string& prefix, const std::vector<float>& diffuse,
    const std::vector<float>& specular, vtkPhongUniformValues& out) const;
  void AddAmbient(vtkPhongUniformValues& out) const;
  RGB AttenuationOf(vtkLight* light);
  void AddSpot(vtkLight* light, const vtkPhongLightGeometry& geometry, PositionalArrays& arrays);
  void AddPositional(const std::vector<vtkLight*>& lights, const char* prefix, bool isSpot,
    vtkPhongUniformValues& out);
  void AddSpotArrays(
    const std::string& prefix, PositionalArrays& arrays, vtkPhongUniformValues& out) const;
  void AddEmission(vtkPhongUniformValues& out);

  vtkShaderProgram* Program;
  vtkRenderer* Renderer;
  const Plan& ThePlan;
  vtkPhongProblemLog& Log;
  std::map<vtkLight*, int> LightIndex; ///< as the renderer lists its lights, for messages
  double AmbientLight[3] = { 0.0, 0.0, 0.0 };
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongLightUniforms.h
