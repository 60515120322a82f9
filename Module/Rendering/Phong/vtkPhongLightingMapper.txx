// The implementation of vtkPhongLightingMapper<Base>, included only by the rendering module's
// files that instantiate it (vtkPhongPolyDataMapper.cxx, vtkPhongBlockMapper.cxx).

#ifndef vtkPhongLightingMapper_txx
#define vtkPhongLightingMapper_txx

#include "vtkPhongLightingMapper.h"

#include "vtkActor.h"
#include "vtkCellData.h"
#include "vtkNew.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkOpenGLShaderProperty.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPhongBufferBlocks.h"
#include "vtkPhongClosedSurface.h"
#include "vtkPhongCompatibility.h"
#include "vtkPhongDepthPrePass.h"
#include "vtkPhongGouraudBound.h"
#include "vtkPhongMapperCore.h"
#include "vtkPhongScopedCulling.h"
#include "vtkPhongShaderCode.h"
#include "vtkPhongVisibleClusters.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProperty.h"

template <class Base>
struct vtkPhongLightingMapper<Base>::Internals
{
  vtkNew<vtkPhongMapperCore> Core;
  // The visibility work: culled back faces, the depth pre-pass, the depth pass's clusters.
  vtkPhongClosedSurface ClosedSurface;
  vtkPhongDepthPrePass PrePass;
  vtkPhongVisibleClusters Clusters;
  // The triangles binned for the error budget's per-vertex bound.
  vtkPhongGouraudBound Triangles;
  // The depth pass of the pre-pass is being drawn (its program computes no light).
  bool DrawingDepthOnly = false;
  bool UsedClosedSurfaceCulling = false;
  bool UsedDepthPrePass = false;
  double DepthPassTriangles = 0.0;
};

//------------------------------------------------------------------------------
template <class Base>
vtkPhongLightingMapper<Base>::vtkPhongLightingMapper()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
template <class Base>
vtkPhongLightingMapper<Base>::~vtkPhongLightingMapper() = default;

//------------------------------------------------------------------------------
template <class Base>
vtkPhongMapperCore* vtkPhongLightingMapper<Base>::GetCore()
{
  return this->Internal->Core;
}

//------------------------------------------------------------------------------
template <class Base>
bool vtkPhongLightingMapper<Base>::GetUsedClosedSurfaceCulling() const
{
  return this->Internal->UsedClosedSurfaceCulling;
}

//------------------------------------------------------------------------------
template <class Base>
bool vtkPhongLightingMapper<Base>::GetUsedDepthPrePass() const
{
  return this->Internal->UsedDepthPrePass;
}

//------------------------------------------------------------------------------
template <class Base>
double vtkPhongLightingMapper<Base>::GetDepthPassTriangles() const
{
  return this->Internal->DepthPassTriangles;
}

//------------------------------------------------------------------------------
template <class Base>
double vtkPhongLightingMapper<Base>::GetDepthComplexity() const
{
  return this->Internal->PrePass.GetDepthComplexity();
}

//------------------------------------------------------------------------------
template <class Base>
bool vtkPhongLightingMapper<Base>::StockNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  return this->Base::GetNeedToRebuildShaders(cellBO, ren, act);
}

//------------------------------------------------------------------------------
template <class Base>
void vtkPhongLightingMapper<Base>::BuildBufferObjects(vtkRenderer* ren, vtkActor* act)
{
  this->Base::BuildBufferObjects(ren, act);
  vtkPhongBufferBlocks::ReleasePackedCopies(this->VBOs);
}

//------------------------------------------------------------------------------
// VTK's test first (it also refreshes this primitive's light complexity), then what only the
// stock mapper's protected state tells, for the core's plan: the shader is rebuilt when the
// plan's signature changed.
template <class Base>
bool vtkPhongLightingMapper<Base>::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  const bool rebuild = this->StockNeedToRebuildShaders(cellBO, ren, act);

  vtkPhongMapperCore* core = this->Internal->Core;
  vtkPhongPrimitiveState state;
  state.LightComplexity = static_cast<int>(this->PrimitiveInfo[&cellBO].LastLightComplexity);
  state.IsTriangles =
    cellBO.PrimitiveType == Base::PrimitiveTris || cellBO.PrimitiveType == Base::PrimitiveTriStrips;
  state.HasPointNormals = this->VBOs->GetNumberOfComponents("normalMC") == 3;
  state.HasCellNormals = this->HaveCellNormals;
  // Every block in the buffer: their normals share it.
  const std::vector<vtkPolyData*> blocks = this->LitBlocks();
  for (vtkPolyData* block : blocks)
  {
    vtkDataArray* normals = state.HasPointNormals ? block->GetPointData()->GetNormals()
      : state.HasCellNormals                      ? block->GetCellData()->GetNormals()
                                                  : nullptr;
    state.NormalsMayBeInvalid =
      state.NormalsMayBeInvalid || (normals && core->HasUnusableVectors(normals));
  }
  vtkPhongMapperCore::BoundsInWorld(blocks, act, state.BoundsWC);
  state.NormalsFromShape = this->DrawingTubesOrSpheres(cellBO, act);
  state.DrawingEdges = this->DrawingEdges(ren, act);
  state.HasGeometryShader = state.DrawingEdges || this->HaveWideLines(ren, act) ||
    act->GetShaderProperty()->HasGeometryShaderCode();
  state.DrawingVertices = this->DrawingVertices;
  state.DrawingSelection = this->DrawingSelection;
  state.HasUserShaderCode = vtkPhongShaderCode::HasUserCode(act, this->LegacyShaders());
  state.MaterialPerBlock = this->MaterialPerBlock();

  vtkPhongLightingSettings* settings = this->LightingSettings();
  core->Options.DebugView = settings->GetDebugView();
  core->Options.DebugLightIndex = settings->GetDebugLightIndex();
  core->Options.Specialize = settings->GetShaderSpecialization();
  core->Options.InterpolatedDots = settings->GetInterpolatedDotProducts();
  core->Options.LightCullingBound = settings->GetLightCullingBound();
  core->Options.ErrorBudget = settings->GetErrorBudget() / 255.0;
  if (core->Options.ErrorBudget > 0.0 && &cellBO == &this->Primitives[Base::PrimitiveTris] &&
    state.HasPointNormals)
  {
    this->Internal->Triangles.Update(blocks, this->VBOBuildTime.GetMTime());
    state.Triangles = &this->Internal->Triangles;
  }
  core->Options.SpecularAntiAliasing = settings->GetSpecularAntiAliasing();
  core->Options.LightingWithoutLights = settings->GetLightingWithoutLights();
  core->Options.DepthOnly = this->Internal->DrawingDepthOnly;
  core->MaximumNumberOfPrograms = settings->GetMaximumNumberOfShaderPrograms();
  return core->PlanPrimitive(cellBO, ren, act, state) || rebuild;
}

//------------------------------------------------------------------------------
template <class Base>
void vtkPhongLightingMapper<Base>::UpdateShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  vtkPhongMapperCore* core = this->Internal->Core;
  core->BeginUpdateShaders();
  this->Base::UpdateShaders(cellBO, ren, act);
  if (core->EndUpdateShaders(cellBO, ren, this->Reporter()))
  {
    this->Base::UpdateShaders(cellBO, ren, act); // now planned with VTK's lighting
  }
}

//------------------------------------------------------------------------------
template <class Base>
void vtkPhongLightingMapper<Base>::BuildShaders(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Base::BuildShaders(shaders, ren, act);
  this->Internal->Core->FinishBuild(
    shaders, this->LastBoundBO, ren, act, this->Reporter(),
    [&]() { this->Base::BuildShaders(shaders, ren, act); },
    [&]()
    {
      this->GetShaderTemplate(shaders, ren, vtkPhongMapperCore::TemplateActor(act));
      this->ReplaceShaderValues(shaders, ren, act);
    });
}

//------------------------------------------------------------------------------
template <class Base>
void vtkPhongLightingMapper<Base>::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  if (!this->Internal->Core->Handles(this->LastBoundBO))
  {
    this->Base::ReplaceShaderLight(shaders, ren, act);
    return;
  }
  this->Internal->Core->ReplaceShaderLight(shaders, this->LastBoundBO);
}

//------------------------------------------------------------------------------
template <class Base>
void vtkPhongLightingMapper<Base>::SetLightingShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  if (!this->Internal->Core->Handles(&cellBO))
  {
    this->Base::SetLightingShaderParameters(cellBO, ren, act);
    return;
  }
  this->Internal->Core->SetLightUniforms(cellBO, ren);
}

//------------------------------------------------------------------------------
template <class Base>
void vtkPhongLightingMapper<Base>::SetPropertyShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Base::SetPropertyShaderParameters(cellBO, ren, act);
  if (this->Internal->Core->Handles(&cellBO))
  {
    this->Internal->Core->SetMaterialUniforms(cellBO);
  }
}

//------------------------------------------------------------------------------
// With the back faces of closed surfaces culled when none can be seen (vtkPhongClosedSurface);
// then plainly or with the depth pre-pass (vtkPhongDepthPrePass), whose depth pass may draw
// only the triangle clusters seen in the last frames (vtkPhongVisibleClusters). Culling of
// either kind needs every block of the buffer drawn, visible and opaque: a block left out
// could open a surface the others close, and the clusters are all the blocks' triangles.
template <class Base>
void vtkPhongLightingMapper<Base>::RenderPieceDraw(vtkRenderer* ren, vtkActor* act)
{
  const bool allowed = this->VisibilityWorkAllowed();
  std::vector<vtkPhongBufferBlock> blocks;
  const bool everyBlock = allowed && this->BlocksInBuffer(blocks);
  const unsigned int hiddenFaces = everyBlock ? this->HiddenFaces(ren, act, blocks) : 0;
  this->Internal->UsedClosedSurfaceCulling = hiddenFaces != 0;
  vtkPhongScopedCulling culling(ren, hiddenFaces);
  this->DrawSurfaces(ren, act, blocks, everyBlock, allowed);
}

//------------------------------------------------------------------------------
// The faces to cull, or 0: nothing drawn may show a back face other than through the closed
// surfaces (a shader replacement, a clipping plane's cut, a texture's transparent texel, an
// edge over a silhouette could), then the surfaces and the view (vtkPhongClosedSurface).
template <class Base>
unsigned int vtkPhongLightingMapper<Base>::HiddenFaces(
  vtkRenderer* ren, vtkActor* act, const std::vector<vtkPhongBufferBlock>& blocks)
{
  if (!this->LightingSettings()->GetClosedSurfaceCulling() || this->HasSelection() ||
    !vtkPhongClosedSurface::DrawsOnlySurfaces(
      ren, act, this->Primitives, this->LegacyShaders(), this->ClippingPlanesSeen()))
  {
    return 0;
  }
  vtkPhongClosedSurface& surface = this->Internal->ClosedSurface;
  surface.Update(this->Primitives[Base::PrimitiveTris].IBO, blocks, this->VBOBuildTime.GetMTime());
  double bounds[6];
  this->SurfaceBounds(bounds);
  return surface.HiddenFaces(ren, act, bounds);
}

//------------------------------------------------------------------------------
// Plainly or with the depth pre-pass (vtkPhongDepthPrePass decides and draws), whose depth
// pass may leave out the triangles hidden in the last frame (vtkPhongVisibleClusters).
template <class Base>
void vtkPhongLightingMapper<Base>::DrawSurfaces(vtkRenderer* ren, vtkActor* act,
  const std::vector<vtkPhongBufferBlock>& blocks, bool everyBlock, bool allowed)
{
  vtkPhongLightingSettings* settings = this->LightingSettings();
  const int mode =
    allowed ? settings->GetDepthPrePass() : vtkPhongLightingSettings::DepthPrePassOff;
  double triangles = 0.0;
  for (vtkPolyData* block : this->LitBlocks())
  {
    triangles += static_cast<double>(block->GetNumberOfPolys() + block->GetNumberOfStrips());
  }
  vtkPhongVisibleClusters& clusters = this->Internal->Clusters;
  // The automatic mode's clusters wait for its decision that the pre-pass pays: an open
  // terrain's probe would arrange them only to find that it does not.
  const bool wanted = mode == vtkPhongLightingSettings::DepthPrePassOn ||
    (mode == vtkPhongLightingSettings::DepthPrePassAutomatic &&
      this->Internal->PrePass.PaysSoFar());
  const bool culling = everyBlock && settings->GetDepthPrePassOcclusionCulling() && wanted &&
    vtkPhongVisibleClusters::CanCull(ren, act, this, this->Primitives);
  // Culled, the depth pass draws the seen clusters' triangles and nothing else (VTK's
  // triangulated polygons, where `triangles` counts cells).
  const double depthTriangles =
    culling && clusters.GetNumberOfTriangles() > 0 ? clusters.CollectVisibility() : triangles;
  this->Internal->DepthPassTriangles = 0.0;
  this->Internal->UsedDepthPrePass = this->Internal->PrePass.Draw(mode, ren, act, this, triangles,
    depthTriangles, this->Internal->Core->GetNumberOfCulledLights(),
    this->Internal->UsedClosedSurfaceCulling,
    [&](bool depthOnly)
    {
      // VTK's draw advances the primitive id offset of cell colours and normals as it goes:
      // the lit draw must start where the depth pass did.
      const auto primitiveIdOffset = this->PrimitiveIDOffset;
      this->Internal->DrawingDepthOnly = depthOnly;
      if (depthOnly)
      {
        this->DrawDepthPass(ren, act, blocks, culling, triangles);
        this->PrimitiveIDOffset = primitiveIdOffset;
      }
      else
      {
        this->Base::RenderPieceDraw(ren, act);
      }
      this->Internal->DrawingDepthOnly = false;
    });
}

//------------------------------------------------------------------------------
// The depth pass is VTK's draw with the depth-only program; culled, the triangles are those
// of the clusters seen in the last frame, and a share of the hidden ones. The clusters are
// made again when the buffer was, from the points of its blocks (a copy made for that and not
// kept where there are several).
template <class Base>
void vtkPhongLightingMapper<Base>::DrawDepthPass(vtkRenderer* ren, vtkActor* act,
  const std::vector<vtkPhongBufferBlock>& blocks, bool culling, double triangles)
{
  vtkPhongVisibleClusters& clusters = this->Internal->Clusters;
  bool culled = false;
  if (culling)
  {
    vtkWindow* window = ren->GetRenderWindow();
    vtkOpenGLIndexBufferObject* triangles = this->Primitives[Base::PrimitiveTris].IBO;
    const vtkMTimeType builtAt = this->VBOBuildTime.GetMTime();
    vtkSmartPointer<vtkPolyData> points;
    if (!clusters.IsCurrent(window, triangles, builtAt))
    {
      points = vtkPhongBufferBlocks::Points(blocks);
    }
    culled = clusters.Update(window, triangles, points, builtAt);
  }
  if (!culled)
  {
    this->Base::RenderPieceDraw(ren, act);
    this->Internal->DepthPassTriangles = triangles;
    return;
  }
  this->DrawingVertices = false;
  this->DrawingSelection = false;
  this->UpdateShaders(this->Primitives[Base::PrimitiveTris], ren, act);
  clusters.Draw(ren, act);
  this->Internal->DepthPassTriangles = clusters.GetNumberOfTrianglesDrawn();
}

//------------------------------------------------------------------------------
template <class Base>
void vtkPhongLightingMapper<Base>::RenderPieceFinish(vtkRenderer* ren, vtkActor* act)
{
  this->Base::RenderPieceFinish(ren, act);
  // Parameter problems are reported once, not every frame: only when they change.
  this->Internal->Core->ReportProblems(this->Reporter());
}

//------------------------------------------------------------------------------
template <class Base>
void vtkPhongLightingMapper<Base>::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internal->PrePass.ReleaseGraphicsResources(window);
  this->Internal->Clusters.ReleaseGraphicsResources(window);
  this->Internal->Core->ReleaseGraphicsResources();
  this->Base::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
template <class Base>
vtkShaderProperty* vtkPhongLightingMapper<Base>::LegacyShaders() const
{
#if VTKPHONG_VTK_MAPPER_SHADER_REPLACEMENTS
  return this->LegacyShaderProperty;
#else
  return nullptr;
#endif
}

#endif
