/**
 * @class   vtkPhongMaterial
 * @brief   the material maths every part of the shader path shares (private)
 *
 * What a material means for the lighting, in one place: its lobe and shininess (from a
 * vtkPhongProperty, else VTK's Phong lobe and specular power), the lobe's energy
 * normalization and the sanitized coefficient-colour products the uniforms upload. The
 * planner, light culling and both uniform halves read it.
 */

#ifndef vtkPhongMaterial_h
#define vtkPhongMaterial_h

class vtkProperty;

class vtkPhongMaterial
{
public:
  /**
   * vtkPhongProperty's shininess (unclamped), else VTK's specular power.
   */
  static double ShininessOf(vtkProperty* material);

  /**
   * vtkPhongProperty's lighting model, else vtkPhongProperty::Phong (VTK's lobe).
   */
  static int LightingModelOf(vtkProperty* material);

  /**
   * The energy normalization of the lobe, folded into the specular colour on the CPU.
   */
  static double LobeNormalization(int lightingModel, double shininess);

  /**
   * product = coefficient * color * scale per channel, non-finite coefficients and colour
   * components taken as 0.
   */
  static void FiniteProduct(
    double coefficient, const double color[3], const double scale[3], float product[3]);
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongMaterial.h
