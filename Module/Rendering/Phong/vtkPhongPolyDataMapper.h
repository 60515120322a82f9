/**
 * @class   vtkPhongPolyDataMapper
 * @brief   drop-in polydata mapper that renders the exact Phong / Blinn-Phong lighting model
 *
 * vtkPhongPolyDataMapper is a vtkOpenGLPolyDataMapper whose shaders evaluate the lighting
 * equation of docs/lighting-model.md instead of VTK's: emission, ambient, diffuse and specular
 * terms summed over any number of lights of every VTK kind (headlight, camera and scene
 * lights; directional, point and spot lights with (c, l, q) attenuation), with flat, per-vertex
 * Gouraud and per-fragment Phong interpolation. It reads the settings VTK users already make:
 *
 * - vtkProperty: Ambient/Diffuse/Specular coefficients and colours, SpecularPower,
 *   Interpolation, Lighting; the actor's BackfaceProperty for back faces.
 * - vtkLight: every light kind, Intensity, and the ambient, diffuse and specular colours
 *   (stock VTK uses only DiffuseColor), attenuation, cone angle and spot exponent.
 * - vtkRenderer: Ambient (ignored by stock VTK), TwoSidedLighting, the light collection.
 * - vtkPhongProperty (optional): the lobe (Phong, Blinn-Phong, normalized forms), shininess
 *   up to 1e6, emission, smooth terminator, soft spot edges and per-vertex Gouraud.
 *
 * With VTK's defaults and the Phong lobe the picture matches the stock mapper; the differences
 * where stock VTK departs from the model are listed in docs/compatibility.md.
 *
 * The generated shader contains only what the scene needs (no specular code when the
 * specular coefficient is 0, one loop per light kind present, ...). Each primitive's shader
 * is identified by a signature; changing a value (colour, intensity, light position) only
 * updates uniforms, while changing the structure builds a new shader variant. The statistics
 * below let tests and benchmarks see this.
 *
 * Primitives the model does not cover (PBR interpolation, vertex visibility glyphs, selection
 * highlights, VTK's lighting-map passes) are drawn by the stock code.
 *
 * @sa vtkPhongProperty vtkOpenGLPolyDataMapper
 */

#ifndef vtkPhongPolyDataMapper_h
#define vtkPhongPolyDataMapper_h

#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenMeshNormals.h"      // for the weighting values
#include "vtkRenderingPhongModule.h" // for export macro

#include <map>    // for std::map
#include <memory> // for std::unique_ptr

class vtkShaderProperty;

class VTKRENDERINGPHONG_EXPORT vtkPhongPolyDataMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkPhongPolyDataMapper* New();
  vtkTypeMacro(vtkPhongPolyDataMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * What the mapper shows: the final colour, one term alone (textures still multiply the
   * ambient and diffuse terms), the shading normal as a colour ((N + 1) / 2, view
   * coordinates), or the full contribution of the light chosen by DebugLightIndex.
   *
   * PositionVC and NormalVC write a G-buffer for a float target (vtkPhongFloatRenderPass):
   * the shaded point's view-coordinate position, and the shading normal exactly as the
   * lighting uses it (unit, view coordinates, after the fallbacks and the turn towards the
   * viewer), unencoded. Their alpha is 1 on front faces and 0.5 on back faces, so the
   * material side can be told; an 8-bit window clamps them. vtkPhongReference shades such a
   * G-buffer in double precision to measure the shading arithmetic alone. Per-vertex
   * Gouraud has no per-fragment normal: NormalVC shows the interpolated one.
   */
  enum DebugViews
  {
    Final = 0,
    AmbientTerm = 1,
    DiffuseTerm = 2,
    SpecularTerm = 3,
    EmissionTerm = 4,
    ShadingNormal = 5,
    SingleLight = 6,
    PositionVC = 7,
    NormalVC = 8
  };

  ///@{
  /**
   * The debug view. Default Final; one of the DebugViews (values are clamped).
   * Each view is its own shader variant.
   */
  vtkSetClampMacro(DebugView, int, Final, NormalVC);
  vtkGetMacro(DebugView, int);
  void SetDebugViewToFinal() { this->SetDebugView(Final); }
  void SetDebugViewToAmbientTerm() { this->SetDebugView(AmbientTerm); }
  void SetDebugViewToDiffuseTerm() { this->SetDebugView(DiffuseTerm); }
  void SetDebugViewToSpecularTerm() { this->SetDebugView(SpecularTerm); }
  void SetDebugViewToEmissionTerm() { this->SetDebugView(EmissionTerm); }
  void SetDebugViewToShadingNormal() { this->SetDebugView(ShadingNormal); }
  void SetDebugViewToSingleLight() { this->SetDebugView(SingleLight); }
  void SetDebugViewToPositionVC() { this->SetDebugView(PositionVC); }
  void SetDebugViewToNormalVC() { this->SetDebugView(NormalVC); }
  const char* GetDebugViewAsString();
  ///@}

  ///@{
  /**
   * The light shown by the SingleLight view: its index among the renderer's switched-on
   * lights, in the order of the renderer's light collection. Default 0, range [0, VTK_INT_MAX];
   * an index with no light renders black and reports an error. Changing it does not build a
   * new shader.
   */
  vtkSetClampMacro(DebugLightIndex, int, 0, VTK_INT_MAX);
  vtkGetMacro(DebugLightIndex, int);
  ///@}

  ///@{
  /**
   * Normals for input without them. When the input has neither point nor cell normals, has
   * polygons or strips, and the actor's interpolation is not Flat, the mapper computes point
   * normals with vtkOpenMeshNormals (stock VTK shades such input with faceted screen-space
   * normals). The result is cached: it is recomputed only when the input or these settings
   * change, and when only the points move the filter reuses its topology. With splitting,
   * points along sharp edges are duplicated; point picking still reports input point ids
   * (the mapper uses the vtkOriginalPointIds array unless a PointIdArrayName is set).
   * ComputeMissingNormals: default on. NormalsWeighting: default vtkOpenMeshNormals::Max, one
   * of Uniform, Area, Angle, Max. NormalsFeatureAngle: default 30 degrees, range [0, 180].
   * NormalsSplitting: default on.
   */
  vtkSetMacro(ComputeMissingNormals, bool);
  vtkGetMacro(ComputeMissingNormals, bool);
  vtkBooleanMacro(ComputeMissingNormals, bool);
  vtkSetClampMacro(NormalsWeighting, int, vtkOpenMeshNormals::Uniform, vtkOpenMeshNormals::Max);
  vtkGetMacro(NormalsWeighting, int);
  void SetNormalsWeightingToUniform() { this->SetNormalsWeighting(vtkOpenMeshNormals::Uniform); }
  void SetNormalsWeightingToArea() { this->SetNormalsWeighting(vtkOpenMeshNormals::Area); }
  void SetNormalsWeightingToAngle() { this->SetNormalsWeighting(vtkOpenMeshNormals::Angle); }
  void SetNormalsWeightingToMax() { this->SetNormalsWeighting(vtkOpenMeshNormals::Max); }
  virtual void SetNormalsFeatureAngle(double angle); ///< NaN is refused with an error
  vtkGetMacro(NormalsFeatureAngle, double);
  vtkSetMacro(NormalsSplitting, bool);
  vtkGetMacro(NormalsSplitting, bool);
  vtkBooleanMacro(NormalsSplitting, bool);
  ///@}

  /**
   * The filter that computes missing normals (its counts describe the last computation), and
   * whether the last render used its output.
   */
  vtkOpenMeshNormals* GetNormalsGenerator();
  vtkGetMacro(UsedGeneratedNormals, bool);

  ///@{
  /**
   * Shader specialization. On (the default), the generated shader holds only what the scene
   * needs (docs/shaders.md). Off, the mapper builds the all-features variant instead: every
   * optional term (ambient, diffuse, specular, emission, the ambient light of positional
   * lights, distance attenuation, spot falloff and soft edges, the normal fallback) and a
   * loop for every light kind, lights the scene lacks standing in with zero intensity. It
   * draws the same picture, more slowly: it exists to measure what specialization buys.
   */
  vtkSetMacro(ShaderSpecialization, bool);
  vtkGetMacro(ShaderSpecialization, bool);
  vtkBooleanMacro(ShaderSpecialization, bool);
  ///@}

  ///@{
  /**
   * Interpolated dot products. On (the default), directional lights lit per fragment take
   * N.L and L.V from dot products evaluated at the vertices and interpolated, where the
   * shading normal is VTK's vertex normal and the lobe is Phong's (docs/shaders.md): exact up
   * to rounding, about a fifth less lighting time, about twice the rounding (1e-5 in ordinary
   * scenes, docs/results/extremes.md). Off, they compute both per fragment: it exists to
   * measure the trade.
   */
  vtkSetMacro(InterpolatedDotProducts, bool);
  vtkGetMacro(InterpolatedDotProducts, bool);
  vtkBooleanMacro(InterpolatedDotProducts, bool);
  ///@}

  ///@{
  /**
   * Light culling. A point or spot light is left out of this actor's shader when the colour
   * it could add anywhere in the actor's bounds, with the actor's materials, is small: the
   * lights left out add at most LightCullingBound together, per channel (linear colour,
   * before clamping), so the picture differs from the unculled one by at most that much
   * (docs/lighting-model.md, "Light culling"). Default 0.5 / 255 (half an 8-bit level),
   * range [0, 1e9]; 0 evaluates every light. Only in the final view (debug views keep every
   * light). NumberOfCulledLights: how many lights the last planned primitive left out.
   * Culling changes the light counts of the variant: each culled set is its own cached
   * program, so a light that moves in and out of reach switches between two compiled
   * programs.
   */
  virtual void SetLightCullingBound(double bound); ///< NaN is refused with an error
  vtkGetMacro(LightCullingBound, double);
  int GetNumberOfCulledLights();
  ///@}

  enum DepthPrePassModes
  {
    DepthPrePassOff = 0,
    DepthPrePassOn = 1,
    DepthPrePassAutomatic = 2
  };

  ///@{
  /**
   * Depth pre-pass: draw the opaque geometry once with a program that computes no light
   * (colour writes off), then lit, so that with the depth test (VTK's GL_LEQUAL) only the
   * nearest surface of each pixel is shaded however many layers lie behind it. The pre-pass
   * costs about one unlit draw and saves the lighting of every hidden layer. Automatic (the
   * default) counts, on the GPU, the fragments a plain draw shades and those the pre-pass
   * leaves visible, and uses the pre-pass while the hidden share pays for it under the
   * lights evaluated (vtkPhongDepthPrePass.h; the break-even is in
   * docs/results/performance.md, "Depth complexity"); On always, Off never. Never in
   * translucent passes (depth peeling included), hardware selection (picking), for unlit
   * actors or with edges or vertices shown; Automatic also leaves out render passes (shadows,
   * SSAO), depth offsets and imposters, where the lit draw cannot skip hidden fragments.
   * UsedDepthPrePass: whether the last draw used it. DepthComplexity: fragments a plain draw
   * shades per visible one, as last measured by Automatic (0: not measured).
   */
  vtkSetClampMacro(DepthPrePass, int, DepthPrePassOff, DepthPrePassAutomatic);
  vtkGetMacro(DepthPrePass, int);
  vtkGetMacro(UsedDepthPrePass, bool);
  double GetDepthComplexity();
  ///@}

  ///@{
  /**
   * Occlusion culling of the depth pre-pass (default on): the depth pass only has to hold
   * the nearest surfaces, so it leaves out the triangles hidden in the last frame. The
   * triangles are cut into up to 256 spatially compact clusters (never mixing large
   * connected components, such as nested contours); the depth pass draws the clusters seen,
   * nearest first, each counted by an occlusion query (read a frame later), and leaves out
   * those none of whose fragments passed; every 32 frames it draws each hidden cluster again
   * to see whether it came into view. The lit draw still draws every triangle, so a cluster
   * that comes into view costs frames of overdraw, never a wrong pixel. It applies to inputs
   * of polygons only (no vertices, lines or strips), drawn as surfaces, outside render
   * passes (vtkPhongVisibleClusters.h). DepthPassTriangles: the triangles the last depth
   * pass drew (0 without a pre-pass).
   */
  vtkSetMacro(DepthPrePassOcclusionCulling, bool);
  vtkGetMacro(DepthPrePassOcclusionCulling, bool);
  vtkBooleanMacro(DepthPrePassOcclusionCulling, bool);
  vtkGetMacro(DepthPassTriangles, double);
  ///@}

  ///@{
  /**
   * Culling of hidden back faces (default on). Seen from outside, the back faces of a closed,
   * consistently oriented surface all lie behind its front faces, yet a plain draw sets
   * them up, rasterizes them and tests their depth (on llvmpipe about a third of a closed
   * mesh's frame). When the triangles form closed surfaces that bound a solid, never its
   * inside-out (checked once per upload: points at one position taken as one, every edge
   * used once each way, no concave polygon, cavities inside the solid), and the camera sees
   * all of the bounds from beyond the near plane, the mapper culls the faces turned away:
   * the picture is the same, but for pixels where a back face won a depth tie by rounding.
   * Never for translucent or textured actors, other representations than surface, edges or
   * vertices shown, clipping planes, shader code of the user's, triangle strips, wide lines,
   * hardware selection, render passes (a shadow map is drawn from the light) or when the
   * actor's property culls faces itself (vtkPhongClosedSurface.h). The analysis costs about
   * 0.1 s per million triangles, once per upload. UsedClosedSurfaceCulling: whether the last
   * draw culled.
   */
  vtkSetMacro(ClosedSurfaceCulling, bool);
  vtkGetMacro(ClosedSurfaceCulling, bool);
  vtkBooleanMacro(ClosedSurfaceCulling, bool);
  vtkGetMacro(UsedClosedSurfaceCulling, bool);
  ///@}

  ///@{
  /**
   * Shader statistics since the mapper was created (or last released its graphics resources).
   * ShaderCompileCount: how many times the mapper asked the render window for a program
   * whose source it had not used before; each costs a compile and link unless another mapper
   * compiled the identical source first. NumberOfShaderVariants: distinct lighting
   * signatures built. LastShaderBuildTime: seconds spent in the last such build (source
   * generation, compile and link).
   */
  int GetShaderCompileCount();
  int GetNumberOfShaderVariants();
  double GetLastShaderBuildTime();
  ///@}

  ///@{
  /**
   * The most lighting shader programs the mapper keeps compiled. Beyond it, the least
   * recently used program is released: VTK's shader cache keeps its source and compiles it
   * again (counted in ShaderCompileCount) if the scene needs it again. Default 32, range
   * [0, 4096]; 0 keeps every program. A program costs about 1.5 MB on llvmpipe; a scene whose
   * structure keeps changing (a light count raised from 1 to 200) would otherwise keep every
   * one. NumberOfCompiledShaderPrograms: how many of the mapper's programs are compiled now;
   * NumberOfReleasedShaderPrograms: how many it released so far.
   */
  vtkSetClampMacro(MaximumNumberOfShaderPrograms, int, 0, 4096);
  vtkGetMacro(MaximumNumberOfShaderPrograms, int);
  int GetNumberOfCompiledShaderPrograms();
  int GetNumberOfReleasedShaderPrograms();
  ///@}

  ///@{
  /**
   * The lighting signature and the shader sources (before the render window's version and
   * output substitutions) of the last shader this mapper built. The signature lists the
   * features present and the light counts per kind; it is empty for a primitive drawn by
   * the stock code.
   */
  const char* GetLastShaderSignature();
  const char* GetLastVertexShaderSource();
  const char* GetLastFragmentShaderSource();
  const char* GetLastGeometryShaderSource();
  ///@}

  void ReleaseGraphicsResources(vtkWindow* window) override;

  ///@{
  /**
   * The colours of the data set drawn: the normals' output where the mapper computed the
   * normals (its points split at sharp edges), the input otherwise.
   */
  using Superclass::MapScalars;
  vtkUnsignedCharArray* MapScalars(double alpha) override;
  vtkUnsignedCharArray* MapScalars(double alpha, int& cellFlag) override;
  ///@}

  /**
   * Copy the settings of another mapper, the debug view included.
   */
  void ShallowCopy(vtkAbstractMapper* mapper) override;

protected:
  vtkPhongPolyDataMapper();
  ~vtkPhongPolyDataMapper() override;

  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  /// VTK's test, with the input as it was (no computed normals) for points and lines, which
  /// stock VTK draws unlit without normals.
  bool StockNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act);
  void UpdateShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void BuildShaders(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderLight(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetLightingShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void SetPropertyShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void ComputeBounds() override;
  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;

  int DebugView = Final;
  int DebugLightIndex = 0;
  bool ComputeMissingNormals = true;
  int NormalsWeighting = vtkOpenMeshNormals::Max;
  double NormalsFeatureAngle = 30.0;
  bool NormalsSplitting = true;
  bool UsedGeneratedNormals = false;
  bool ShaderSpecialization = true;
  bool InterpolatedDotProducts = true;
  double LightCullingBound = 0.5 / 255.0;
  int DepthPrePass = DepthPrePassAutomatic;
  bool UsedDepthPrePass = false;
  bool DepthPrePassOcclusionCulling = true;
  double DepthPassTriangles = 0.0;
  bool ClosedSurfaceCulling = true;
  bool UsedClosedSurfaceCulling = false;
  int MaximumNumberOfShaderPrograms = 32;

private:
  vtkPhongPolyDataMapper(const vtkPhongPolyDataMapper&) = delete;
  void operator=(const vtkPhongPolyDataMapper&) = delete;

  vtkPolyData* GetValidInput(vtkPolyData* input);
  void DrawSurfaces(vtkRenderer* ren, vtkActor* act);
  unsigned int HiddenFaces(vtkRenderer* ren, vtkActor* act);
  bool CanCullDepthPass(vtkRenderer* ren, vtkActor* act);
  void DrawDepthPass(vtkRenderer* ren, vtkActor* act, bool culled);
  vtkShaderProperty* LegacyShaders() const;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
