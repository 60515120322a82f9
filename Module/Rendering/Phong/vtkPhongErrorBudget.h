/**
 * @class   vtkPhongErrorBudget
 * @brief   how a primitive spends the user's error budget (private)
 *
 * Called by vtkPhongShaderPlanner under vtkPhongLightingSettings::ErrorBudget. The budget
 * is the largest difference per pixel and channel (linear colour) allowed between the
 * picture and the exact per-fragment model computed in double. It pays, in this order:
 * - light culling, at most half of the budget (and never more than LightCullingBound);
 * - per-vertex lighting of the surface (vtkPhongGouraudBound), with what is left less the
 *   float rounding of the lighting itself, while the surface's vertices are fewer than the
 *   fragments it covers (ChooseMode): every light sum per vertex where that bound fits,
 *   else (under two lobes or more, 20 or more where the lobes would be squared per fragment)
 *   the specular sums alone, the diffuse term staying exact per fragment (its clamp at the
 *   terminator is the costliest part of the per-vertex bound);
 * - a whole shininess raised by squaring instead of pow, in whichever mode, its rounding
 *   charged (WholePowerError).
 * The errors of the mechanisms add up by the triangle inequality, so the picture stays
 * within their sum. Hysteresis is on the safe side only: the planner moves to a cheaper mode
 * when its bound is at most 0.8 of what is left, stays while it fits, and goes back at once
 * when it does not.
 */

#ifndef vtkPhongErrorBudget_h
#define vtkPhongErrorBudget_h

#include "vtkPhongGouraudBound.h" // for vtkPhongGouraudBound::Scene
#include "vtkPhongShaderPlan.h"   // for vtkPhongShaderPlan

class vtkActor;
class vtkMatrix4x4;
class vtkRenderer;

class vtkPhongErrorBudget
{
public:
  using Mode = vtkPhongGouraudBound::Mode;

  /**
   * The cheapest mode of the plan's light sums within `available` (linear colour), given the
   * primitive's binned triangles and their bounds in world coordinates, `last`, the last
   * choice, and whether per fragment the lobes would be raised by squaring (`squared`,
   * WholePowerError); `bound` receives the chosen mode's bound (0 per fragment).
   */
  static Mode ChooseMode(vtkRenderer* ren, vtkActor* actor, const vtkPhongShaderPlan& plan,
    vtkPhongGouraudBound& triangles, const double boundsWC[6], double available, Mode last,
    bool squared, double& bound);

  /**
   * How far the picture may stray (linear colour) when the plan's lights raise their lobes to
   * the whole shininess `n` by squaring instead of pow: each of its products rounds once
   * (u = 2^-24), and each rounding is raised to the power of the factors it enters (a
   * squaring's, for x^(2^b), 2^b - 1 of them; each product into the power, one): n in all, a
   * relative error of gamma_n = n u / (1 - n u) on each lobe; and, the program not being the
   * exact one, the rounding both make their own way:
   * the cosine's (8 u, which the lobe multiplies by up to n) and the lighting's (0.01 level
   * and 2e-5 of the lights' largest contributions, FloatMargin's). The contributions count
   * the lights' intensity, colours and largest attenuation, the materials' weights and the
   * lobe's normalization. +inf where a light's values bound nothing (attenuation without a
   * constant term).
   */
  static double WholePowerError(const vtkPhongShaderPlan& plan, int n);

  /**
   * How far the picture may stray (linear colour) when the plan is drawn by another program
   * with the same arithmetic, up to what its compiler makes of it (the light and material values
   * as constants, UNIFORM_CONSTANTS: a pow with a constant exponent may become products): the
   * rounding both make their own way, WholePowerError's last term. +inf where a light's
   * values bound nothing.
   */
  static double ProgramRoundingError(const vtkPhongShaderPlan& plan);

private:
  static void LargestContributions(
    const vtkPhongShaderPlan& plan, double& specular, double& lights);
  // The rounding of float lighting against the double model, taken off what per-vertex
  // lighting may spend: 0.01 level plus 2e-5 of the lights' largest contributions.
  static double FloatMargin(const vtkPhongGouraudBound::Scene& scene);
  // The lights, the view and the material in the model coordinates of the normals; false
  // when the actor's matrix is not a similarity (angles would not hold) or a light is not
  // bounded (AddPointLights).
  static bool MakeScene(vtkRenderer* ren, vtkActor* actor, const vtkPhongShaderPlan& plan,
    vtkPhongGouraudBound::Scene& scene);
  // The plan's point lights into `scene` (their positions in model coordinates, by
  // `viewToModel`, whose inverse's scale is `viewPerModel`; `weights` the materials' of
  // vtkPhongLightCulling::MaterialWeights); false for one attenuated without a constant term.
  static bool AddPointLights(vtkRenderer* ren, const vtkPhongShaderPlan& plan,
    vtkMatrix4x4* viewToModel, double viewPerModel, const double weights[3][3],
    vtkPhongGouraudBound::Scene& scene);
  // Whether the specular sums alone per vertex save more than they cost: two lobes or more,
  // 20 or more where per fragment the lobes would be squared.
  static bool SpecularPerVertexPays(const vtkPhongGouraudBound::Scene& scene, bool squared);
  // Whether per-vertex lighting costs less: vertices x sides against the covered fragments.
  static bool PerVertexIsCheaper(vtkRenderer* ren, const double boundsWC[6],
    const vtkPhongGouraudBound& triangles, bool twoSided);
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongErrorBudget.h
