/**
 * @class   vtkPhongLightCulling
 * @brief   which positional lights an actor may skip: those that cannot change its colour by more
 * than a bound
 *
 * Called by vtkPhongShaderPlanner for each primitive it plans. For every point and spot
 * light it bounds, over the actor's bounds (in view coordinates, where the shader measures
 * distances), the light's whole contribution with the actor's actual materials:
 *
 *     B = A(d_min) * spot_max * I * max over channels of
 *         (ka*Ca*La + kd*Cd*Ld + ks*Cs*Ls*lobe normalization)
 *
 * where d_min is the distance from the light to the box (the attenuation (c, l, q) falls
 * with distance), spot_max the largest spot factor over the box's bounding sphere (0 when
 * the sphere lies outside the cone), Ca and Cd at least 1 (scalar and texture colours) and
 * N.L, the lobe and the gate at most 1. The lights with the smallest bounds are dropped while
 * the sum of the dropped bounds stays at most the culling bound, so the colour of every
 * pixel of the actor differs from the unculled render by at most the bound, however many
 * lights were dropped. docs/lighting-model.md ("Light culling") has the derivation.
 *
 * Dropping lights changes the plan's light counts, hence its signature: each culled set
 * is its own variant, compiled once and cached like any other.
 *
 * Private to the module.
 *
 * @sa vtkPhongShaderPlanner vtkPhongPolyDataMapper::SetLightCullingBound
 */

#ifndef vtkPhongLightCulling_h
#define vtkPhongLightCulling_h

#include <vector> // for std::vector

class vtkLight;
class vtkMatrix4x4;
class vtkProperty;
class vtkRenderer;

class vtkPhongLightCulling
{
public:
  /**
   * The colour of what lies within `boundsWC` (world coordinates) can change by at most
   * `bound` (per channel, linear, before any clamping) when the lights left out of `points`
   * and `spots` are dropped. `front` and `back` are the materials lighting uses (the same
   * when there is no back material). Returns how many lights were dropped, and in `spent` the
   * sum of their bounds (how much of `bound` the culling used); bound <= 0 (or NaN), or
   * uninitialized bounds, drop none.
   */
  static int Cull(vtkRenderer* ren, const double boundsWC[6], vtkProperty* front, vtkProperty* back,
    double bound, std::vector<vtkLight*>& points, std::vector<vtkLight*>& spots, double& spent);

  /**
   * The bound B above for one positional light (spot or not) over the given box in view
   * coordinates (xmin, xmax, ymin, ymax, zmin, zmax), with `material` the largest of the
   * materials' per-channel weights (see Cull). Public for tests.
   */
  static double ContributionBound(vtkLight* light, bool isSpot, const double lightPositionVC[3],
    const double spotAxisVC[3], const double boxVC[6], const double materialWeight[3][3]);

  /**
   * Per light colour (ambient, diffuse, specular) and channel: the largest ka*Ca, kd*Cd and
   * ks*Cs*normalization over both materials, colours that scalars or textures may replace
   * counting as at least 1. Also the error budget's weights (vtkPhongErrorBudget).
   */
  static void MaterialWeights(vtkProperty* front, vtkProperty* back, double weights[3][3]);

  /**
   * Whether a positional light fades with distance: its attenuation coefficients (c, l, q),
   * as the uniforms upload them (non-finite or negative ones as 0), are not (1, 0, 0). Where
   * they are, the shader attenuates it by exactly 1.
   */
  static bool IsAttenuated(vtkLight* light);

  /**
   * The box around the eight corners of `bounds` through `matrix` (homogeneous): world to
   * view for the culling, model to world for vtkPhongMapperCore::BoundsInWorld. False where
   * `bounds` are uninitialized or the result is not finite.
   */
  static bool TransformBox(const double bounds[6], vtkMatrix4x4* matrix, double transformed[6]);
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongLightCulling.h
