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
#include "vtkOpenMeshNormals.h"       // for the weighting values
#include "vtkPhongLightingMapper.h"   // for the superclass
#include "vtkPhongLightingSettings.h" // for the settings
#include "vtkRenderingPhongModule.h"  // for export macro

#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

// The wrappers see VTK's mapper as the superclass: the lighting template between them adds
// no method of the Python API.
#ifdef __VTK_WRAP__
#define vtkPhongPolyDataMapperSuperclass vtkOpenGLPolyDataMapper
#else
#define vtkPhongPolyDataMapperSuperclass vtkPhongLightingMapper<vtkOpenGLPolyDataMapper>
#endif

class VTKRENDERINGPHONG_EXPORT vtkPhongPolyDataMapper : public vtkPhongPolyDataMapperSuperclass
{
public:
  static vtkPhongPolyDataMapper* New();
  vtkTypeMacro(vtkPhongPolyDataMapper, vtkPhongPolyDataMapperSuperclass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The lighting settings (vtkPhongLightingSettings, where each is documented): the debug
   * view (DebugView, DebugViews, DebugLightIndex), light culling (LightCullingBound), the
   * visibility work (ClosedSurfaceCulling, DepthPrePass, DepthPrePassOcclusionCulling), the
   * shader cache (MaximumNumberOfShaderPrograms) and two measurement-only switches
   * (ShaderSpecialization, InterpolatedDotProducts), each settable here under its own name,
   * as on vtkPhongCompositePolyDataMapper. LightingSettings: the settings object itself,
   * which mappers may share.
   */
  vtkPhongLightingSettingsForwardingMacro();

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

  /**
   * How many point and spot lights the last planned primitive left out (light culling).
   */
  int GetNumberOfCulledLights();

  /**
   * The most the last planned primitive's approximations (light culling, per-vertex lighting
   * under ErrorBudget) may make its colour stray from the exact model, in 8-bit levels.
   */
  double GetErrorBound();

  ///@{
  /**
   * What else the last planned primitive spent ErrorBudget on: where its light sums went
   * (BudgetModes: BudgetPerFragment, always so without a budget, BudgetSpecularPerVertex or
   * BudgetPerVertex; as a string, "per fragment", "specular per vertex" or "per vertex"),
   * and the whole shininess its lobes raised by squaring instead of pow (0: pow, as in the
   * exact mode). The BudgetUse debug view shows the mode in colour.
   */
  int GetBudgetMode();
  const char* GetBudgetModeAsString();
  int GetSquaredShininess();
  ///@}

  ///@{
  /**
   * What the last draw did: whether it used the depth pre-pass, the fragments a plain draw
   * shades per visible one as last measured by the automatic pre-pass (0: not measured), the
   * triangles the last depth pass drew (0 without a pre-pass), and whether it culled the back
   * faces of closed surfaces.
   */
  bool GetUsedDepthPrePass();
  double GetDepthComplexity();
  double GetDepthPassTriangles();
  bool GetUsedClosedSurfaceCulling();
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
   * How many of the mapper's lighting programs are compiled now, and how many it released
   * so far (MaximumNumberOfShaderPrograms).
   */
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

  /// VTK's test, with the input as it was (no computed normals) for points and lines, which
  /// stock VTK draws unlit without normals.
  bool StockNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void ComputeBounds() override;
  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;

  ///@{
  /// One polydata in the buffer, the mapper's own settings (vtkPhongLightingMapper).
  vtkPhongLightingSettings* LightingSettings() override;
  std::vector<vtkPolyData*> LitBlocks() override;
  bool BlocksInBuffer(std::vector<vtkPhongBufferBlock>& blocks) override;
  void SurfaceBounds(double bounds[6]) override;
  ///@}

  bool ComputeMissingNormals = true;
  int NormalsWeighting = vtkOpenMeshNormals::Max;
  double NormalsFeatureAngle = 30.0;
  bool NormalsSplitting = true;
  bool UsedGeneratedNormals = false;

private:
  vtkPhongPolyDataMapper(const vtkPhongPolyDataMapper&) = delete;
  void operator=(const vtkPhongPolyDataMapper&) = delete;

  vtkPolyData* GetValidInput(vtkPolyData* input);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#undef vtkPhongPolyDataMapperSuperclass

#endif
