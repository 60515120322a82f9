/**
 * @class   vtkPhongProperty
 * @brief   the material terms of the exact Phong / Blinn-Phong model that vtkProperty lacks
 *
 * vtkPhongProperty is a vtkOpenGLProperty: an actor takes it wherever it takes a vtkProperty,
 * and every vtkProperty setting (colours, Ambient/Diffuse/Specular coefficients, Interpolation,
 * Opacity, Lighting, ...) keeps its meaning. vtkPhongPolyDataMapper reads the additions below;
 * an actor with a plain vtkProperty gets their defaults, which reproduce stock VTK.
 *
 * - LightingModel: the specular lobe, Phong (R.V), Blinn-Phong (N.H) or their
 *   energy-normalized forms, which scale the lobe by (n+2)/2 and (n+8)/8.
 * - Shininess: the exponent n over [0, 1e6]. vtkProperty::SpecularPower is clamped to
 *   [0, 128]; the two are kept in step (see SetShininess).
 * - Emission: a colour added to the lit result, independent of lights (not
 *   vtkProperty::EmissiveFactor, which only scales PBR emissive textures).
 * - SmoothTerminator: gate the highlight with max(N.L, 0) instead of a step at N.L = 0.
 * - SoftSpotEdge / SpotEdgeWidth: fade spot lights across a band inside the cone edge.
 * - PerVertexGouraud: evaluate the lighting equation at the vertices and interpolate the
 *   result (classic Gouraud). Stock VTK shades "Gouraud" per fragment; this property keeps
 *   that behaviour unless PerVertexGouraud is on.
 *
 * The lighting equation is documented in docs/lighting-model.md.
 *
 * @sa vtkPhongPolyDataMapper vtkProperty
 */

#ifndef vtkPhongProperty_h
#define vtkPhongProperty_h

#include "vtkOpenGLProperty.h"
#include "vtkRenderingPhongModule.h" // for export macro

class VTKRENDERINGPHONG_EXPORT vtkPhongProperty : public vtkOpenGLProperty
{
public:
  static vtkPhongProperty* New();
  vtkTypeMacro(vtkPhongProperty, vtkOpenGLProperty);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The specular lobes. The normalized forms multiply the lobe by (n+2)/2 (Phong) or
   * (n+8)/8 (Blinn-Phong) so a highlight keeps its energy as it sharpens.
   */
  enum LightingModels
  {
    Phong = 0,
    BlinnPhong = 1,
    NormalizedPhong = 2,
    NormalizedBlinnPhong = 3
  };

  ///@{
  /**
   * The specular lobe. Default Phong, the lobe stock VTK uses with more than one light;
   * one of Phong, BlinnPhong, NormalizedPhong, NormalizedBlinnPhong (values are clamped).
   * Changing the lobe changes the generated shader.
   */
  vtkSetClampMacro(LightingModel, int, Phong, NormalizedBlinnPhong);
  vtkGetMacro(LightingModel, int);
  void SetLightingModelToPhong() { this->SetLightingModel(Phong); }
  void SetLightingModelToBlinnPhong() { this->SetLightingModel(BlinnPhong); }
  void SetLightingModelToNormalizedPhong() { this->SetLightingModel(NormalizedPhong); }
  void SetLightingModelToNormalizedBlinnPhong() { this->SetLightingModel(NormalizedBlinnPhong); }
  const char* GetLightingModelAsString();
  ///@}

  ///@{
  /**
   * The shininess n of the specular lobe. Default 1 (vtkProperty's SpecularPower default),
   * range [0, 1e6]: a negative value is clamped to 0 with a warning, a NaN is refused with
   * an error. n = 0 makes the lobe 1 wherever the highlight gate is open (pow(0,0) = 1).
   * SetShininess also sets vtkProperty::SpecularPower to min(n, 128) for code that reads
   * SpecularPower, and SetSpecularPower sets Shininess, so the last call wins.
   */
  virtual void SetShininess(double shininess);
  vtkGetMacro(Shininess, double);
  double GetShininessMinValue() { return 0.0; }
  double GetShininessMaxValue() { return 1.0e6; }
  void SetSpecularPower(double specularPower) override;
  ///@}

  ///@{
  /**
   * The emission E, linear RGB, added to the lit colour and untouched by textures.
   * Default (0, 0, 0). Components must be finite and non-negative: a negative component is
   * clamped to 0 with a warning, a NaN or infinite one is refused with an error.
   */
  virtual void SetEmission(double red, double green, double blue);
  virtual void SetEmission(const double rgb[3]);
  vtkGetVector3Macro(Emission, double);
  ///@}

  ///@{
  /**
   * Smooth terminator: gate the highlight with max(N.L, 0) rather than with a step that
   * opens at N.L = 0, so a highlight fades out at the shadow line instead of being cut.
   * Default off (the contract's step gate). Changing it changes the generated shader.
   */
  vtkSetMacro(SmoothTerminator, bool);
  vtkGetMacro(SmoothTerminator, bool);
  vtkBooleanMacro(SmoothTerminator, bool);
  ///@}

  ///@{
  /**
   * Soft spot edge: instead of cutting a spot light off at its cone angle, fade it out with
   * a smoothstep across the last SpotEdgeWidth degrees inside the cone. Default off (hard
   * edge, as stock VTK). Changing SoftSpotEdge changes the generated shader; changing
   * SpotEdgeWidth does not.
   */
  vtkSetMacro(SoftSpotEdge, bool);
  vtkGetMacro(SoftSpotEdge, bool);
  vtkBooleanMacro(SoftSpotEdge, bool);
  ///@}

  ///@{
  /**
   * Width in degrees of the soft spot edge band. Default 5, range [0, 90]; NaN is refused
   * with an error.
   */
  virtual void SetSpotEdgeWidth(double width);
  vtkGetMacro(SpotEdgeWidth, double);
  ///@}

  ///@{
  /**
   * Per-vertex Gouraud: with Interpolation set to Gouraud, evaluate the lighting equation at
   * each vertex and interpolate the resulting light across the primitive. Default off, so a
   * Gouraud property shades per fragment exactly as stock VTK does. Needs point normals;
   * primitives without them (and points drawn as spheres, lines as tubes) stay per fragment.
   * SetInterpolationToPerVertexGouraud() sets both Interpolation and this flag.
   */
  vtkSetMacro(PerVertexGouraud, bool);
  vtkGetMacro(PerVertexGouraud, bool);
  vtkBooleanMacro(PerVertexGouraud, bool);
  void SetInterpolationToPerVertexGouraud();
  ///@}

  /**
   * Copy every vtkProperty setting of p and, when p is a vtkPhongProperty, its own as well.
   */
  void DeepCopy(vtkProperty* p);

protected:
  vtkPhongProperty();
  ~vtkPhongProperty() override;

  int LightingModel = Phong;
  double Shininess = 1.0;
  double Emission[3] = { 0.0, 0.0, 0.0 };
  bool SmoothTerminator = false;
  bool SoftSpotEdge = false;
  double SpotEdgeWidth = 5.0;
  bool PerVertexGouraud = false;

private:
  vtkPhongProperty(const vtkPhongProperty&) = delete;
  void operator=(const vtkPhongProperty&) = delete;
};

#endif
