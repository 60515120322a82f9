#include "vtkPhongPolyDataMapper.h"

#include "vtkActor.h"
#include "vtkCellData.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderProperty.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPhongClampedSetter.h"
#include "vtkPhongClosedSurface.h"
#include "vtkPhongCompatibility.h"
#include "vtkPhongDepthPrePass.h"
#include "vtkPhongMapperCore.h"
#include "vtkPhongValidBlocks.h"
#include "vtkPhongVisibleClusters.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProperty.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

vtkStandardNewMacro(vtkPhongPolyDataMapper);

struct vtkPhongPolyDataMapper::Internals
{
  vtkNew<vtkPhongMapperCore> Core;
  vtkNew<vtkOpenMeshNormals> Normals;
  // The mapper named vtkOriginalPointIds for picking itself (and may unname it).
  bool NamedPointIds = false;
  // The input, or the copy drawn instead when cells name missing points.
  vtkPhongValidBlocks ValidInputs;
  // The input drawn before the normals filter replaced it (see StockNeedToRebuildShaders).
  vtkPolyData* InputWithoutNormals = nullptr;
  // The depth pass of the pre-pass is being drawn (its program computes no light).
  bool DrawingDepthOnly = false;
  vtkPhongDepthPrePass PrePass;
  // The triangles the depth pass draws: those seen in the last frame.
  vtkPhongVisibleClusters Clusters;
  // Whether the triangles are closed surfaces, whose back faces can be culled.
  vtkPhongClosedSurface ClosedSurface;
};

//------------------------------------------------------------------------------
vtkPhongPolyDataMapper::vtkPhongPolyDataMapper()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkPhongPolyDataMapper::~vtkPhongPolyDataMapper() = default;

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::SetLightCullingBound(double bound)
{
  vtkPhongSetClamped(this, "LightCullingBound", this->LightCullingBound, bound, 0.0, 1.0e9);
}

//------------------------------------------------------------------------------
int vtkPhongPolyDataMapper::GetNumberOfCulledLights()
{
  return this->Internal->Core->GetNumberOfCulledLights();
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::SetNormalsFeatureAngle(double angle)
{
  vtkPhongSetClamped(this, "NormalsFeatureAngle", this->NormalsFeatureAngle, angle, 0.0, 180.0);
}

//------------------------------------------------------------------------------
// Cells that name missing points would make VTK read out of bounds (bounds, buffer upload)
// and the normals filter too: such cells are collapsed in a copy (vtkPhongCellValidator),
// reported once per input change.
vtkPolyData* vtkPhongPolyDataMapper::GetValidInput(vtkPolyData* input)
{
  return this->Internal->ValidInputs.Get(input, this);
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::ComputeBounds()
{
  vtkPolyData* input = this->GetValidInput(this->GetInput());
  if (!input)
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return;
  }
  input->GetBounds(this->Bounds);
}

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
int vtkPhongPolyDataMapper::GetNumberOfCompiledShaderPrograms()
{
  return this->Internal->Core->GetNumberOfCompiledPrograms();
}

//------------------------------------------------------------------------------
int vtkPhongPolyDataMapper::GetNumberOfReleasedShaderPrograms()
{
  return this->Internal->Core->GetNumberOfReleasedPrograms();
}

//------------------------------------------------------------------------------
int vtkPhongPolyDataMapper::GetShaderCompileCount()
{
  return this->Internal->Core->GetShaderCompileCount();
}

//------------------------------------------------------------------------------
int vtkPhongPolyDataMapper::GetNumberOfShaderVariants()
{
  return this->Internal->Core->GetNumberOfShaderVariants();
}

//------------------------------------------------------------------------------
double vtkPhongPolyDataMapper::GetLastShaderBuildTime()
{
  return this->Internal->Core->GetLastShaderBuildTime();
}

//------------------------------------------------------------------------------
const char* vtkPhongPolyDataMapper::GetLastShaderSignature()
{
  return this->Internal->Core->GetLastShaderSignature().c_str();
}

//------------------------------------------------------------------------------
const char* vtkPhongPolyDataMapper::GetLastVertexShaderSource()
{
  return this->Internal->Core->GetLastVertexShaderSource().c_str();
}

//------------------------------------------------------------------------------
const char* vtkPhongPolyDataMapper::GetLastFragmentShaderSource()
{
  return this->Internal->Core->GetLastFragmentShaderSource().c_str();
}

//------------------------------------------------------------------------------
const char* vtkPhongPolyDataMapper::GetLastGeometryShaderSource()
{
  return this->Internal->Core->GetLastGeometryShaderSource().c_str();
}

//------------------------------------------------------------------------------
bool vtkPhongPolyDataMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // The stock test first: it also refreshes this primitive's light complexity.
  const bool rebuild = this->StockNeedToRebuildShaders(cellBO, ren, act);

  // What only the stock mapper's protected state tells (vtkPhongCompositeMapperHelper reads
  // the same for all its blocks).
  vtkPhongMapperCore* core = this->Internal->Core;
  vtkPhongShaderBuilder::PrimitiveState state;
  state.LightComplexity = this->PrimitiveInfo[&cellBO].LastLightComplexity;
  state.IsTriangles =
    cellBO.PrimitiveType == PrimitiveTris || cellBO.PrimitiveType == PrimitiveTriStrips;
  state.HasPointNormals = this->VBOs->GetNumberOfComponents("normalMC") == 3;
  state.HasCellNormals = this->HaveCellNormals;
  state.NormalsMayBeInvalid = state.HasPointNormals
    ? core->HasUnusableVectors(this->CurrentInput->GetPointData()->GetNormals())
    : state.HasCellNormals &&
      core->HasUnusableVectors(this->CurrentInput->GetCellData()->GetNormals());
  state.NormalsFromShape = this->DrawingTubesOrSpheres(cellBO, act);
  state.DrawingEdges = this->DrawingEdges(ren, act);
  state.HasGeometryShader = state.DrawingEdges || this->HaveWideLines(ren, act) ||
    act->GetShaderProperty()->HasGeometryShaderCode();
  state.DrawingVertices = this->DrawingVertices;
  state.DrawingSelection = this->DrawingSelection;
  state.HasUserShaderCode = vtkPhongClosedSurface::HasShaderCode(act, this->LegacyShaders());

  core->Options.DebugView = this->DebugView;
  core->Options.DebugLightIndex = this->DebugLightIndex;
  core->Options.Specialize = this->ShaderSpecialization;
  core->Options.InterpolatedDots = this->InterpolatedDotProducts;
  core->Options.LightCullingBound = this->LightCullingBound;
  core->Options.DepthOnly = this->Internal->DrawingDepthOnly;
  core->MaximumNumberOfPrograms = this->MaximumNumberOfShaderPrograms;
  return core->PlanPrimitive(cellBO, ren, act, state) || rebuild;
}

//------------------------------------------------------------------------------
// Stock VTK lights points and lines (and a surface drawn as points) only when the input has
// normals: those computed here for the polygons must not light them. The stock test, which
// decides the light complexity from the input's normals, sees the input as it was.
bool vtkPhongPolyDataMapper::StockNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  const bool surface = act->GetProperty()->GetRepresentation() != VTK_POINTS &&
    (cellBO.PrimitiveType == PrimitiveTris || cellBO.PrimitiveType == PrimitiveTriStrips);
  vtkPolyData* drawn = this->CurrentInput;
  if (this->UsedGeneratedNormals && !surface && this->Internal->InputWithoutNormals)
  {
    this->CurrentInput = this->Internal->InputWithoutNormals;
  }
  const bool rebuild = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);
  this->CurrentInput = drawn;
  return rebuild;
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::BuildShaders(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::BuildShaders(shaders, ren, act);
  this->Internal->Core->FinishBuild(
    shaders, this->LastBoundBO, ren, act, this,
    [&]() { this->Superclass::BuildShaders(shaders, ren, act); },
    [&]()
    {
      this->GetShaderTemplate(shaders, ren, vtkPhongMapperCore::TemplateActor(act));
      this->ReplaceShaderValues(shaders, ren, act);
    });
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::UpdateShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Internal->Core->BeginUpdateShaders();
  this->Superclass::UpdateShaders(cellBO, ren, act);
  if (this->Internal->Core->EndUpdateShaders(cellBO, ren, this))
  {
    this->Superclass::UpdateShaders(cellBO, ren, act); // now planned with VTK's lighting
  }
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  if (!this->Internal->Core->Handles(this->LastBoundBO))
  {
    this->Superclass::ReplaceShaderLight(shaders, ren, act);
    return;
  }
  this->Internal->Core->ReplaceShaderLight(shaders, this->LastBoundBO);
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::SetLightingShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  if (!this->Internal->Core->Handles(&cellBO))
  {
    this->Superclass::SetLightingShaderParameters(cellBO, ren, act);
    return;
  }
  this->Internal->Core->SetLightUniforms(cellBO, ren);
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::SetPropertyShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetPropertyShaderParameters(cellBO, ren, act);
  if (this->Internal->Core->Handles(&cellBO))
  {
    this->Internal->Core->SetMaterialUniforms(cellBO);
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
  vtkPolyData* input = this->GetValidInput(this->CurrentInput);
  this->CurrentInput = input;
  this->Internal->InputWithoutNormals = input;
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
// VTK's BuildBufferObjects maps the scalars of GetInput(), but draws CurrentInput: the
// normals' output, whose split points have ids past the input's, would read colours (and
// colour texture coordinates) past their end.
vtkUnsignedCharArray* vtkPhongPolyDataMapper::MapScalars(double alpha)
{
  int cellFlag = 0;
  return this->MapScalars(alpha, cellFlag);
}

//------------------------------------------------------------------------------
vtkUnsignedCharArray* vtkPhongPolyDataMapper::MapScalars(double alpha, int& cellFlag)
{
  vtkDataSet* drawn =
    this->UsedGeneratedNormals && this->CurrentInput ? this->CurrentInput : this->GetInput();
  return this->Superclass::MapScalars(drawn, alpha, cellFlag);
}

//------------------------------------------------------------------------------
// With the back faces culled when none can be seen (vtkPhongClosedSurface); both the depth
// pass and the lit draw then leave them out.
void vtkPhongPolyDataMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* act)
{
  const unsigned int hiddenFaces = this->HiddenFaces(ren, act);
  this->UsedClosedSurfaceCulling = hiddenFaces != 0;
  vtkPhongClosedSurface::ScopedCulling culling(ren, hiddenFaces);
  this->DrawSurfaces(ren, act);
}

//------------------------------------------------------------------------------
// The mapper's own shader replacements (VTK before 9.2), or nullptr.
vtkShaderProperty* vtkPhongPolyDataMapper::LegacyShaders() const
{
#if VTKPHONG_VTK_MAPPER_SHADER_REPLACEMENTS
  return this->LegacyShaderProperty;
#else
  return nullptr;
#endif
}

//------------------------------------------------------------------------------
// The faces to cull, or 0: nothing drawn may show a back face other than through the closed
// surfaces (a shader replacement, a clipping plane's cut, a texture's transparent texel, an
// edge over a silhouette could), then the surfaces and the view (vtkPhongClosedSurface).
unsigned int vtkPhongPolyDataMapper::HiddenFaces(vtkRenderer* ren, vtkActor* act)
{
  if (!this->ClosedSurfaceCulling || !this->CurrentInput ||
    !vtkPhongClosedSurface::DrawsOnlySurfaces(
      ren, act, this->Primitives, this->LegacyShaders(), this->GetNumberOfClippingPlanes()))
  {
    return 0;
  }
  vtkPhongClosedSurface& surface = this->Internal->ClosedSurface;
  surface.Update(
    this->Primitives[PrimitiveTris].IBO, this->CurrentInput, this->VBOBuildTime.GetMTime());
  return surface.HiddenFaces(ren, act, this->CurrentInput->GetBounds());
}

//------------------------------------------------------------------------------
// Plainly or with the depth pre-pass (vtkPhongDepthPrePass decides and draws), whose depth
// pass may leave out the triangles hidden in the last frame (vtkPhongVisibleClusters).
void vtkPhongPolyDataMapper::DrawSurfaces(vtkRenderer* ren, vtkActor* act)
{
  vtkPolyData* input = this->CurrentInput;
  const double triangles =
    input ? static_cast<double>(input->GetNumberOfPolys() + input->GetNumberOfStrips()) : 0.0;
  vtkPhongVisibleClusters& clusters = this->Internal->Clusters;
  const bool culling = this->CanCullDepthPass(ren, act);
  // Culled, the depth pass draws the seen clusters' triangles and nothing else (VTK's
  // triangulated polygons, where `triangles` counts cells).
  const double depthTriangles =
    culling && clusters.GetNumberOfTriangles() > 0 ? clusters.CollectVisibility() : triangles;
  this->DepthPassTriangles = 0.0;
  this->UsedDepthPrePass = this->Internal->PrePass.Draw(this->DepthPrePass, ren, act, this,
    triangles, depthTriangles, this->GetNumberOfCulledLights(),
    [&](bool depthOnly)
    {
      // VTK's draw advances the primitive id offset of cell colours and normals as it goes:
      // the lit draw must start where the depth pass did.
      const int primitiveIdOffset = this->PrimitiveIDOffset;
      this->Internal->DrawingDepthOnly = depthOnly;
      if (depthOnly)
      {
        const bool culled = culling &&
          clusters.Update(ren->GetRenderWindow(), this->Primitives[PrimitiveTris].IBO, input,
            this->VBOBuildTime.GetMTime());
        this->DrawDepthPass(ren, act, culled);
        this->DepthPassTriangles = culled ? clusters.GetNumberOfTrianglesDrawn() : triangles;
        this->PrimitiveIDOffset = primitiveIdOffset;
      }
      else
      {
        this->Superclass::RenderPieceDraw(ren, act);
      }
      this->Internal->DrawingDepthOnly = false;
    });
}

//------------------------------------------------------------------------------
// The depth pass is VTK's draw with the depth-only program; culled, the triangles are those
// of the clusters seen in the last frame, and a share of the hidden ones.
void vtkPhongPolyDataMapper::DrawDepthPass(vtkRenderer* ren, vtkActor* act, bool culled)
{
  if (!culled)
  {
    this->Superclass::RenderPieceDraw(ren, act);
    return;
  }
  this->DrawingVertices = false;
  this->DrawingSelection = false;
  this->UpdateShaders(this->Primitives[PrimitiveTris], ren, act);
  this->Internal->Clusters.Draw(ren, act);
}

//------------------------------------------------------------------------------
bool vtkPhongPolyDataMapper::CanCullDepthPass(vtkRenderer* ren, vtkActor* act)
{
  return this->DepthPrePassOcclusionCulling && this->DepthPrePass != DepthPrePassOff &&
    vtkPhongVisibleClusters::CanCull(ren, act, this, this->Primitives);
}

//------------------------------------------------------------------------------
double vtkPhongPolyDataMapper::GetDepthComplexity()
{
  return this->Internal->PrePass.GetDepthComplexity();
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::RenderPieceFinish(ren, act);
  // Parameter problems are reported once, not every frame: only when they change.
  this->Internal->Core->ReportProblems(this);
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internal->PrePass.ReleaseGraphicsResources(window);
  this->Internal->Clusters.ReleaseGraphicsResources(window);
  this->Internal->Core->ReleaseGraphicsResources();
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
  os << indent << "InterpolatedDotProducts: " << (this->InterpolatedDotProducts ? "On" : "Off")
     << "\n";
  os << indent << "LightCullingBound: " << this->LightCullingBound << "\n";
  os << indent << "DepthPrePass: " << this->DepthPrePass << "\n";
  os << indent << "UsedDepthPrePass: " << (this->UsedDepthPrePass ? "yes" : "no") << "\n";
  os << indent << "DepthComplexity: " << this->Internal->PrePass.GetDepthComplexity() << "\n";
  os << indent
     << "DepthPrePassOcclusionCulling: " << (this->DepthPrePassOcclusionCulling ? "On" : "Off")
     << "\n";
  os << indent << "DepthPassTriangles: " << this->DepthPassTriangles << "\n";
  os << indent << "ClosedSurfaceCulling: " << (this->ClosedSurfaceCulling ? "On" : "Off") << "\n";
  os << indent << "UsedClosedSurfaceCulling: " << (this->UsedClosedSurfaceCulling ? "yes" : "no")
     << "\n";
  os << indent << "MaximumNumberOfShaderPrograms: " << this->MaximumNumberOfShaderPrograms << "\n";
  os << indent << "Lighting:\n";
  this->Internal->Core->PrintSelf(os, indent.GetNextIndent());
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
    this->SetInterpolatedDotProducts(phong->GetInterpolatedDotProducts());
    this->SetLightCullingBound(phong->GetLightCullingBound());
    this->SetDepthPrePass(phong->GetDepthPrePass());
    this->SetDepthPrePassOcclusionCulling(phong->GetDepthPrePassOcclusionCulling());
    this->SetClosedSurfaceCulling(phong->GetClosedSurfaceCulling());
    this->SetMaximumNumberOfShaderPrograms(phong->GetMaximumNumberOfShaderPrograms());
  }
  this->Superclass::ShallowCopy(mapper);
}
