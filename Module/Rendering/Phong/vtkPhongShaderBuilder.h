/**
 * @class   vtkPhongShaderBuilder
 * @brief   plans, writes and feeds the lighting shaders of the vtkPhong mappers
 *
 * vtkPhongShaderBuilder holds the one implementation of the lighting model of
 * docs/lighting-model.md on the GPU. A mapper (vtkPhongPolyDataMapper, or a composite helper,
 * through vtkPhongMapperCore) calls it at three points of VTK's shader life cycle, one concern
 * each, as VTK's mapper splits ReplaceShaderColor/Normal/Light:
 *
 * 1. MakePlan() (vtkPhongShaderPlanner): for the primitive about to be drawn, decide which
 *    code the shader needs (the light kinds and counts present, the terms with non-zero
 *    coefficients, the lobe, the interpolation, the debug view) as typed features
 *    (vtkPhongShaderFeatures.h), and summarise them in a signature. Equal signatures mean
 *    identical lighting code, so the mapper rebuilds its shader only when the signature
 *    changes; values (colours, intensities, positions) are uniforms and never recompile.
 * 2. ReplaceShaderValues() (vtkPhongShaderTemplate): substitute VTK's //VTK::Light::* tags
 *    (and UniformFlow, TCoord in the fragment shader) with the GLSL templates of glsl/,
 *    keeping only the sections the plan needs.
 * 3. SetLightUniforms() (vtkPhongLightUniforms) / SetMaterialUniforms()
 *    (vtkPhongMaterialUniforms): upload the light and material values.
 *
 * Bad parameters met on the way are substituted as documented and collected once each
 * (vtkPhongProblemLog) for the mapper to report. Primitives the model does not cover (PBR,
 * the vertex-visibility pass, VTK's lighting map passes) get Plan::Handled = false and keep
 * VTK's own shader code.
 *
 * Not wrapped: the mapper is the Python-facing API.
 *
 * @sa vtkPhongPolyDataMapper vtkPhongProperty
 */

#ifndef vtkPhongShaderBuilder_h
#define vtkPhongShaderBuilder_h

#include "vtkLight.h" // for vtkNew<vtkLight>
#include "vtkNew.h"   // for vtkNew
#include "vtkObject.h"
#include "vtkPhongShaderFeatures.h"  // for vtkPhongFeatureSet
#include "vtkRenderingPhongModule.h" // for export macro
#include "vtkShader.h"               // for vtkShader::Type

#include <map>    // for std::map
#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

class vtkActor;
class vtkPhongProblemLog;
class vtkProperty;
class vtkRenderer;
class vtkShaderProgram;

class VTKRENDERINGPHONG_EXPORT vtkPhongShaderBuilder : public vtkObject
{
public:
  static vtkPhongShaderBuilder* New();
  vtkTypeMacro(vtkPhongShaderBuilder, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * What the calling mapper knows about the primitive it is about to draw and the builder
   * cannot see: VTK keeps these in the mapper's protected state.
   */
  struct PrimitiveState
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
  };

  /**
   * The mapper's own settings that shape the shader.
   */
  struct Options
  {
    int DebugView = 0; ///< a vtkPhongPolyDataMapper::DebugViews value
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
    /// the depth pre-pass: VTK's fragment shader with no lighting code at all, so that the
    /// pass costs what an unlit draw does (vtkPhongDepthPrePass.h)
    bool DepthOnly = false;
  };

  /**
   * Everything MakePlan() decided for one primitive.
   */
  struct Plan
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
    int DebugView = 0;                   ///< a vtkPhongPolyDataMapper::DebugViews value
    int ShadowFactorCount = 0;           ///< vtkShadowMapPass's factors (one per light)
    int CulledLights = 0;                ///< positional lights left out (vtkPhongLightCulling)
    bool Has(vtkPhongFeature feature) const { return this->Features.Has(feature); }
  };

  /**
   * Decide how the primitive is lit. Cheap (a pass over the lights); called every frame.
   */
  Plan MakePlan(
    vtkRenderer* ren, vtkActor* actor, const PrimitiveState& state, const Options& options);

  /**
   * Substitute the lighting code of a handled plan into the shader sources.
   */
  void ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders, const Plan& plan);

  /**
   * Upload the light uniforms (and emission, ambient light) of a handled plan.
   */
  void SetLightUniforms(vtkShaderProgram* program, vtkRenderer* ren, const Plan& plan);

  /**
   * Upload the material uniforms that differ from VTK's (unclamped shininess, normalized
   * lobes, sanitized colours, one-sided back material). Call after the stock mapper's
   * SetPropertyShaderParameters.
   */
  void SetMaterialUniforms(vtkShaderProgram* program, const Plan& plan);

  /**
   * Problems found in the scene's parameters (NaN colours, negative intensities, ...) while
   * planning and uploading, one line each, since the last call to TakeProblems(). The mapper
   * reports them through its own error macro.
   */
  std::string TakeProblems();

  /**
   * Keep, from a GLSL template, the lines of the named section whose //PHONG_IF conditions
   * hold for the plan, with @NAME@ placeholders filled in (vtkPhongShaderTemplate). Public
   * for tests.
   */
  std::string ResolveTemplate(const char* templateText, const char* section, const Plan& plan);

  /**
   * The embedded GLSL template of a file of Module/Rendering/Phong/glsl by its name without
   * extension (vtkPhongLightingLib, vtkPhongFS, vtkPhongVS, vtkPhongGS); nullptr for another name.
   */
  static const char* GetTemplate(const char* name);

protected:
  vtkPhongShaderBuilder();
  ~vtkPhongShaderBuilder() override;

  std::unique_ptr<vtkPhongProblemLog> Log;

  // Lights that contribute nothing (intensity 0), standing in for the light kinds a scene
  // lacks in the all-features variant, whose code needs at least one light of each kind.
  vtkNew<vtkLight> PlaceholderDirectional;
  vtkNew<vtkLight> PlaceholderPoint;
  vtkNew<vtkLight> PlaceholderSpot;

private:
  vtkPhongShaderBuilder(const vtkPhongShaderBuilder&) = delete;
  void operator=(const vtkPhongShaderBuilder&) = delete;
};

#endif
