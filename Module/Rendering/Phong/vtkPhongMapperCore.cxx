#include "vtkPhongMapperCore.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLHelper.h"
#include "vtkPhongCompatibility.h"
#include "vtkPhongLightCulling.h"
#include "vtkPhongLightUniforms.h"
#include "vtkPhongLightingSettings.h"
#include "vtkPhongMaterialUniforms.h"
#include "vtkPhongProblemLog.h"
#include "vtkPhongShaderPlanner.h"
#include "vtkPhongShaderTemplate.h"
#include "vtkPhongShadowMaps.h"
#include "vtkShaderProgram.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkBoundingBox.h"
#include "vtkMath.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLShaderProperty.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <list>
#include <set>

vtkStandardNewMacro(vtkPhongMapperCore);

struct vtkPhongMapperCore::Internals
{
  // Bad parameters met while planning and uploading, reported once by ReportProblems.
  vtkPhongProblemLog Log;
  // The all-features variant (no specialization) stands in lights the scene lacks by these,
  // of zero intensity.
  vtkNew<vtkLight> PlaceholderDirectional;
  vtkNew<vtkLight> PlaceholderPoint;
  vtkNew<vtkLight> PlaceholderSpot;
  // The plan of each primitive (points, lines, polygons, strips), made afresh every frame
  // by PlanPrimitive and used until the next one.
  std::map<const vtkOpenGLHelper*, vtkPhongShaderPlan> Plans;
  // Per primitive, under an error budget: its light and material values as last planned, in how
  // many plans in a row they came back, and how many they must (TakeSteadyConstants).
  struct SteadyValues
  {
    vtkPhongUniformValues Values;
    int Repeats = 0;
    int Required = 1;
    vtkPhongUniformValues Taken; ///< the values last written as constants
    int TakenPlans = 0;          ///< plans that used them since Required last moved
  };
  std::map<const vtkOpenGLHelper*, SteadyValues> Steady;
  std::set<std::string> Signatures;
  // Variants whose shader failed to compile: drawn with VTK's lighting instead.
  std::set<std::string> FailedSignatures;
  // Hashes of the shader sources handed to the render window's shader cache.
  std::set<std::size_t> KnownSources;
  // The lighting programs in use, most recently used first, with their window; those
  // released (the shader cache keeps them and compiles them again on their next use).
  struct UsedProgram
  {
    vtkWeakPointer<vtkShaderProgram> Program;
    vtkWeakPointer<vtkWindow> Window;
  };
  std::list<UsedProgram> RecentPrograms;
  std::set<const vtkShaderProgram*> Released;
  int ReleasedPrograms = 0;
  bool BuiltShaders = false;
  std::chrono::steady_clock::time_point UpdateStart;
  std::string ReportedProblems;

  int ShaderCompileCount = 0;
  int CulledLights = 0;
  double ErrorBound = 0.0;
  int BudgetMode = 0;
  int SquaredShininess = 0;
  double LastShaderBuildTime = 0.0;
  std::string LastSignature;
  std::string LastVertexSource;
  std::string LastFragmentSource;
  std::string LastGeometrySource;

  // Whether a normals array holds unusable vectors, by array and modification time.
  struct NormalsScan
  {
    vtkMTimeType Time = 0;
    bool Unusable = false;
  };
  std::map<vtkDataArray*, NormalsScan> NormalsScans;
};

//------------------------------------------------------------------------------
vtkPhongMapperCore::vtkPhongMapperCore()
  : Internal(new Internals)
{
  Internals& internal = *this->Internal;
  internal.PlaceholderDirectional->SetIntensity(0.0);
  internal.PlaceholderPoint->SetIntensity(0.0);
  internal.PlaceholderPoint->PositionalOn();
  internal.PlaceholderPoint->SetConeAngle(180.0);
  internal.PlaceholderSpot->SetIntensity(0.0);
  internal.PlaceholderSpot->PositionalOn();
  internal.PlaceholderSpot->SetConeAngle(45.0);
  internal.PlaceholderSpot->SetExponent(2.0);
  internal.PlaceholderSpot->SetAttenuationValues(1.0, 0.1, 0.1);
  internal.PlaceholderPoint->SetAttenuationValues(1.0, 0.1, 0.1);
  internal.PlaceholderPoint->SetAmbientColor(1.0, 1.0, 1.0);
}

//------------------------------------------------------------------------------
vtkPhongMapperCore::~vtkPhongMapperCore() = default;

//------------------------------------------------------------------------------
bool vtkPhongMapperCore::PlanPrimitive(const vtkOpenGLHelper& cellBO, vtkRenderer* ren,
  vtkActor* act, const vtkPhongPrimitiveState& state)
{
  Internals& internal = *this->Internal;
  vtkPhongShaderPlanner::PlaceholderLights placeholders;
  placeholders.Directional = internal.PlaceholderDirectional;
  placeholders.Point = internal.PlaceholderPoint;
  placeholders.Spot = internal.PlaceholderSpot;
  vtkPhongShaderPlan plan =
    vtkPhongShaderPlanner(placeholders, internal.Log).MakePlan(ren, act, state, this->Options);
  this->TakeSteadyConstants(cellBO, ren, state, plan);
  if (plan.Handled && this->Internal->FailedSignatures.count(plan.Signature))
  {
    plan = vtkPhongShaderPlan();
  }
  this->Internal->CulledLights = plan.CulledLights;
  this->Internal->ErrorBound = plan.ErrorBound;
  this->Internal->BudgetMode = plan.BudgetMode;
  this->Internal->SquaredShininess = plan.WholeShininess;
  auto& current = this->Internal->Plans[&cellBO];
  const bool changed = current.Signature != plan.Signature;
  current = std::move(plan);
  // A program released by the limit on compiled programs (this core's or another's, for
  // identical sources) is rebuilt through VTK's full path, which also rebinds the vertex
  // attributes to the new link; compiled behind VTK's back it would draw with stale ones.
  const bool released = cellBO.Program && !cellBO.Program->GetCompiled();
  return changed || released;
}

//------------------------------------------------------------------------------
// Under an error budget, the light and material values go into the fragment shader as constants
// once they came back unchanged in Required plans in a row (a still camera, or camera lights
// whatever the camera does): a program of their own, compiled once, and kept while they stay. Each
// new set of values taken doubles Required (up to 64), and every 4 * Required plans that use the
// constants halve it again (down to 1): lights that keep changing and resting (scene lights as
// the camera turns and stops, an animation's steps) compile a program where the last ones
// served several times the repeats they waited for, soon stop where they did not, and draw
// with the uniforms' program meanwhile. A program with constants that failed to compile is
// not taken again.
void vtkPhongMapperCore::TakeSteadyConstants(const vtkOpenGLHelper& cellBO, vtkRenderer* ren,
  const vtkPhongPrimitiveState& state, vtkPhongShaderPlan& plan)
{
  Internals& internal = *this->Internal;
  if (!vtkPhongShaderPlanner::MayTakeConstants(plan, this->Options))
  {
    return; // (the depth pre-pass plans the same primitive: its count goes on)
  }
  vtkPhongUniformValues values = this->ConstantCandidates(ren, state, plan);
  Internals::SteadyValues& steady = internal.Steady[&cellBO];
  if (values == steady.Values)
  {
    ++steady.Repeats;
  }
  else
  {
    steady.Values = values;
    steady.Repeats = 0;
  }
  if (values != steady.Taken)
  {
    if (steady.Repeats < steady.Required)
    {
      return;
    }
    steady.Taken = values;
    steady.Required = std::min(2 * steady.Required, 64);
    steady.TakenPlans = 0;
  }
  else if (++steady.TakenPlans >= 4 * steady.Required)
  {
    steady.Required = std::max(steady.Required / 2, 1);
    steady.TakenPlans = 0;
  }
  vtkPhongShaderPlan withConstants = plan;
  if (vtkPhongShaderPlanner::SetConstants(std::move(values), this->Options, withConstants) &&
    !internal.FailedSignatures.count(withConstants.Signature))
  {
    plan = std::move(withConstants);
  }
}

//------------------------------------------------------------------------------
// The values that may become constants. The lights' make a program that every actor of the
// same structure shares; the material's make one of the actor's own. Those are taken only in
// renderers drawing at most MaterialConstantsActors visible actors: each program costs a compile
// and llvmpipe's JIT (about 60 ms), and 50 actors of 50 colours stalled their second frame 3 s
// where one program served them all. VTK's own material uniforms are left out where VTK sets
// them again per block (the composite mapper's block colours and opacities).
vtkPhongUniformValues vtkPhongMapperCore::ConstantCandidates(
  vtkRenderer* ren, const vtkPhongPrimitiveState& state, const vtkPhongShaderPlan& plan)
{
  Internals& internal = *this->Internal;
  using Source = vtkPhongUniformValue::Source;
  vtkPhongUniformValues values = vtkPhongLightUniforms(nullptr, ren, plan, internal.Log).Values();
  const vtkPhongUniformValues material =
    vtkPhongMaterialUniforms(nullptr, plan, internal.Log).Values();
  values.insert(values.end(), material.begin(), material.end());
  const bool ownProgram = FewVisibleActors(ren);
  values.erase(std::remove_if(values.begin(), values.end(),
                 [&](const vtkPhongUniformValue& value)
                 {
                   return (value.From != Source::Light && !ownProgram) ||
                     (value.From == Source::StockMaterial && state.MaterialPerBlock);
                 }),
    values.end());
  return values;
}

//------------------------------------------------------------------------------
// Whether the renderer draws at most MaterialConstantsActors visible actors (the count stops at
// one more: a busy renderer costs a few steps per primitive, not one per actor).
bool vtkPhongMapperCore::FewVisibleActors(vtkRenderer* ren)
{
  vtkActorCollection* actors = ren->GetActors();
  vtkCollectionSimpleIterator it;
  int visible = 0;
  actors->InitTraversal(it);
  for (vtkActor* actor = actors->GetNextActor(it); actor && visible <= MaterialConstantsActors;
       actor = actors->GetNextActor(it))
  {
    visible += actor->GetVisibility() ? 1 : 0;
  }
  return visible <= MaterialConstantsActors;
}

//------------------------------------------------------------------------------
void vtkPhongMapperCore::BoundsInWorld(
  const std::vector<vtkPolyData*>& blocks, vtkActor* act, double boundsWC[6])
{
  vtkBoundingBox boxMC;
  for (vtkPolyData* block : blocks)
  {
    boxMC.AddBounds(block->GetBounds());
  }
  double boundsMC[6];
  boxMC.GetBounds(boundsMC);
  if (!vtkPhongLightCulling::TransformBox(boundsMC, act->GetMatrix(), boundsWC))
  {
    vtkMath::UninitializeBounds(boundsWC);
  }
}

//------------------------------------------------------------------------------
bool vtkPhongMapperCore::Handles(const vtkOpenGLHelper* cellBO) const
{
  auto found = this->Internal->Plans.find(cellBO);
  return found != this->Internal->Plans.end() && found->second.Handled;
}

//------------------------------------------------------------------------------
void vtkPhongMapperCore::BeginUpdateShaders()
{
  this->Internal->BuiltShaders = false;
  this->Internal->UpdateStart = std::chrono::steady_clock::now();
}

//------------------------------------------------------------------------------
void vtkPhongMapperCore::ShadersBuilt(
  std::map<vtkShader::Type, vtkShader*>& shaders, vtkOpenGLHelper* cellBO)
{
  // EndUpdateShaders recognizes a failed build by the null program it leaves.
  vtkPhongCompatibility::ForgetProgramBeforeBuild(*cellBO);
  this->Internal->BuiltShaders = true;
  this->Internal->LastVertexSource = shaders[vtkShader::Vertex]->GetSource();
  this->Internal->LastGeometrySource = shaders[vtkShader::Geometry]->GetSource();
  this->Internal->LastFragmentSource = shaders[vtkShader::Fragment]->GetSource();
  this->Internal->LastSignature = this->Internal->Plans[cellBO].Signature;
}

//------------------------------------------------------------------------------
void vtkPhongMapperCore::FinishBuild(std::map<vtkShader::Type, vtkShader*>& shaders,
  vtkOpenGLHelper* cellBO, vtkRenderer* ren, vtkActor* act, vtkObject* reporter,
  const std::function<void()>& buildStock, const std::function<void()>& buildBare)
{
  if (this->Handles(cellBO))
  {
    KeepUserLightOutput(shaders[vtkShader::Fragment], act);
  }
  if (!Compiles(shaders, ren))
  {
    if (this->Handles(cellBO))
    {
      this->FallBackToVTK(cellBO, reporter);
      buildStock();
    }
    if (!Compiles(shaders, ren))
    {
      vtkErrorWithObjectMacro(reporter,
        "The actor's shader code or replacements (vtkShaderProperty) fail to compile with "
        "VTK's own lighting too; the primitive is drawn with VTK's shaders, without them.");
      buildBare();
    }
  }
  this->ShadersBuilt(shaders, cellBO);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkActor> vtkPhongMapperCore::TemplateActor(vtkActor* act)
{
  auto standIn = vtkSmartPointer<vtkActor>::New();
  standIn->SetProperty(act->GetProperty());
  standIn->SetBackfaceProperty(act->GetBackfaceProperty());
  standIn->SetTexture(act->GetTexture());
  standIn->SetPropertyKeys(act->GetPropertyKeys());
  return standIn;
}

//------------------------------------------------------------------------------
// Compile the sources through the window's shader cache, which keeps the program for VTK's
// own request right after. The cache rewrites the sources it is given (version line, outputs):
// it gets copies, so that VTK's request hashes the very same text.
bool vtkPhongMapperCore::Compiles(std::map<vtkShader::Type, vtkShader*>& shaders, vtkRenderer* ren)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!window)
  {
    return true; // nothing to compile with: VTK will say so
  }
  vtkNew<vtkShader> vertex, geometry, fragment;
  vertex->SetType(vtkShader::Vertex);
  vertex->SetSource(shaders[vtkShader::Vertex]->GetSource());
  geometry->SetType(vtkShader::Geometry);
  geometry->SetSource(shaders[vtkShader::Geometry]->GetSource());
  fragment->SetType(vtkShader::Fragment);
  fragment->SetSource(shaders[vtkShader::Fragment]->GetSource());
  std::map<vtkShader::Type, vtkShader*> copies{ { vtkShader::Vertex, vertex },
    { vtkShader::Geometry, geometry }, { vtkShader::Fragment, fragment } };
  return window->GetShaderCache()->ReadyShaderProgram(copies) != nullptr;
}

//------------------------------------------------------------------------------
// A vtkPhong variant that failed to compile: remember it (its next plans are VTK's) and
// draw this primitive with VTK's lighting from now on.
void vtkPhongMapperCore::FallBackToVTK(const vtkOpenGLHelper* cellBO, vtkObject* reporter)
{
  // vtkShaderProgram has already printed the numbered source and the log.
  const std::string signature = this->Internal->Plans[cellBO].Signature;
  this->Internal->FailedSignatures.insert(signature);
  this->Internal->Plans[cellBO] = vtkPhongShaderPlan();
  vtkErrorWithObjectMacro(reporter,
    "The lighting shader variant ["
      << signature
      << "] failed to compile or link (the shader program's errors give the numbered "
         "source and the compiler log); this primitive falls back to VTK's own lighting.");
}

//------------------------------------------------------------------------------
// A user replacement of //VTK::Light::Impl that writes the colour itself (VTK's cube-map
// examples: ambientColor + diffuse + specular + reflection) takes the place of the lighting,
// as it does in stock VTK: what vtkPhong adds after the texture (specular, emission, debug
// views) would count the highlight twice, and is left out.
void vtkPhongMapperCore::KeepUserLightOutput(vtkShader* fragment, vtkActor* act)
{
  if (!UserWritesLightOutput(act))
  {
    return;
  }
  std::string source = fragment->GetSource();
  const std::string postBegin = "  // vtkPhong after the texture (";
  const std::string postEnd = "  // vtkPhong after the texture: end\n";
  const std::size_t begin = source.find(postBegin);
  const std::size_t end = source.find(postEnd);
  if (begin != std::string::npos && end != std::string::npos && begin < end)
  {
    source.erase(begin, end + postEnd.size() - begin);
    fragment->SetSource(source);
  }
}

//------------------------------------------------------------------------------
bool vtkPhongMapperCore::UserWritesLightOutput(vtkActor* act)
{
  auto* property = vtkOpenGLShaderProperty::SafeDownCast(act->GetShaderProperty());
  if (!property)
  {
    return false;
  }
  for (const auto& replacement : property->GetAllShaderReplacements())
  {
    if (replacement.first.ShaderType == vtkShader::Fragment &&
      replacement.first.OriginalValue == "//VTK::Light::Impl" &&
      replacement.second.Replacement.find("gl_FragData[0]") != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkPhongMapperCore::EndUpdateShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkObject* reporter)
{
  Internals& internal = *this->Internal;
  const bool built = internal.BuiltShaders;
  const bool failed = built && this->CheckNewProgram(cellBO, reporter);
  const vtkPhongShaderPlan& plan = internal.Plans[&cellBO];
  if (!failed && plan.Handled && !plan.DepthOnly) // the pre-pass's one program is not counted
  {
    this->UseProgram(cellBO.Program, ren);
  }
  return failed;
}

//------------------------------------------------------------------------------
// Move the program to the front of the recently used list; release the programs beyond
// MaximumNumberOfPrograms from its back.
void vtkPhongMapperCore::UseProgram(vtkShaderProgram* program, vtkRenderer* ren)
{
  Internals& internal = *this->Internal;
  if (!program)
  {
    return;
  }
  auto& recent = internal.RecentPrograms;
  auto found = std::find_if(recent.begin(), recent.end(),
    [program](const Internals::UsedProgram& used) { return used.Program == program; });
  if (found != recent.end())
  {
    recent.splice(recent.begin(), recent, found);
    return;
  }
  if (internal.Released.erase(program))
  {
    ++internal.ShaderCompileCount; // a released program compiled again
  }
  recent.push_front({ program, ren->GetRenderWindow() });
  bool released = false;
  while (this->MaximumNumberOfPrograms > 0 &&
    static_cast<int>(recent.size()) > this->MaximumNumberOfPrograms)
  {
    Internals::UsedProgram& oldest = recent.back();
    if (oldest.Program && oldest.Window)
    {
      oldest.Program->ReleaseGraphicsResources(oldest.Window);
      internal.Released.insert(oldest.Program);
      ++internal.ReleasedPrograms;
      released = true;
    }
    recent.pop_back();
  }
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (released && window)
  {
    // vtkShaderProgram::ReleaseGraphicsResources unbinds whatever program is current
    // (glUseProgram(0)) while the shader cache still believes the primitive's program is
    // bound: bind it again, or the primitive draws nothing.
    window->GetShaderCache()->ClearLastShaderBound();
    window->GetShaderCache()->ReadyShaderProgram(program);
  }
}

//------------------------------------------------------------------------------
std::size_t vtkPhongMapperCore::HashSources(
  const std::string& vertex, const std::string& geometry, const std::string& fragment)
{
  return std::hash<std::string>{}(vertex + '\n' + geometry + '\n' + fragment);
}

//------------------------------------------------------------------------------
// After VTK built the shaders: count a new variant, and report a program that failed to
// compile (true: the mapper draws the primitive again with VTK's lighting).
bool vtkPhongMapperCore::CheckNewProgram(vtkOpenGLHelper& cellBO, vtkObject* reporter)
{
  Internals& internal = *this->Internal;
  const std::chrono::duration<double> elapsed =
    std::chrono::steady_clock::now() - internal.UpdateStart;

  // The depth pre-pass's program (once per mapper) is neither a lighting variant nor counted
  // as a build: the statistics follow the lighting.
  const vtkPhongShaderPlan& plan = internal.Plans[&cellBO];
  if (plan.Handled && !plan.DepthOnly)
  {
    internal.Signatures.insert(plan.Signature);
  }
  const std::size_t sourceHash = HashSources(
    internal.LastVertexSource, internal.LastGeometrySource, internal.LastFragmentSource);
  if (internal.KnownSources.insert(sourceHash).second && !plan.DepthOnly)
  {
    ++internal.ShaderCompileCount;
    internal.LastShaderBuildTime = elapsed.count();
  }

  if (!cellBO.Program && plan.Handled)
  {
    // vtkShaderProgram has already printed the numbered source and the log.
    const std::string signature = plan.Signature;
    internal.FailedSignatures.insert(signature);
    vtkErrorWithObjectMacro(reporter,
      "The lighting shader variant ["
        << signature
        << "] failed to compile or link (the shader program's errors give the numbered "
           "source and the compiler log); this primitive falls back to VTK's own lighting.");
    return true;
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkPhongMapperCore::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*>& shaders, const vtkOpenGLHelper* cellBO)
{
  vtkPhongShaderTemplate(this).Substitute(shaders, this->Internal->Plans[cellBO]);
}

//------------------------------------------------------------------------------
void vtkPhongMapperCore::SetLightUniforms(vtkOpenGLHelper& cellBO, vtkRenderer* ren)
{
  const vtkPhongShaderPlan& plan = this->Internal->Plans[&cellBO];
  vtkPhongLightUniforms(cellBO.Program, ren, plan, this->Internal->Log).Upload();
  vtkPhongShadowMaps::UploadLightIndices(cellBO.Program, ren, plan);
}

//------------------------------------------------------------------------------
void vtkPhongMapperCore::SetMaterialUniforms(vtkOpenGLHelper& cellBO)
{
  vtkPhongMaterialUniforms(cellBO.Program, this->Internal->Plans[&cellBO], this->Internal->Log)
    .Upload();
}

//------------------------------------------------------------------------------
void vtkPhongMapperCore::ReportProblems(vtkObject* reporter)
{
  const std::string problems = this->Internal->Log.Take();
  if (problems != this->Internal->ReportedProblems)
  {
    if (!problems.empty())
    {
      vtkErrorWithObjectMacro(reporter,
        "Bad lighting parameters (rendered with the documented substitutes):\n"
          << problems);
    }
    this->Internal->ReportedProblems = problems;
  }
}

//------------------------------------------------------------------------------
bool vtkPhongMapperCore::HasUnusableVectors(vtkDataArray* normals)
{
  if (!normals)
  {
    return false;
  }
  auto found = this->Internal->NormalsScans.find(normals);
  if (found != this->Internal->NormalsScans.end() && found->second.Time == normals->GetMTime())
  {
    return found->second.Unusable;
  }
  if (this->Internal->NormalsScans.size() > 1024)
  {
    this->Internal->NormalsScans.clear(); // arrays come and go: keep the cache small
  }
  Internals::NormalsScan& scan = this->Internal->NormalsScans[normals];
  scan.Time = normals->GetMTime();
  scan.Unusable = false;
  // The shader normalizes in float: a squared length that underflows or overflows a float
  // (with room for the actor's scale, which the normal matrix applies first) has no usable
  // direction there, however valid in double.
  auto unusable = [](double x, double y, double z)
  {
    const double lengthSquared = x * x + y * y + z * z;
    return !(lengthSquared >= 1.0e-30 && lengthSquared <= 1.0e30);
  };
  const vtkIdType count = normals->GetNumberOfTuples();
  if (auto* floats = vtkFloatArray::SafeDownCast(normals))
  {
    const float* v = floats->GetPointer(0);
    for (vtkIdType i = 0; i < count && !scan.Unusable; ++i, v += 3)
    {
      scan.Unusable = unusable(v[0], v[1], v[2]);
    }
  }
  else
  {
    double v[3];
    for (vtkIdType i = 0; i < count && !scan.Unusable; ++i)
    {
      normals->GetTuple(i, v);
      scan.Unusable = unusable(v[0], v[1], v[2]);
    }
  }
  return scan.Unusable;
}

//------------------------------------------------------------------------------
void vtkPhongMapperCore::ReleaseGraphicsResources()
{
  // Programs live in the window's shader cache; a new context compiles again.
  this->Internal->KnownSources.clear();
  this->Internal->Plans.clear();
  this->Internal->Steady.clear();
  this->Internal->RecentPrograms.clear();
  this->Internal->Released.clear();
}

//------------------------------------------------------------------------------
int vtkPhongMapperCore::GetNumberOfReleasedPrograms() const
{
  return this->Internal->ReleasedPrograms;
}

//------------------------------------------------------------------------------
int vtkPhongMapperCore::GetNumberOfCompiledPrograms() const
{
  return static_cast<int>(
    std::count_if(this->Internal->RecentPrograms.begin(), this->Internal->RecentPrograms.end(),
      [](const Internals::UsedProgram& used)
      { return used.Program && used.Program->GetCompiled(); }));
}

//------------------------------------------------------------------------------
int vtkPhongMapperCore::GetShaderCompileCount() const
{
  return this->Internal->ShaderCompileCount;
}

//------------------------------------------------------------------------------
int vtkPhongMapperCore::GetNumberOfShaderVariants() const
{
  return static_cast<int>(this->Internal->Signatures.size());
}

//------------------------------------------------------------------------------
double vtkPhongMapperCore::GetLastShaderBuildTime() const
{
  return this->Internal->LastShaderBuildTime;
}

//------------------------------------------------------------------------------
int vtkPhongMapperCore::GetNumberOfCulledLights() const
{
  return this->Internal->CulledLights;
}

//------------------------------------------------------------------------------
double vtkPhongMapperCore::GetErrorBound() const
{
  return this->Internal->ErrorBound * 255.0;
}

//------------------------------------------------------------------------------
int vtkPhongMapperCore::GetBudgetMode() const
{
  return this->Internal->BudgetMode;
}

//------------------------------------------------------------------------------
int vtkPhongMapperCore::GetSquaredShininess() const
{
  return this->Internal->SquaredShininess;
}

//------------------------------------------------------------------------------
const std::string& vtkPhongMapperCore::GetLastShaderSignature() const
{
  return this->Internal->LastSignature;
}

//------------------------------------------------------------------------------
const std::string& vtkPhongMapperCore::GetLastVertexShaderSource() const
{
  return this->Internal->LastVertexSource;
}

//------------------------------------------------------------------------------
const std::string& vtkPhongMapperCore::GetLastFragmentShaderSource() const
{
  return this->Internal->LastFragmentSource;
}

//------------------------------------------------------------------------------
const std::string& vtkPhongMapperCore::GetLastGeometryShaderSource() const
{
  return this->Internal->LastGeometrySource;
}

//------------------------------------------------------------------------------
void vtkPhongMapperCore::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DebugView: " << this->Options.DebugView << "\n";
  os << indent << "DebugLightIndex: " << this->Options.DebugLightIndex << "\n";
  os << indent << "Specialize: " << (this->Options.Specialize ? "On" : "Off") << "\n";
  os << indent << "ShaderCompileCount: " << this->GetShaderCompileCount() << "\n";
  os << indent << "NumberOfShaderVariants: " << this->GetNumberOfShaderVariants() << "\n";
  os << indent << "LastShaderBuildTime: " << this->GetLastShaderBuildTime() << "\n";
  os << indent << "LastShaderSignature: " << this->GetLastShaderSignature() << "\n";
  os << indent << "NumberOfCulledLights: " << this->GetNumberOfCulledLights() << "\n";
  os << indent << "ErrorBound: " << this->GetErrorBound() << "\n";
  os << indent
     << "BudgetMode: " << vtkPhongLightingSettings::GetBudgetModeAsString(this->GetBudgetMode())
     << "\n";
  os << indent << "SquaredShininess: " << this->GetSquaredShininess() << "\n";
  os << indent << "Primitives planned: " << this->Internal->Plans.size() << "\n";
  os << indent << "Failed variants: " << this->Internal->FailedSignatures.size() << "\n";
  os << indent << "MaximumNumberOfPrograms: " << this->MaximumNumberOfPrograms << "\n";
  os << indent << "Programs in use: " << this->Internal->RecentPrograms.size() << "\n";
  os << indent << "Released programs: " << this->Internal->ReleasedPrograms << "\n";
}
