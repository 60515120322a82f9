/**
 * @file    vtkPhongShadowMaps.h
 * @brief   vtkPhong's lights under VTK's vtkShadowMapPass
 *
 * vtkShadowMapPass puts, before //VTK::Light::Impl, one `vec2 factor<i> = ...;` per light of
 * the renderer (i: the light's place in vtkRenderer::GetLights(), switched on or not; 1 where
 * the light casts no shadow), and then multiplies VTK's own per-light lines
 * (`diffuse += (df * lightColor<i>);`) by them. vtkPhong sums its lights in loops over
 * uniform arrays, one per kind, so it reads the factors itself: the fragment shader copies
 * them into `phongShadowFactors[]` and each light's diffuse and specular contributions are
 * multiplied by the factor of its renderer index, uploaded as `phong<Kind>LightShadow[]`
 * (the SHADOW_MAPS sections of glsl/vtkPhongLightingLib.glsl). Private to the module.
 */

#ifndef vtkPhongShadowMaps_h
#define vtkPhongShadowMaps_h

#include "vtkPhongShaderPlan.h" // for the plan

#include <string> // for std::string

class vtkRenderer;
class vtkShaderProgram;

namespace vtkPhongShadowMaps
{
/**
 * How many shadow factors vtkShadowMapPass declared in the fragment source (0: no pass).
 */
int CountFactors(const std::string& fragmentSource);

/**
 * The lines that copy the pass's factors into phongShadowFactors[], for the top of the
 * lighting code.
 */
std::string CopyFactors(int count);

/**
 * Upload each light's index into phongShadowFactors[] (its place among the renderer's lights),
 * where the program has the shadow-map arrays.
 */
void UploadLightIndices(
  vtkShaderProgram* program, vtkRenderer* ren, const vtkPhongShaderPlan& plan);
}

#endif
// VTK-HeaderTest-Exclude: vtkPhongShadowMaps.h
