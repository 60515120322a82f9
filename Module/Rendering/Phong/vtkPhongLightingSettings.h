/**
 * @class   vtkPhongLightingSettings
 * @brief   the settings of vtkPhong's lighting, shared by every mapper that lights with it
 *
 * vtkPhongLightingSettings holds what a user sets on vtkPhongPolyDataMapper and
 * vtkPhongCompositePolyDataMapper about the lighting: the debug view, light culling, the
 * visibility work (closed-surface culling, the depth pre-pass and its occlusion culling) and
 * the shader cache. Both mappers expose every setting under the same name
 * (vtkPhongLightingSettingsForwardingMacro) and forward it here, so a setting exists on both
 * or on neither (TestPhongSettingsParity checks it), one NaN policy applies (NaN is refused
 * with an error, never stored) and one PrintSelf and DeepCopy describe and copy them.
 *
 * Several mappers may share one object (SetLightingSettings on each): ParaView's "Phong
 * Surface" gives its full-resolution and level-of-detail mappers the same one.
 *
 * Two settings exist to measure what a mechanism buys and are not for users:
 * ShaderSpecialization and InterpolatedDotProducts (their docs say "Measurement only").
 *
 * @sa vtkPhongPolyDataMapper vtkPhongCompositePolyDataMapper
 */

#ifndef vtkPhongLightingSettings_h
#define vtkPhongLightingSettings_h

#include "vtkObject.h"
#include "vtkRenderingPhongModule.h" // for export macro

class VTKRENDERINGPHONG_EXPORT vtkPhongLightingSettings : public vtkObject
{
public:
  static vtkPhongLightingSettings* New();
  vtkTypeMacro(vtkPhongLightingSettings, vtkObject);
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
   *
   * BudgetUse shows how each primitive spends the error budget (ErrorBudget): it is planned
   * as the final view, then drawn in one colour, blue where the light sums stay per fragment,
   * green where the specular sums go per vertex and the diffuse term stays per fragment,
   * orange where every sum goes per vertex; its brightness goes from 0.25 (nothing spent)
   * to 1 (the whole budget spent, GetErrorBound() / ErrorBudget, light culling included).
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
    NormalVC = 8,
    BudgetUse = 9
  };

  enum DepthPrePassModes
  {
    DepthPrePassOff = 0,
    DepthPrePassOn = 1,
    DepthPrePassAutomatic = 2
  };

  /**
   * Where a primitive's light sums went under ErrorBudget (the mappers' GetBudgetMode):
   * every sum at each fragment, as in the exact mode; the specular sums at the vertices and
   * the diffuse term at each fragment; every sum at the vertices, interpolated.
   */
  enum BudgetModes
  {
    BudgetPerFragment = 0,
    BudgetSpecularPerVertex = 1,
    BudgetPerVertex = 2
  };

  /**
   * A BudgetModes value's name: "per fragment", "specular per vertex", "per vertex"
   * ("unknown" for any other value).
   */
  static const char* GetBudgetModeAsString(int mode);

  /**
   * The settings that the mappers code which never names vtkPhong gets start from: those
   * VTK's object factory makes while vtkPhongObjectFactory's switch is on
   * (`vtkPolyDataMapper()` in a PyVista, vedo or VTK script, the one inside
   * vtkDataSetMapper), and the block mappers it gives VTK's own composite mapper (VTK 9.3
   * on). One object for the process, made on first use; each such mapper copies it when it
   * is made (as PyVista's global theme applies to what is made after it), so set a value here
   * (an ErrorBudget, a DebugView) before the scene is built. Python:
   * `vtkphong.overrides.defaults()`. A mapper made by name starts from its class's defaults.
   * A program that cannot call this (one run with VTK_AUTOLOAD_PATH and no change to its
   * code, pvbatch) states its budget in the environment: VTKPHONG_ERROR_BUDGET, in levels,
   * is read when the defaults are made; anything but a number in [0, 255] is reported with
   * an error and left out.
   */
  static vtkPhongLightingSettings* GetFactoryDefaults();

  ///@{
  /**
   * The debug view. Default Final; one of the DebugViews (values are clamped).
   * Each view is its own shader variant.
   */
  vtkSetClampMacro(DebugView, int, Final, BudgetUse);
  vtkGetMacro(DebugView, int);
  const char* GetDebugViewAsString();
  static const char* DebugViewAsString(int view);
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
   * Measurement only: shader specialization. On (the default), the generated shader holds
   * only what the scene needs (docs/shaders.md). Off, the mapper builds the all-features
   * variant instead: every optional term (ambient, diffuse, specular, emission, the ambient
   * light of positional lights, distance attenuation, spot falloff and soft edges, the normal
   * fallback) and a loop for every light kind, lights the scene lacks standing in with zero
   * intensity. It draws the same picture, more slowly: it exists to measure what
   * specialization buys.
   */
  vtkSetMacro(ShaderSpecialization, bool);
  vtkGetMacro(ShaderSpecialization, bool);
  vtkBooleanMacro(ShaderSpecialization, bool);
  ///@}

  ///@{
  /**
   * Measurement only: interpolated dot products. On (the default), directional lights lit
   * per fragment take N.L and L.V from dot products evaluated at the vertices and
   * interpolated, where the shading normal is VTK's vertex normal and the lobe is Phong's
   * (docs/shaders.md): exact up to rounding, about a fifth less lighting time, about twice
   * the rounding (1e-5 in ordinary scenes, docs/results/extremes.md). Off, they compute both
   * per fragment: it exists to measure the trade.
   */
  vtkSetMacro(InterpolatedDotProducts, bool);
  vtkGetMacro(InterpolatedDotProducts, bool);
  vtkBooleanMacro(InterpolatedDotProducts, bool);
  ///@}

  ///@{
  /**
   * Light culling. A point or spot light is left out of an actor's shader when the colour it
   * could add anywhere in the actor's bounds, with the actor's materials, is small: the
   * lights left out add at most LightCullingBound together, per channel (linear colour,
   * before clamping), so the picture differs from the unculled one by at most that much
   * (docs/lighting-model.md, "Light culling"). Default 0.5 / 255 (half an 8-bit level),
   * range [0, 1e9]; 0 evaluates every light; NaN is refused with an error. Only in the final
   * view (debug views keep every light). Culling changes the light counts of the variant:
   * each culled set is its own cached program, so a light that moves in and out of reach
   * switches between two compiled programs.
   */
  virtual void SetLightCullingBound(double bound);
  vtkGetMacro(LightCullingBound, double);
  ///@}

  /**
   * SetLightCullingBound, reporting a refused value through `reporter` (the mapper the user
   * set it on) rather than through this object.
   */
  void SetLightCullingBound(double bound, vtkObject* reporter);

  ///@{
  /**
   * The error budget: how far, in 8-bit levels, each pixel's linear colour (per channel,
   * before clamping) may stray from the exact per-fragment model computed in double, so that
   * the mapper may draw faster. Default 0, range [0, 255]; NaN is refused with an error.
   * 0 is the exact mode: no approximation enters it and its shaders are those of a mapper
   * without the setting. Above 0 the mapper spends the budget where a proven bound shows it
   * fits (docs/lighting-model.md, "Error budget"):
   * - light culling takes at most half of it (and never more than LightCullingBound);
   * - a surface with point normals under directional lights and point lights (attenuated
   *   ones with a constant term; not spot lights) is lit at its vertices and the sums
   *   interpolated (VTK's true Gouraud), when the bound on the difference from per-fragment
   *   lighting, over every triangle and every light, fits what culling left and the mesh's
   *   vertices are fewer than the fragments it covers (on sub-pixel triangles per-vertex
   *   lighting costs more, and the mapper keeps per fragment);
   * - a whole shininess from 2 to 1000 is raised by squaring instead of pow, its rounding
   *   charged to the budget.
   * Only in the final view. Each choice is its own cached program.
   */
  virtual void SetErrorBudget(double levels);
  vtkGetMacro(ErrorBudget, double);
  ///@}

  /**
   * SetErrorBudget, reporting a refused value through `reporter`.
   */
  void SetErrorBudget(double levels, vtkObject* reporter);

  ///@{
  /**
   * Specular anti-aliasing: each fragment's specular lobe widened by the shading normal's
   * variation over its pixel, so that a highlight narrower than a pixel shows the pixel's
   * average instead of one sample of it (no sparkle, no flicker as the surface turns). The
   * lobe cos^n is about a Gaussian of variance 1/n in angle; the normal's spread over the
   * pixel's box adds (|dN/dx|^2 + |dN/dy|^2) / 24 (four times that for the Phong lobe, whose
   * reflection vector turns twice as fast), capped at 0.09 where derivatives spike at
   * silhouettes, and the lobe keeps its energy ((n' + 1) / (n + 1)); docs/lighting-model.md,
   * "Specular anti-aliasing". It changes the model (a pixel's average, not its centre), so
   * it is off by default. Per fragment only (per-vertex sums are already averaged over
   * their triangles); under an error budget the sums stay per fragment, the budget being
   * defined against the unfiltered model. Its shaders are variants of their own.
   */
  vtkSetMacro(SpecularAntiAliasing, bool);
  vtkGetMacro(SpecularAntiAliasing, bool);
  vtkBooleanMacro(SpecularAntiAliasing, bool);
  ///@}

  ///@{
  /**
   * What a surface shows when the renderer has no switched-on light (automatic light
   * creation off, every light removed or switched off: PyVista's `lighting=None` and
   * `remove_all_lights()`, vedo's `lighting("off")` on a renderer). Off (the default), as
   * VTK: unlit, its colours as they are (a colour map's true colours). On, what the model
   * gives without a light: emission and the ambient term E + ka*Ca*Ia (docs/lighting-model.md).
   */
  vtkSetMacro(LightingWithoutLights, bool);
  vtkGetMacro(LightingWithoutLights, bool);
  vtkBooleanMacro(LightingWithoutLights, bool);
  ///@}

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
   * Composite data: over the blocks one block mapper draws together, never for blocks that
   * mix point and cell scalars, which VTK 9.1 colours wrongly. Default DepthPrePassAutomatic;
   * one of the DepthPrePassModes (clamped).
   */
  vtkSetClampMacro(DepthPrePass, int, DepthPrePassOff, DepthPrePassAutomatic);
  vtkGetMacro(DepthPrePass, int);
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
   * passes (vtkPhongVisibleClusters.h); composite data only while every block a block mapper
   * draws is visible and opaque.
   */
  vtkSetMacro(DepthPrePassOcclusionCulling, bool);
  vtkGetMacro(DepthPrePassOcclusionCulling, bool);
  vtkBooleanMacro(DepthPrePassOcclusionCulling, bool);
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
   * actor's property culls faces itself (vtkPhongClosedSurface.h). Composite data: over the
   * blocks one block mapper draws together, only while every one of them is visible and
   * opaque, so that no block left out opens a surface the others close. The analysis costs
   * about 0.1 s per million triangles, once per upload.
   */
  vtkSetMacro(ClosedSurfaceCulling, bool);
  vtkGetMacro(ClosedSurfaceCulling, bool);
  vtkBooleanMacro(ClosedSurfaceCulling, bool);
  ///@}

  ///@{
  /**
   * The most lighting shader programs a mapper (each block mapper of a composite one) keeps
   * compiled. Beyond it, the least recently used program is released: VTK's shader cache
   * keeps its source and compiles it again (counted in ShaderCompileCount) if the scene
   * needs it again. Default 32, range [0, 4096]; 0 keeps every program. A program costs about
   * 1.5 MB on llvmpipe; a scene whose structure keeps changing (a light count raised from 1
   * to 200) would otherwise keep every one.
   */
  vtkSetClampMacro(MaximumNumberOfShaderPrograms, int, 0, 4096);
  vtkGetMacro(MaximumNumberOfShaderPrograms, int);
  ///@}

  /**
   * Copy every setting of `other` (nothing when it is nullptr).
   */
  void DeepCopy(vtkPhongLightingSettings* other);

protected:
  vtkPhongLightingSettings() = default;
  ~vtkPhongLightingSettings() override = default;

  int DebugView = Final;
  int DebugLightIndex = 0;
  bool ShaderSpecialization = true;
  bool InterpolatedDotProducts = true;
  double LightCullingBound = 0.5 / 255.0;
  double ErrorBudget = 0.0;
  bool SpecularAntiAliasing = false;
  bool LightingWithoutLights = false;
  int DepthPrePass = DepthPrePassAutomatic;
  bool DepthPrePassOcclusionCulling = true;
  bool ClosedSurfaceCulling = true;
  int MaximumNumberOfShaderPrograms = 32;

private:
  // A bounded double setting: NaN refused and values clamped to [0, largest], with the error
  // reported through `reporter`.
  void SetChecked(vtkObject* reporter, const char* name, double& member, double value,
    double largest);

  vtkPhongLightingSettings(const vtkPhongLightingSettings&) = delete;
  void operator=(const vtkPhongLightingSettings&) = delete;
};

#ifndef __VTK_WRAP__
#include "vtkSmartPointer.h" // for vtkSmartPointer

/**
 * The settings object a mapper holds: never nullptr (SetLightingSettings refuses it with an
 * error through the mapper), its changes counted in the mapper's modification time.
 */
class VTKRENDERINGPHONG_EXPORT vtkPhongLightingSettingsHolder
{
public:
  vtkPhongLightingSettings* Get() const { return this->Settings; }
  /// Hold `settings`; whether that changed what is held.
  bool Set(vtkPhongLightingSettings* settings, vtkObject* holder);
  /// The later of the holder's own time and the settings' modification time.
  vtkMTimeType MTime(vtkMTimeType holderTime) const;

private:
  vtkSmartPointer<vtkPhongLightingSettings> Settings =
    vtkSmartPointer<vtkPhongLightingSettings>::New();
};
#endif

/**
 * The lighting settings as a mapper exposes them: every setting of vtkPhongLightingSettings
 * under the same name, forwarded to the mapper's settings object, with the debug-view and
 * pre-pass and budget-mode enumerations; GetMTime counts the settings' changes. Used once in
 * the class body of each vtkPhong mapper, which defines GetLightingSettings and
 * SetLightingSettings (a mapper always has settings: nullptr is refused).
 */
#define vtkPhongLightingSettingsForwardingMacro()                                                  \
  enum DebugViews                                                                                  \
  {                                                                                                \
    Final = vtkPhongLightingSettings::Final,                                                       \
    AmbientTerm = vtkPhongLightingSettings::AmbientTerm,                                           \
    DiffuseTerm = vtkPhongLightingSettings::DiffuseTerm,                                           \
    SpecularTerm = vtkPhongLightingSettings::SpecularTerm,                                         \
    EmissionTerm = vtkPhongLightingSettings::EmissionTerm,                                         \
    ShadingNormal = vtkPhongLightingSettings::ShadingNormal,                                       \
    SingleLight = vtkPhongLightingSettings::SingleLight,                                           \
    PositionVC = vtkPhongLightingSettings::PositionVC,                                             \
    NormalVC = vtkPhongLightingSettings::NormalVC,                                                 \
    BudgetUse = vtkPhongLightingSettings::BudgetUse                                                \
  };                                                                                               \
  enum DepthPrePassModes                                                                           \
  {                                                                                                \
    DepthPrePassOff = vtkPhongLightingSettings::DepthPrePassOff,                                   \
    DepthPrePassOn = vtkPhongLightingSettings::DepthPrePassOn,                                     \
    DepthPrePassAutomatic = vtkPhongLightingSettings::DepthPrePassAutomatic                        \
  };                                                                                               \
  enum BudgetModes                                                                                 \
  {                                                                                                \
    BudgetPerFragment = vtkPhongLightingSettings::BudgetPerFragment,                               \
    BudgetSpecularPerVertex = vtkPhongLightingSettings::BudgetSpecularPerVertex,                   \
    BudgetPerVertex = vtkPhongLightingSettings::BudgetPerVertex                                    \
  };                                                                                               \
  vtkPhongLightingSettings* GetLightingSettings();                                                 \
  void SetLightingSettings(vtkPhongLightingSettings* settings);                                    \
  vtkMTimeType GetMTime() override;                                                                \
  void SetDebugView(int view)                                                                      \
  {                                                                                                \
    this->GetLightingSettings()->SetDebugView(view);                                               \
  }                                                                                                \
  int GetDebugView()                                                                               \
  {                                                                                                \
    return this->GetLightingSettings()->GetDebugView();                                            \
  }                                                                                                \
  const char* GetDebugViewAsString()                                                               \
  {                                                                                                \
    return this->GetLightingSettings()->GetDebugViewAsString();                                    \
  }                                                                                                \
  void SetDebugViewToFinal()                                                                       \
  {                                                                                                \
    this->SetDebugView(Final);                                                                     \
  }                                                                                                \
  void SetDebugViewToAmbientTerm()                                                                 \
  {                                                                                                \
    this->SetDebugView(AmbientTerm);                                                               \
  }                                                                                                \
  void SetDebugViewToDiffuseTerm()                                                                 \
  {                                                                                                \
    this->SetDebugView(DiffuseTerm);                                                               \
  }                                                                                                \
  void SetDebugViewToSpecularTerm()                                                                \
  {                                                                                                \
    this->SetDebugView(SpecularTerm);                                                              \
  }                                                                                                \
  void SetDebugViewToEmissionTerm()                                                                \
  {                                                                                                \
    this->SetDebugView(EmissionTerm);                                                              \
  }                                                                                                \
  void SetDebugViewToShadingNormal()                                                               \
  {                                                                                                \
    this->SetDebugView(ShadingNormal);                                                             \
  }                                                                                                \
  void SetDebugViewToSingleLight()                                                                 \
  {                                                                                                \
    this->SetDebugView(SingleLight);                                                               \
  }                                                                                                \
  void SetDebugViewToPositionVC()                                                                  \
  {                                                                                                \
    this->SetDebugView(PositionVC);                                                                \
  }                                                                                                \
  void SetDebugViewToNormalVC()                                                                    \
  {                                                                                                \
    this->SetDebugView(NormalVC);                                                                  \
  }                                                                                                \
  void SetDebugViewToBudgetUse()                                                                   \
  {                                                                                                \
    this->SetDebugView(BudgetUse);                                                                 \
  }                                                                                                \
  void SetDebugLightIndex(int index)                                                               \
  {                                                                                                \
    this->GetLightingSettings()->SetDebugLightIndex(index);                                        \
  }                                                                                                \
  int GetDebugLightIndex()                                                                         \
  {                                                                                                \
    return this->GetLightingSettings()->GetDebugLightIndex();                                      \
  }                                                                                                \
  void SetShaderSpecialization(bool on)                                                            \
  {                                                                                                \
    this->GetLightingSettings()->SetShaderSpecialization(on);                                      \
  }                                                                                                \
  bool GetShaderSpecialization()                                                                   \
  {                                                                                                \
    return this->GetLightingSettings()->GetShaderSpecialization();                                 \
  }                                                                                                \
  void ShaderSpecializationOn()                                                                    \
  {                                                                                                \
    this->SetShaderSpecialization(true);                                                           \
  }                                                                                                \
  void ShaderSpecializationOff()                                                                   \
  {                                                                                                \
    this->SetShaderSpecialization(false);                                                          \
  }                                                                                                \
  void SetInterpolatedDotProducts(bool on)                                                         \
  {                                                                                                \
    this->GetLightingSettings()->SetInterpolatedDotProducts(on);                                   \
  }                                                                                                \
  bool GetInterpolatedDotProducts()                                                                \
  {                                                                                                \
    return this->GetLightingSettings()->GetInterpolatedDotProducts();                              \
  }                                                                                                \
  void InterpolatedDotProductsOn()                                                                 \
  {                                                                                                \
    this->SetInterpolatedDotProducts(true);                                                        \
  }                                                                                                \
  void InterpolatedDotProductsOff()                                                                \
  {                                                                                                \
    this->SetInterpolatedDotProducts(false);                                                       \
  }                                                                                                \
  void SetLightCullingBound(double bound)                                                          \
  {                                                                                                \
    this->GetLightingSettings()->SetLightCullingBound(bound, this);                                \
  }                                                                                                \
  double GetLightCullingBound()                                                                    \
  {                                                                                                \
    return this->GetLightingSettings()->GetLightCullingBound();                                    \
  }                                                                                                \
  void SetErrorBudget(double levels)                                                               \
  {                                                                                                \
    this->GetLightingSettings()->SetErrorBudget(levels, this);                                     \
  }                                                                                                \
  double GetErrorBudget()                                                                          \
  {                                                                                                \
    return this->GetLightingSettings()->GetErrorBudget();                                          \
  }                                                                                                \
  void SetSpecularAntiAliasing(bool on)                                                            \
  {                                                                                                \
    this->GetLightingSettings()->SetSpecularAntiAliasing(on);                                      \
  }                                                                                                \
  bool GetSpecularAntiAliasing()                                                                   \
  {                                                                                                \
    return this->GetLightingSettings()->GetSpecularAntiAliasing();                                 \
  }                                                                                                \
  void SpecularAntiAliasingOn() { this->SetSpecularAntiAliasing(true); }                           \
  void SpecularAntiAliasingOff() { this->SetSpecularAntiAliasing(false); }                         \
  void SetLightingWithoutLights(bool on)                                                           \
  {                                                                                                \
    this->GetLightingSettings()->SetLightingWithoutLights(on);                                     \
  }                                                                                                \
  bool GetLightingWithoutLights()                                                                  \
  {                                                                                                \
    return this->GetLightingSettings()->GetLightingWithoutLights();                                \
  }                                                                                                \
  void LightingWithoutLightsOn() { this->SetLightingWithoutLights(true); }                         \
  void LightingWithoutLightsOff() { this->SetLightingWithoutLights(false); }                       \
  void SetDepthPrePass(int mode)                                                                   \
  {                                                                                                \
    this->GetLightingSettings()->SetDepthPrePass(mode);                                            \
  }                                                                                                \
  int GetDepthPrePass()                                                                            \
  {                                                                                                \
    return this->GetLightingSettings()->GetDepthPrePass();                                         \
  }                                                                                                \
  void SetDepthPrePassOcclusionCulling(bool on)                                                    \
  {                                                                                                \
    this->GetLightingSettings()->SetDepthPrePassOcclusionCulling(on);                              \
  }                                                                                                \
  bool GetDepthPrePassOcclusionCulling()                                                           \
  {                                                                                                \
    return this->GetLightingSettings()->GetDepthPrePassOcclusionCulling();                         \
  }                                                                                                \
  void DepthPrePassOcclusionCullingOn()                                                            \
  {                                                                                                \
    this->SetDepthPrePassOcclusionCulling(true);                                                   \
  }                                                                                                \
  void DepthPrePassOcclusionCullingOff()                                                           \
  {                                                                                                \
    this->SetDepthPrePassOcclusionCulling(false);                                                  \
  }                                                                                                \
  void SetClosedSurfaceCulling(bool on)                                                            \
  {                                                                                                \
    this->GetLightingSettings()->SetClosedSurfaceCulling(on);                                      \
  }                                                                                                \
  bool GetClosedSurfaceCulling()                                                                   \
  {                                                                                                \
    return this->GetLightingSettings()->GetClosedSurfaceCulling();                                 \
  }                                                                                                \
  void ClosedSurfaceCullingOn()                                                                    \
  {                                                                                                \
    this->SetClosedSurfaceCulling(true);                                                           \
  }                                                                                                \
  void ClosedSurfaceCullingOff()                                                                   \
  {                                                                                                \
    this->SetClosedSurfaceCulling(false);                                                          \
  }                                                                                                \
  void SetMaximumNumberOfShaderPrograms(int count)                                                 \
  {                                                                                                \
    this->GetLightingSettings()->SetMaximumNumberOfShaderPrograms(count);                          \
  }                                                                                                \
  int GetMaximumNumberOfShaderPrograms()                                                           \
  {                                                                                                \
    return this->GetLightingSettings()->GetMaximumNumberOfShaderPrograms();                        \
  }

#endif
