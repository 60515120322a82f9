/**
 * @class   vtkPhongAttenuation
 * @brief   a positional light's distance attenuation as the shader evaluates it, and its
 *          bounds over a range of distances (private)
 *
 * A(d) = 1 / max(c + l d + q d^2, 1e-20), with the coefficients as the uniforms upload them.
 * Light culling bounds a light's contribution with its largest value over an actor's box; the
 * error budget's per-vertex bound (vtkPhongGouraudBound) also with how much it can change
 * between two points of one triangle (docs/lighting-model.md).
 */

#ifndef vtkPhongAttenuation_h
#define vtkPhongAttenuation_h

#include <array> // for std::array

class vtkLight;

class vtkPhongAttenuation
{
public:
  /**
   * `light`'s coefficients (c, l, q) as vtkPhongLightUniforms uploads them: non-finite or
   * negative ones as 0, none above vtkPhongProblemLog::LargestAttenuation (unreported: the
   * uniforms report what they substitute).
   */
  static vtkPhongAttenuation Of(vtkLight* light);

  /**
   * Whether the coefficients are VTK's default (1, 0, 0), where the shader attenuates by
   * exactly 1.
   */
  bool IsNone() const;

  /**
   * A(d), as the shader: also the largest value at distances >= d (it falls with d >= 0).
   */
  double At(double d) const;

  /**
   * The largest |dA/dd| at distances from `nearest` to `farthest` (0 <= nearest <= farthest):
   * (l + 2 q farthest) / den(nearest)^2, since the denominator grows with d. +inf where the
   * shader's floor on the denominator could act (den(nearest) <= 1e-15).
   */
  double SteepestOver(double nearest, double farthest) const;

  /**
   * The same attenuation of distances measured in units `scale` times longer: (c, l s, q s^2).
   */
  vtkPhongAttenuation Scaled(double scale) const;

  std::array<double, 3> Coefficients = { { 1.0, 0.0, 0.0 } }; ///< (c, l, q)

  bool operator==(const vtkPhongAttenuation& other) const
  {
    return this->Coefficients == other.Coefficients;
  }
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongAttenuation.h
