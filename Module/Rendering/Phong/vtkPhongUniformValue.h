/**
 * @class   vtkPhongUniformValue
 * @brief   one uniform's value as the lighting code uploads it, or declares it as a constant
 *
 * A vec3 or a float, or an array of them (a value per light). The uniform halves of the shader
 * path (vtkPhongLightUniforms, vtkPhongMaterialUniforms) give every value they upload as a
 * list of these: what Upload() sends to a program, what vtkPhongMapperCore compares from frame
 * to frame and, under UNIFORM_CONSTANTS, what vtkPhongShaderTemplate writes into the fragment
 * shader instead.
 *
 * Private to the module.
 */

#ifndef vtkPhongUniformValue_h
#define vtkPhongUniformValue_h

#include <string>  // for std::string
#include <utility> // for std::move
#include <vector>  // for std::vector

class vtkShaderProgram;

struct vtkPhongUniformValue
{
  /// What a value depends on, which decides whether it may be a constant (vtkPhongMapperCore).
  enum class Source
  {
    Light,        ///< the lights alone: programs with them as constants serve many actors
    Material,     ///< the actor's material (with or without the lights): the lighting's own
    StockMaterial ///< the actor's material, in VTK's own uniforms (ambientColorUniform, ...)
  };

  std::string Name;     ///< the GLSL name, e.g. phongDirectionalLightToLightVC
  int Components = 3;   ///< 3: vec3 elements, 1: float elements
  bool IsArray = false; ///< an array of Values.size() / Components elements; else one element
  std::vector<float> Values;
  Source From = Source::Light;

  ///@{
  /// A single vec3 or float, or an array of them (three floats an element for vec3; arrays
  /// are the lights').
  template <typename RGB> // float[3], double[3], std::array<float, 3>, ...
  static vtkPhongUniformValue Vec3(
    const std::string& name, const RGB& rgb, Source from = Source::Light)
  {
    return { name, 3, false,
      { static_cast<float>(rgb[0]), static_cast<float>(rgb[1]), static_cast<float>(rgb[2]) },
      from };
  }
  static vtkPhongUniformValue Float(
    const std::string& name, float value, Source from = Source::Light)
  {
    return { name, 1, false, { value }, from };
  }
  static vtkPhongUniformValue Vec3Array(const std::string& name, std::vector<float> values)
  {
    return { name, 3, true, std::move(values), Source::Light };
  }
  static vtkPhongUniformValue FloatArray(const std::string& name, std::vector<float> values)
  {
    return { name, 1, true, std::move(values), Source::Light };
  }
  ///@}

  /// The GLSL type of an element: "vec3" or "float".
  const char* ElementType() const { return this->Components == 3 ? "vec3" : "float"; }

  /// The number of elements (1 for a single value).
  std::size_t Count() const { return this->Values.size() / this->Components; }

  /**
   * Upload each value to the program (a value declared as a constant instead is not a uniform
   * of the program, and is skipped).
   */
  static void Upload(vtkShaderProgram* program, const std::vector<vtkPhongUniformValue>& values);

  bool operator==(const vtkPhongUniformValue& other) const
  {
    return this->Name == other.Name && this->Components == other.Components &&
      this->IsArray == other.IsArray && this->Values == other.Values && this->From == other.From;
  }
  bool operator!=(const vtkPhongUniformValue& other) const { return !(*this == other); }
};

using vtkPhongUniformValues = std::vector<vtkPhongUniformValue>;

#endif
// VTK-HeaderTest-Exclude: vtkPhongUniformValue.h
