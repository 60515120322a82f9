#include "vtkPhongPolyDataMapper.h"

#include "vtkActor.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPhongShaderBuilder.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkShaderProgram.h"
#include "vtkShaderProperty.h"

#include <chrono>
#include <cmath>
#include <functional>
#include <set>

vtkStandardNewMacro(vtkPhongPolyDataMapper);

struct vtkPhongPolyDataMapper::Internals
{
  vtkNew<vtkPhongShaderBuilder> Builder;
  vtkNew<vtkOpenMeshNormals> Normals;
  // The mapper named vtkOriginalPointIds for picking itself (and may unname it).
  bool NamedPointIds = false;
  // The plan of each primitive (points, lines, polygons, strips), made afresh
  // every frame by GetNeedToRebuildShaders and used until the next one.
  std::map<const vtkOpenGLHelper*, vtkPhongShaderBuilder::Plan> Plans;
  std::set<std::string> Signatures;
  // Variants whose shader failed to compile: drawn with VTK's lighting instead.
  std::set<std::string> FailedSignatures;
  // Hashes of the shader sources handed to the render window's shader cache.
  std::set<std::size_t> KnownSources;
  bool BuiltShaders = false;
  std::string ReportedProblems;

  // Whether a normals array holds unusable (zero, NaN, infinite) vectors,
  // cached by the array and its modification time: a scan per change.
  struct NormalsScan
  {
    vtkDataArray* Array = nullptr;
    vtkMTimeType Time = 0;
    bool Unusable = false;
  };
  NormalsScan PointNormals;
  NormalsScan CellNormals;
  bool HasUnusableVectors(vtkDataArray* normals, NormalsScan& cache);
};

//------------------------------------------------------------------------------
bool vtkPhongPolyDataMapper::Internals::HasUnusableVectors(
  vtkDataArray* normals, NormalsScan& cache)
{
  if (!normals)
  {
    return false;
  }
  if (cache.Array == normals && cache.Time == normals->GetMTime())
  {
    return cache.Unusable;
  }
  cache.Array = normals;
  cache.Time = normals->GetMTime();
  cache.Unusable = false;
  auto unusable = [](double x, double y, double z)
  {
    const double lengthSquared = x * x + y * y + z * z;
    return !(lengthSquared > 0.0) || !std::isfinite(lengthSquared);
  };
  const vtkIdType count = normals->GetNumberOfTuples();
  if (auto* floats = vtkFloatArray::SafeDownCast(normals))
  {
    const float* v = floats->GetPointer(0);
    for (vtkIdType i = 0; i < count && !cache.Unusable; ++i, v += 3)
    {
      cache.Unusable = unusable(v[0], v[1], v[2]);
    }
  }
  else
  {
    double v[3];
    for (vtkIdType i = 0; i < count && !cache.Unusable; ++i)
    {
      normals->GetTuple(i, v);
      cache.Unusable = unusable(v[0], v[1], v[2]);
    }
  }
  return cache.Unusable;
}

//------------------------------------------------------------------------------
vtkPhongPolyDataMapper::vtkPhongPolyDataMapper()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkPhongPolyDataMapper::~vtkPhongPolyDataMapper() = default;

//------------------------------------------------------------------------------
const char* vtkPhongPolyDataMapper::GetDebugViewAsString()
{
  switch (this->DebugView)
  {
    case AmbientTerm:
      return "AmbientTerm";
    case DiffuseTerm:
      return "DiffuseTerm";
    case SpecularTerm:
      return "SpecularTerm";
    case EmissionTerm:
      return "EmissionTerm";
    case ShadingNormal:
      return "ShadingNormal";
    case SingleLight:
      return "SingleLight";
    case PositionVC:
      return "PositionVC";
    case NormalVC:
      return "NormalVC";
    case Final:
    default:
      return "Final";
  }
}

//------------------------------------------------------------------------------
int vtkPhongPolyDataMapper::GetNumberOfShaderVariants()
{
  return static_cast<int>(this->Internal->Signatures.size());
}

//------------------------------------------------------------------------------
bool vtkPhongPolyDataMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // The stock test first: it also refreshes this primitive's light complexity.
  bool rebuild = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);

  vtkPhongShaderBuilder::PrimitiveState state;
  state.LightComplexity = this->PrimitiveInfo[&cellBO].LastLightComplexity;
  state.IsTriangles =
    cellBO.PrimitiveType == PrimitiveTris || cellBO.PrimitiveType == PrimitiveTriStrips;
  state.HasPointNormals = this->VBOs->GetNumberOfComponents("normalMC") == 3;
  state.HasCellNormals = this->HaveCellNormals;
  if (state.HasPointNormals)
  {
    state.NormalsMayBeInvalid = this->Internal->HasUnusableVectors(
      this->CurrentInput->GetPointData()->GetNormals(), this->Internal->PointNormals);
  }
  else if (state.HasCellNormals)
  {
    state.NormalsMayBeInvalid = this->Internal->HasUnusableVectors(
      this->CurrentInput->GetCellData()->GetNormals(), this->Internal->CellNormals);
  }
  state.NormalsFromShape = this->DrawingTubesOrSpheres(cellBO, act);
  state.HasGeometryShader = this->DrawingEdges(ren, act) || this->HaveWideLines(ren, act) ||
    act->GetShaderProperty()->HasGeometryShaderCode();
  state.DrawingVertices = this->DrawingVertices;
  state.DrawingSelection = this->DrawingSelection;

  vtkPhongShaderBuilder::Options options;
  options.DebugView = this->DebugView;
  options.DebugLightIndex = this->DebugLightIndex;
  options.Specialize = this->ShaderSpecialization;

  vtkPhongShaderBuilder::Plan plan = this->Internal->Builder->MakePlan(ren, act, state, options);
  if (plan.Handled && this->Internal->FailedSignatures.count(plan.Signature))
  {
    plan = vtkPhongShaderBuilder::Plan();
  }
  auto& current = this->Internal->Plans[&cellBO];
  if (current.Signature != plan.Signature)
  {
    rebuild = true;
  }
  current = std::move(plan);
  return rebuild;
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::BuildShaders(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::BuildShaders(shaders, ren, act);
  this->Internal->BuiltShaders = true;
  this->LastVertexSource = shaders[vtkShader::Vertex]->GetSource();
  this->LastGeometrySource = shaders[vtkShader::Geometry]->GetSource();
  this->LastFragmentSource = shaders[vtkShader::Fragment]->GetSource();
  this->LastSignature = this->Internal->Plans[this->LastBoundBO].Signature;
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::UpdateShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Internal->BuiltShaders = false;
  const auto start = std::chrono::steady_clock::now();
  this->Superclass::UpdateShaders(cellBO, ren, act);
  if (!this->Internal->BuiltShaders)
  {
    return;
  }
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;

  const vtkPhongShaderBuilder::Plan& plan = this->Internal->Plans[&cellBO];
  if (plan.Handled)
  {
    this->Internal->Signatures.insert(plan.Signature);
  }
  const std::size_t sourceHash = std::hash<std::string>{}(
    this->LastVertexSource + '\n' + this->LastGeometrySource + '\n' + this->LastFragmentSource);
  if (this->Internal->KnownSources.insert(sourceHash).second)
  {
    ++this->ShaderCompileCount;
    this->LastShaderBuildTime = elapsed.count();
  }

  if (!cellBO.Program && plan.Handled)
  {
    // vtkShaderProgram has already printed the numbered source and the log.
    const std::string signature = plan.Signature;
    this->Internal->FailedSignatures.insert(signature);
    vtkErrorMacro("The lighting shader variant [" << signature
                                                  << "] failed to compile or link (the shader "
                                                     "program's errors give the numbered source "
                                                     "and the compiler log); this primitive falls "
                                                     "back to VTK's own lighting.");
    this->Superclass::UpdateShaders(cellBO, ren, act);
  }
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  auto found = this->Internal->Plans.find(this->LastBoundBO);
  if (found == this->Internal->Plans.end() || !found->second.Handled)
  {
    this->Superclass::ReplaceShaderLight(shaders, ren, act);
    return;
  }
  this->Internal->Builder->ReplaceShaderValues(shaders, found->second);
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::SetLightingShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  auto found = this->Internal->Plans.find(&cellBO);
  if (found == this->Internal->Plans.end() || !found->second.Handled)
  {
    this->Superclass::SetLightingShaderParameters(cellBO, ren, act);
    return;
  }
  this->Internal->Builder->SetLightUniforms(cellBO.Program, ren, found->second);
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::SetPropertyShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetPropertyShaderParameters(cellBO, ren, act);
  auto found = this->Internal->Plans.find(&cellBO);
  if (found != this->Internal->Plans.end() && found->second.Handled)
  {
    this->Internal->Builder->SetMaterialUniforms(cellBO.Program, found->second);
  }
}

//------------------------------------------------------------------------------
vtkOpenMeshNormals* vtkPhongPolyDataMapper::GetNormalsGenerator()
{
  return this->Internal->Normals;
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act)
{
  // Input without normals, shaded smoothly: draw the normals filter's output
  // instead. The filter re-executes only when its input or settings change.
  vtkPolyData* input = this->CurrentInput;
  this->UsedGeneratedNormals = this->ComputeMissingNormals && input &&
    (input->GetNumberOfPolys() > 0 || input->GetNumberOfStrips() > 0) &&
    !input->GetPointData()->GetNormals() && !input->GetCellData()->GetNormals() &&
    act->GetProperty()->GetInterpolation() != VTK_FLAT;
  if (this->UsedGeneratedNormals)
  {
    vtkOpenMeshNormals* normals = this->Internal->Normals;
    if (normals->GetInput() != input)
    {
      normals->SetInputData(input);
    }
    normals->SetWeighting(this->NormalsWeighting);
    normals->SetFeatureAngle(this->NormalsFeatureAngle);
    normals->SetSplitting(this->NormalsSplitting);
    normals->Update();
    this->CurrentInput = normals->GetOutput();
    // Split points get new ids; picking should still report the input's.
    if (this->NormalsSplitting && !this->PointIdArrayName)
    {
      this->SetPointIdArrayName(normals->GetOriginalPointIdsArrayName());
      this->Internal->NamedPointIds = true;
    }
  }
  else if (this->Internal->NamedPointIds)
  {
    this->SetPointIdArrayName(nullptr);
    this->Internal->NamedPointIds = false;
  }
  this->Superclass::RenderPieceStart(ren, act);
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::RenderPieceFinish(ren, act);
  // Report parameter problems once, not every frame: only when they change.
  const std::string problems = this->Internal->Builder->TakeProblems();
  if (problems != this->Internal->ReportedProblems)
  {
    if (!problems.empty())
    {
      vtkErrorMacro("Bad lighting parameters (rendered with the documented substitutes):\n"
        << problems);
    }
    this->Internal->ReportedProblems = problems;
  }
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  // Programs live in the window's shader cache; a new context compiles again.
  this->Internal->KnownSources.clear();
  this->Internal->Plans.clear();
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DebugView: " << this->GetDebugViewAsString() << "\n";
  os << indent << "DebugLightIndex: " << this->DebugLightIndex << "\n";
  os << indent << "ComputeMissingNormals: " << (this->ComputeMissingNormals ? "On" : "Off") << "\n";
  os << indent << "NormalsWeighting: " << this->NormalsWeighting << "\n";
  os << indent << "NormalsFeatureAngle: " << this->NormalsFeatureAngle << "\n";
  os << indent << "NormalsSplitting: " << (this->NormalsSplitting ? "On" : "Off") << "\n";
  os << indent << "UsedGeneratedNormals: " << (this->UsedGeneratedNormals ? "yes" : "no") << "\n";
  os << indent << "ShaderSpecialization: " << (this->ShaderSpecialization ? "On" : "Off") << "\n";
  os << indent << "ShaderCompileCount: " << this->ShaderCompileCount << "\n";
  os << indent << "NumberOfShaderVariants: " << this->GetNumberOfShaderVariants() << "\n";
  os << indent << "LastShaderBuildTime: " << this->LastShaderBuildTime << "\n";
  os << indent << "LastShaderSignature: " << this->LastSignature << "\n";
  os << indent << "LastVertexShaderSource: " << this->LastVertexSource.size() << " characters\n";
  os << indent << "LastFragmentShaderSource: " << this->LastFragmentSource.size()
     << " characters\n";
  os << indent << "LastGeometryShaderSource: " << this->LastGeometrySource.size()
     << " characters\n";
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::ShallowCopy(vtkAbstractMapper* mapper)
{
  if (auto* phong = vtkPhongPolyDataMapper::SafeDownCast(mapper))
  {
    this->SetDebugView(phong->GetDebugView());
    this->SetDebugLightIndex(phong->GetDebugLightIndex());
    this->SetComputeMissingNormals(phong->GetComputeMissingNormals());
    this->SetNormalsWeighting(phong->GetNormalsWeighting());
    this->SetNormalsFeatureAngle(phong->GetNormalsFeatureAngle());
    this->SetNormalsSplitting(phong->GetNormalsSplitting());
    this->SetShaderSpecialization(phong->GetShaderSpecialization());
  }
  this->Superclass::ShallowCopy(mapper);
}
