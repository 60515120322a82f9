/**
 * @file    vtkPhongShaderPlan.h
 * @brief   what the lighting shader of one primitive is made of (private)
 *
 * The bottom of the shader path: the mapper's view of a primitive (vtkPhongPrimitiveState)
 * and its settings (vtkPhongPlanOptions) go into vtkPhongShaderPlanner, whose
 * vtkPhongShaderPlan the template (vtkPhongShaderTemplate), the uniforms
 * (vtkPhongLightUniforms, vtkPhongMaterialUniforms, vtkPhongShadowMaps) and the mapper core
 * (vtkPhongMapperCore) read. Equal signatures mean identical lighting code.
 */

#ifndef vtkPhongShaderPlan_h
#define vtkPhongShaderPlan_h

#include "vtkPhongShaderFeatures.h" // for vtkPhongFeatureSet
#include "vtkPhongUniformValue.h"   // for vtkPhongUniformValues

#include <string> // for std::string
#include <vector> // for std::vector

class vtkLight;
class vtkPhongGouraudBound;
class vtkProperty;

/**
 * What the calling mapper knows about the primitive it is about to draw and the planner
 * cannot see: VTK keeps these in the mapper's protected state.
 */
struct vtkPhongPrimitiveState
{
  int LightComplexity = 0;          ///< the stock mapper's LastLightComplexity (0: unlit)
  bool IsTriangles = false;         ///< polygons or triangle strips
  bool HasPointNormals = false;     ///< a 3-component normalMC vertex buffer exists
  bool HasCellNormals = false;      ///< normals come from a cell normal texture
  bool NormalsMayBeInvalid = false; ///< the normals array holds zero, NaN or Inf vectors
  bool NormalsFromShape = false;    ///< points drawn as spheres or lines as tubes
  bool HasGeometryShader = false;
  bool HasUserShaderCode = false; ///< the actor's or mapper's shader code or replacements
  bool DrawingEdges = false;      ///< surface with edges: VTK's edge colour is ambientColor
  bool DrawingVertices = false;   ///< the vertex-visibility pass
  bool DrawingSelection = false;  ///< the selection-highlight pass
  /// VTK sets its material uniforms again for each block it draws (the composite mapper's
  /// blocks: colours and opacity per block), over those the lighting uploads
  bool MaterialPerBlock = false;
  /// the triangles binned for the error budget's per-vertex bound; null without a budget
  vtkPhongGouraudBound* Triangles = nullptr;
  /// What this primitive draws (its blocks) in world coordinates, through the matrix of the
  /// actor the mapper is given: not that actor's own bounds, which an actor drawing through an
  /// internal one (vtkFollower, vtkLODActor) hands over without a mapper, so without
  /// bounds. Uninitialized (min > max) when there is nothing to bound.
  double BoundsWC[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };

  /// Whether the shading normal is VTK's interpolated point normal: point normals, and no cell
  /// normals, impostors, geometry shader or shader code of the user's that may change it.
  bool ShadesWithPointNormals() const
  {
    return this->HasPointNormals && !this->HasCellNormals && !this->NormalsFromShape &&
      !this->HasGeometryShader && !this->HasUserShaderCode;
  }
};

/**
 * The mapper's own settings that shape the shader.
 */
struct vtkPhongPlanOptions
{
  int DebugView = 0; ///< a vtkPhongLightingSettings::DebugViews value
  int DebugLightIndex = 0;
  /// false: the all-features variant (every optional term and light kind) instead of the
  /// shader the scene needs, for measuring what specialization buys
  bool Specialize = true;
  /// directional lights' N.L and L.V from dot products interpolated from the vertices where
  /// possible (INTERPOLATED_DOTS); false computes them per fragment, for measuring the trade
  bool InterpolatedDots = true;
  /// positional lights may be left out of an actor while the colour they could add there
  /// stays within this bound (vtkPhongLightCulling); 0 keeps every light
  double LightCullingBound = 0.5 / 255.0;
  /// the error budget (linear colour; 0: the exact mode), vtkPhongErrorBudget
  double ErrorBudget = 0.0;
  /// the specular lobe filtered over the pixel (SPECULAR_ANTI_ALIASING), per fragment only
  bool SpecularAntiAliasing = false;
  /// the depth pre-pass: VTK's fragment shader with no lighting code at all, so that the
  /// pass costs what an unlit draw does (vtkPhongDepthPrePass.h)
  bool DepthOnly = false;
  /// surfaces VTK would light, with no switched-on light: the model's emission and ambient
  /// term instead of VTK's unlit colours (vtkPhongLightingSettings::LightingWithoutLights)
  bool LightingWithoutLights = false;
};

/**
 * Everything vtkPhongShaderPlanner::MakePlan() decided for one primitive.
 */
struct vtkPhongShaderPlan
{
  bool Handled = false;   ///< false: VTK's own lighting code is used
  bool DepthOnly = false; ///< the depth pre-pass's program: no lighting, not a variant
  vtkPhongFeatureSet Features;
  std::string Signature;
  std::vector<vtkLight*> DirectionalLights;
  std::vector<vtkLight*> PointLights;
  std::vector<vtkLight*> SpotLights;
  vtkLight* DebugLight = nullptr; ///< the light shown by the SingleLight view
  vtkProperty* FrontMaterial = nullptr;
  vtkProperty* BackMaterial = nullptr; ///< the front material when there is no back one
  int DebugView = 0;                   ///< a vtkPhongLightingSettings::DebugViews value
  int ShadowFactorCount = 0;           ///< vtkShadowMapPass's factors (one per light)
  int CulledLights = 0;                ///< positional lights left out (vtkPhongLightCulling)
  double ErrorBound = 0.0; ///< under an error budget, the most its approximations may stray
  /// where the error budget put the light sums: 0 per fragment, 1 the specular sums per
  /// vertex, 2 every sum per vertex (vtkPhongGouraudBound::Mode), and the share of the budget
  /// ErrorBound is (0 without a budget): what the BudgetUse view shows
  int BudgetMode = 0;
  double BudgetShare = 0.0;
  /// under WHOLE_SHININESS, the shininess n (2 to 1000) the lobe raises by squaring; else 0
  int WholeShininess = 0;
  /// under UNIFORM_CONSTANTS, the uniforms the fragment shader declares as constants instead
  /// (vtkPhongMapperCore: light and material values that stayed the same, under an error budget)
  vtkPhongUniformValues Constants;
  bool Has(vtkPhongFeature feature) const { return this->Features.Has(feature); }
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongShaderPlan.h
