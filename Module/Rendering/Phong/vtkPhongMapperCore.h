/**
 * @class   vtkPhongMapperCore
 * @brief   the lighting half of a vtkPhong mapper, shared by every mapper entry point
 *
 * vtkPhongMapperCore carries everything a mapper does with vtkPhong's lighting beyond VTK's
 * own polydata mapper: the plan of each primitive (vtkPhongShaderPlanner), the bookkeeping of
 * shader variants (signatures, compile count, build time, the last sources), the fallback to
 * VTK's lighting when a variant fails to compile, the cached scan for unusable normals, and
 * the reporting of bad parameters. It calls the shader path's parts directly: the planner,
 * the template (vtkPhongShaderTemplate) and the uniforms (vtkPhongLightUniforms,
 * vtkPhongMaterialUniforms, vtkPhongShadowMaps). Every vtkPhongLightingMapper (the polydata
 * mapper, each block mapper of the composite one) owns one.
 *
 * Private to the rendering module: the mappers are the API.
 *
 * @sa vtkPhongLightingMapper vtkPhongShaderPlanner vtkPhongShaderTemplate
 */

#ifndef vtkPhongMapperCore_h
#define vtkPhongMapperCore_h

#include "vtkObject.h"
#include "vtkPhongShaderPlan.h"      // for the plan
#include "vtkRenderingPhongModule.h" // for export macro
#include "vtkShader.h"               // for vtkShader::Type
#include "vtkSmartPointer.h"         // for vtkSmartPointer

#include <functional> // for std::function
#include <map>        // for std::map
#include <memory>     // for std::unique_ptr
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkActor;
class vtkDataArray;
class vtkOpenGLHelper;
class vtkPolyData;
class vtkRenderer;
class vtkShaderProgram;

class VTKRENDERINGPHONG_EXPORT vtkPhongMapperCore : public vtkObject
{
public:
  static vtkPhongMapperCore* New();
  vtkTypeMacro(vtkPhongMapperCore, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The mapper's settings that shape the shader (debug view, light index, specialization).
   */
  vtkPhongPlanOptions Options;

  /**
   * Plan the primitive about to be drawn (from GetNeedToRebuildShaders). Returns true when
   * its lighting signature changed, i.e. the shader must be rebuilt.
   */
  bool PlanPrimitive(const vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act,
    const vtkPhongPrimitiveState& state);

  /**
   * Whether vtkPhong lights this primitive (false: VTK's own lighting code draws it).
   */
  bool Handles(const vtkOpenGLHelper* cellBO) const;

  ///@{
  /**
   * The shader life cycle, from the mapper's overrides of the same names. UpdateShaders:
   * BeginUpdateShaders() before the stock UpdateShaders, EndUpdateShaders() after it; when
   * EndUpdateShaders returns true the program is missing all the same (FinishBuild below
   * normally prevents it; the error is reported on `reporter`) and the mapper calls the
   * stock UpdateShaders once more, which now plans the primitive with VTK's lighting.
   * ShadersBuilt() (from FinishBuild) keeps the sources and makes a failed build visible
   * whatever the VTK version.
   */
  void BeginUpdateShaders();
  void ShadersBuilt(std::map<vtkShader::Type, vtkShader*>& shaders, vtkOpenGLHelper* cellBO);
  ///@}

  /**
   * From the mapper's BuildShaders, after the stock one: make sure the sources compile before
   * VTK asks for their program (VTK 9.1 dereferences the null program of a first build that
   * fails). A vtkPhong variant that fails is reported once, remembered, and the primitive
   * rebuilt with VTK's lighting (`buildStock`, the stock BuildShaders); sources that still fail
   * (the actor's own shader replacements or shader code are broken, where stock VTK 9.1
   * crashes) are reported and rebuilt without them (`buildBare`: VTK's templates, taken
   * through TemplateActor(), and VTK's substitutions). Ends with ShadersBuilt().
   */
  /**
   * A stand-in for `act` with its properties and no shader code of the user's: what the stock
   * GetShaderTemplate needs to choose VTK's own templates for the bare rebuild of FinishBuild.
   */
  static vtkSmartPointer<vtkActor> TemplateActor(vtkActor* act);

  void FinishBuild(std::map<vtkShader::Type, vtkShader*>& shaders, vtkOpenGLHelper* cellBO,
    vtkRenderer* ren, vtkActor* act, vtkObject* reporter, const std::function<void()>& buildStock,
    const std::function<void()>& buildBare);

  ///@{
  /**
   * The rest of the shader life cycle, from the mapper's overrides of the same names.
   */
  bool EndUpdateShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkObject* reporter);
  void ReplaceShaderLight(
    std::map<vtkShader::Type, vtkShader*>& shaders, const vtkOpenGLHelper* cellBO);
  void SetLightUniforms(vtkOpenGLHelper& cellBO, vtkRenderer* ren);
  void SetMaterialUniforms(vtkOpenGLHelper& cellBO);
  ///@}

  /**
   * Report the bad parameters found since the last call through `reporter`'s error macro,
   * once per change (not every frame).
   */
  void ReportProblems(vtkObject* reporter);

  /**
   * The box around `blocks` in world coordinates (the eight corners of their model box
   * through `act`'s matrix), for vtkPhongPrimitiveState::BoundsWC; uninitialized (min > max)
   * when they bound nothing.
   */
  static void BoundsInWorld(
    const std::vector<vtkPolyData*>& blocks, vtkActor* act, double boundsWC[6]);

  /**
   * Whether a normals array holds zero, NaN or infinite vectors, or vectors too short or too
   * long for the shader to normalize in float (squared length outside [1e-30, 1e30]);
   * scanned once per array and modification.
   */
  bool HasUnusableVectors(vtkDataArray* normals);

  ///@{
  /**
   * The most lighting programs this core keeps compiled: beyond it, the least recently used
   * one is released (VTK's shader cache keeps its sources and compiles it again if it is
   * used again). Default 32; 0 keeps every program. Each costs about 1.5 MB on llvmpipe, and
   * a scene whose structure keeps changing (a light count raised from 1 to 200) would
   * otherwise keep them all.
   */
  int MaximumNumberOfPrograms = 32;
  int GetNumberOfReleasedPrograms() const;
  int GetNumberOfCompiledPrograms() const;
  ///@}

  /**
   * Forget the compiled programs (a new context compiles again) and the plans.
   */
  void ReleaseGraphicsResources();

  ///@{
  /**
   * Statistics: see vtkPhongPolyDataMapper::GetShaderCompileCount() and the sources.
   */
  int GetShaderCompileCount() const;
  int GetNumberOfShaderVariants() const;
  double GetLastShaderBuildTime() const;
  int GetNumberOfCulledLights() const; ///< by the last planned primitive
  double GetErrorBound() const;        ///< of the last planned primitive, in 8-bit levels
  int GetBudgetMode() const;           ///< of the last planned primitive (BudgetModes)
  int GetSquaredShininess() const;     ///< of the last planned primitive; 0: pow
  const std::string& GetLastShaderSignature() const;
  const std::string& GetLastVertexShaderSource() const;
  const std::string& GetLastFragmentShaderSource() const;
  const std::string& GetLastGeometryShaderSource() const;
  ///@}

protected:
  vtkPhongMapperCore();
  ~vtkPhongMapperCore() override;

private:
  void TakeSteadyConstants(const vtkOpenGLHelper& cellBO, vtkRenderer* ren,
    const vtkPhongPrimitiveState& state, vtkPhongShaderPlan& plan);
  vtkPhongUniformValues ConstantCandidates(
    vtkRenderer* ren, const vtkPhongPrimitiveState& state, const vtkPhongShaderPlan& plan);
  static bool FewVisibleActors(vtkRenderer* ren);
  // The most visible actors a renderer may draw for the material's values to become constants.
  static constexpr int MaterialConstantsActors = 4;
  static bool Compiles(std::map<vtkShader::Type, vtkShader*>& shaders, vtkRenderer* ren);
  void FallBackToVTK(const vtkOpenGLHelper* cellBO, vtkObject* reporter);
  static void KeepUserLightOutput(vtkShader* fragment, vtkActor* act);
  static bool UserWritesLightOutput(vtkActor* act);
  bool CheckNewProgram(vtkOpenGLHelper& cellBO, vtkObject* reporter);
  void UseProgram(vtkShaderProgram* program, vtkRenderer* ren);
  static std::size_t HashSources(
    const std::string& vertex, const std::string& geometry, const std::string& fragment);

  vtkPhongMapperCore(const vtkPhongMapperCore&) = delete;
  void operator=(const vtkPhongMapperCore&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
