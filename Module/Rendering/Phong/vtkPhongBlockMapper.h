/**
 * @class   vtkPhongBlockMapper
 * @brief   the mapper that draws a group of blocks for vtkPhongCompositePolyDataMapper
 *
 * vtkPhongBlockMapper<BlockMapper> is VTK's own block mapper of the composite mapper, its
 * lighting handed to vtkPhongMapperCore exactly as vtkPhongPolyDataMapper does. BlockMapper
 * is the class VTK draws a group of blocks with, which depends on the VTK version
 * (vtkPhongCompatibility.h): vtkCompositeMapperHelper2 (a helper of vtkCompositePolyDataMapper2)
 * before VTK 9.3, vtkOpenGLBatchedPolyDataMapper (the delegate of a
 * vtkOpenGLCompositePolyDataMapperDelegator) from VTK 9.3 on. Both keep the blocks in one
 * vertex buffer, know their composite mapper as Parent, list their blocks with
 * GetRenderedList(), and write each block's colour and opacity overrides into VTK's own
 * uniforms (ambientColorUniform, diffuseColorUniform, opacityUniform) between the draws, after
 * the material uniforms set here; the lighting reads those uniforms whenever VTK's colour code
 * assigns the colours more than once (vtkPhongShaderBuilder), so the overrides keep working.
 *
 * Private to the rendering module: the composite mapper is the API.
 *
 * @sa vtkPhongCompositePolyDataMapper vtkPhongMapperCore vtkPhongPolyDataMapper
 */

#ifndef vtkPhongBlockMapper_h
#define vtkPhongBlockMapper_h

#include "vtkActor.h"
#include "vtkCellData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkOpenGLShaderProperty.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPhongClosedSurface.h"
#include "vtkPhongCompatibility.h"
#include "vtkPhongCompositePolyDataMapper.h"
#include "vtkPhongDepthPrePass.h"
#include "vtkPhongMapperCore.h"
#include "vtkPhongVisibleClusters.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSelection.h"
#include "vtkShaderProperty.h"

#include <map>
#include <vector>

template <class BlockMapper>
class vtkPhongBlockMapper : public BlockMapper
{
public:
  static vtkPhongBlockMapper* New() { VTK_STANDARD_NEW_BODY(vtkPhongBlockMapper); }
  vtkTemplateTypeMacro(vtkPhongBlockMapper, BlockMapper);

  vtkPhongMapperCore* GetCore() { return this->Core; }

  ///@{
  /**
   * Whether the last draw culled the back faces of closed surfaces, and whether it drew with
   * the depth pre-pass (RenderPieceDraw).
   */
  bool GetUsedClosedSurfaceCulling() const { return this->UsedClosedSurfaceCulling; }
  bool GetUsedDepthPrePass() const { return this->UsedDepthPrePass; }
  ///@}

  void ReleaseGraphicsResources(vtkWindow* window) override
  {
    this->PrePass.ReleaseGraphicsResources(window);
    this->Clusters.ReleaseGraphicsResources(window);
    this->Core->ReleaseGraphicsResources();
    this->Superclass::ReleaseGraphicsResources(window);
  }

protected:
  vtkPhongBlockMapper() = default;
  ~vtkPhongBlockMapper() override = default;

  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override
  {
    const bool rebuild = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);

    // As vtkPhongPolyDataMapper reads it, except that the normals of every block share
    // the vertex buffer, so every block's normals are scanned.
    vtkPhongShaderBuilder::PrimitiveState state;
    state.LightComplexity = this->PrimitiveInfo[&cellBO].LastLightComplexity;
    state.IsTriangles = cellBO.PrimitiveType == BlockMapper::PrimitiveTris ||
      cellBO.PrimitiveType == BlockMapper::PrimitiveTriStrips;
    state.HasPointNormals = this->VBOs->GetNumberOfComponents("normalMC") == 3;
    state.HasCellNormals = this->HaveCellNormals;
    for (vtkPolyData* block : this->GetRenderedList())
    {
      vtkDataArray* normals = state.HasPointNormals ? block->GetPointData()->GetNormals()
                                                    : block->GetCellData()->GetNormals();
      state.NormalsMayBeInvalid =
        state.NormalsMayBeInvalid || this->Core->HasUnusableVectors(normals);
    }
    state.NormalsFromShape = this->DrawingTubesOrSpheres(cellBO, act);
    state.DrawingEdges = this->DrawingEdges(ren, act);
    state.HasGeometryShader = state.DrawingEdges || this->HaveWideLines(ren, act) ||
      act->GetShaderProperty()->HasGeometryShaderCode();
    state.DrawingVertices = this->DrawingVertices;
    state.DrawingSelection = this->DrawingSelection;
    state.HasUserShaderCode = vtkPhongClosedSurface::HasShaderCode(act, this->LegacyShaders());

    if (auto* parent = vtkPhongCompositePolyDataMapper::SafeDownCast(this->Parent))
    {
      this->Core->Options.DebugView = parent->GetDebugView();
      this->Core->Options.DebugLightIndex = parent->GetDebugLightIndex();
      this->Core->Options.Specialize = parent->GetShaderSpecialization();
      this->Core->Options.InterpolatedDots = parent->GetInterpolatedDotProducts();
      this->Core->Options.LightCullingBound = parent->GetLightCullingBound();
    }
    this->Core->Options.DepthOnly = this->DrawingDepthOnly;
    return this->Core->PlanPrimitive(cellBO, ren, act, state) || rebuild;
  }

  void UpdateShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override
  {
    this->Core->BeginUpdateShaders();
    this->Superclass::UpdateShaders(cellBO, ren, act);
    if (this->Core->EndUpdateShaders(cellBO, ren, this->Reporter()))
    {
      this->Superclass::UpdateShaders(cellBO, ren, act); // now planned with VTK's lighting
    }
  }

  void BuildShaders(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    this->Superclass::BuildShaders(shaders, ren, act);
    this->Core->FinishBuild(
      shaders, this->LastBoundBO, ren, act, this->Reporter(),
      [&]() { this->Superclass::BuildShaders(shaders, ren, act); },
      [&]()
      {
        this->GetShaderTemplate(shaders, ren, vtkPhongMapperCore::TemplateActor(act));
        this->ReplaceShaderValues(shaders, ren, act);
      });
  }

  void ReplaceShaderLight(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override
  {
    if (!this->Core->Handles(this->LastBoundBO))
    {
      this->Superclass::ReplaceShaderLight(shaders, ren, act);
      return;
    }
    this->Core->ReplaceShaderLight(shaders, this->LastBoundBO);
  }

  void SetLightingShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override
  {
    if (!this->Core->Handles(&cellBO))
    {
      this->Superclass::SetLightingShaderParameters(cellBO, ren, act);
      return;
    }
    this->Core->SetLightUniforms(cellBO, ren);
  }

  void SetPropertyShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override
  {
    this->Superclass::SetPropertyShaderParameters(cellBO, ren, act);
    if (this->Core->Handles(&cellBO))
    {
      this->Core->SetMaterialUniforms(cellBO);
    }
  }

  // VTK's upload reads the block's points through its cell ids unchecked: a block with cells
  // naming missing points is uploaded from its collapsed copy, which the composite mapper
  // keeps (and has already made for its bounds).
#if VTKPHONG_VTK_9_3
  void AppendOneBufferObject(vtkRenderer* ren, vtkActor* act,
    typename BlockMapper::GLBatchElement* element, vtkIdType& offset,
    std::vector<unsigned char>& colors, std::vector<float>& norms) override
  {
    ValidBlockScope scope(element->Parent.PolyData, this->ValidBlock(element->Parent.PolyData));
    this->Superclass::AppendOneBufferObject(ren, act, element, offset, colors, norms);
  }
#else
  void AppendOneBufferObject(vtkRenderer* ren, vtkActor* act, vtkCompositeMapperHelperData* element,
    vtkIdType& offset, std::vector<unsigned char>& colors, std::vector<float>& norms) override
  {
    ValidBlockScope scope(element->Data, this->ValidBlock(element->Data));
    this->Superclass::AppendOneBufferObject(ren, act, element, offset, colors, norms);
  }
#endif

  vtkPolyData* ValidBlock(vtkPolyData* block)
  {
    auto* parent = vtkPhongCompositePolyDataMapper::SafeDownCast(this->Parent);
    return parent ? parent->GetValidBlock(block) : block;
  }

  // Points a block pointer at another polydata (the block's valid copy) for as long as it
  // lives.
  struct ValidBlockScope
  {
    ValidBlockScope(vtkPolyData*& block, vtkPolyData* valid)
      : Block(block)
      , Original(block)
    {
      block = valid;
    }
    ~ValidBlockScope() { this->Block = this->Original; }
    ValidBlockScope(const ValidBlockScope&) = delete;
    void operator=(const ValidBlockScope&) = delete;
    vtkPolyData*& Block;
    vtkPolyData* Original;
  };

  // As vtkPhongPolyDataMapper draws, over all the blocks in the vertex buffer: with the back
  // faces of closed surfaces culled (vtkPhongClosedSurface), only when every block is drawn
  // in this pass, visible and opaque, since a block left out could open a surface the others
  // close; then plainly or with the depth pre-pass (vtkPhongDepthPrePass), whose depth pass
  // may draw only the triangle clusters seen in the last frames (vtkPhongVisibleClusters),
  // again only when every block is drawn: the clusters are all the blocks' triangles.
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override
  {
    const bool wellColoured = !this->MixesPointAndCellScalars();
    std::vector<vtkPhongClosedSurface::Block> blocks;
    const bool everyBlock = wellColoured && this->EveryBlockDrawn(blocks);
    const unsigned int hiddenFaces = everyBlock ? this->HiddenFaces(ren, act, blocks) : 0;
    this->UsedClosedSurfaceCulling = hiddenFaces != 0;
    vtkPhongClosedSurface::ScopedCulling culling(ren, hiddenFaces);
    auto* parent = vtkPhongCompositePolyDataMapper::SafeDownCast(this->Parent);
    const int mode =
      parent && wellColoured ? parent->GetDepthPrePass() : vtkPhongPolyDataMapper::DepthPrePassOff;
    double triangles = 0.0;
    for (vtkPolyData* block : this->GetRenderedList())
    {
      triangles += static_cast<double>(block->GetNumberOfPolys() + block->GetNumberOfStrips());
    }
    const bool clustered = everyBlock && parent && parent->GetDepthPrePassOcclusionCulling() &&
      mode != vtkPhongPolyDataMapper::DepthPrePassOff &&
      vtkPhongVisibleClusters::CanCull(ren, act, this, this->Primitives);
    const double depthTriangles = clustered && this->Clusters.GetNumberOfTriangles() > 0
      ? this->Clusters.CollectVisibility()
      : triangles;
    this->UsedDepthPrePass = this->PrePass.Draw(mode, ren, act, this, triangles, depthTriangles,
      this->Core->GetNumberOfCulledLights(),
      [&](bool depthOnly)
      {
        this->DrawingDepthOnly = depthOnly;
        if (depthOnly && clustered && this->UpdateClusters(ren, blocks))
        {
          this->DrawingVertices = false;
          this->DrawingSelection = false;
          this->UpdateShaders(this->Primitives[BlockMapper::PrimitiveTris], ren, act);
          this->Clusters.Draw(ren, act);
        }
        else
        {
          this->Superclass::RenderPieceDraw(ren, act);
        }
        this->DrawingDepthOnly = false;
      });
  }

  // The clusters of all the blocks' triangles (vtkPhongVisibleClusters), made again when the
  // buffer was, from a copy of the blocks' points made for that (not kept).
  bool UpdateClusters(vtkRenderer* ren, const std::vector<vtkPhongClosedSurface::Block>& blocks)
  {
    vtkWindow* window = ren->GetRenderWindow();
    vtkOpenGLIndexBufferObject* triangles = this->Primitives[BlockMapper::PrimitiveTris].IBO;
    const vtkMTimeType builtAt = this->VBOBuildTime.GetMTime();
    vtkSmartPointer<vtkPolyData> points;
    if (!this->Clusters.IsCurrent(window, triangles, builtAt))
    {
      points = vtkPhongClosedSurface::PointsOfBlocks(blocks);
    }
    return this->Clusters.Update(window, triangles, points, builtAt);
  }

  // VTK 9.1 groups blocks by whether they have scalars, not by whether these are point or
  // cell scalars, then colours the whole group as its last block says: the others read
  // colours they do not have, some with an alpha of 0 that the shader discards. A plain draw
  // then shows what lies behind; the lit draw after a depth pass would show holes, and culled
  // back faces would hide what stock VTK shows. Neither is used for such groups.
  bool MixesPointAndCellScalars()
  {
    bool point = false, cell = false;
    for (vtkPolyData* block : this->GetRenderedList())
    {
      int cellFlag = 0;
      if (this->ScalarVisibility &&
        vtkAbstractMapper::GetAbstractScalars(
          block, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag))
      {
        point = point || cellFlag == 0;
        cell = cell || cellFlag != 0;
      }
    }
    return point && cell;
  }

  // The faces to cull, or 0, as vtkPhongPolyDataMapper::HiddenFaces decides, for `blocks`,
  // every block in the vertex buffer.
  unsigned int HiddenFaces(
    vtkRenderer* ren, vtkActor* act, const std::vector<vtkPhongClosedSurface::Block>& blocks)
  {
    auto* parent = vtkPhongCompositePolyDataMapper::SafeDownCast(this->Parent);
    if (!parent || !parent->GetClosedSurfaceCulling())
    {
      return 0;
    }
    const int clippingPlanes =
      this->GetNumberOfClippingPlanes() + parent->GetNumberOfClippingPlanes();
    vtkSelection* selection = parent->GetSelection();
    if (!vtkPhongClosedSurface::DrawsOnlySurfaces(
          ren, act, this->Primitives, this->LegacyShaders(), clippingPlanes) ||
      (selection && selection->GetNumberOfNodes() > 0))
    {
      return 0;
    }
    this->ClosedSurface.Update(
      this->Primitives[BlockMapper::PrimitiveTris].IBO, blocks, this->VBOBuildTime.GetMTime());
    return this->ClosedSurface.HiddenFaces(ren, act, parent->GetBounds());
  }

  // Whether every block in the vertex buffer is visible and opaque; `blocks`: all of them,
  // with the points each uploaded (its valid copy's, from its first vertex on), or none when
  // the buffer does not hold what the blocks say.
  bool EveryBlockDrawn(std::vector<vtkPhongClosedSurface::Block>& blocks)
  {
    bool everyBlock = true;
    for (const BlockInBuffer& block : this->BlocksInBuffer())
    {
      vtkPolyData* uploaded = this->ValidBlock(block.Data);
      if (!uploaded || block.NextVertex - block.StartVertex != uploaded->GetNumberOfPoints())
      {
        blocks.clear();
        return false;
      }
      everyBlock = everyBlock && block.VisibleAndOpaque;
      blocks.push_back({ uploaded, static_cast<vtkIdType>(block.StartVertex) });
    }
    return everyBlock && !blocks.empty();
  }

  struct BlockInBuffer
  {
    vtkPolyData* Data;
    bool VisibleAndOpaque;
    vtkIdType StartVertex;
    vtkIdType NextVertex;
  };

  std::vector<BlockInBuffer> BlocksInBuffer() const
  {
    std::vector<BlockInBuffer> blocks;
#if VTKPHONG_VTK_9_3
    for (const auto& entry : this->VTKPolyDataToGLBatchElement)
    {
      const auto& element = *entry.second;
      blocks.push_back(
        { element.Parent.PolyData, element.Parent.Visibility && element.Parent.IsOpaque,
          element.StartVertex, element.NextVertex });
    }
#else
    for (const auto& entry : this->Data)
    {
      const vtkCompositeMapperHelperData& element = *entry.second;
      blocks.push_back({ element.Data, element.Visibility && element.IsOpaque, element.StartVertex,
        element.NextVertex });
    }
#endif
    return blocks;
  }

  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override
  {
    this->Superclass::RenderPieceFinish(ren, act);
    this->Core->ReportProblems(this->Reporter());
  }

  // Errors name the mapper the user made, not the block mapper.
  vtkObject* Reporter()
  {
    return this->Parent ? static_cast<vtkObject*>(this->Parent) : this;
  }

  vtkNew<vtkPhongMapperCore> Core;
  vtkPhongClosedSurface ClosedSurface;
  bool UsedClosedSurfaceCulling = false;
  vtkPhongDepthPrePass PrePass;
  vtkPhongVisibleClusters Clusters;
  bool UsedDepthPrePass = false;
  bool DrawingDepthOnly = false;

private:
  // The mapper's own shader replacements (VTK before 9.2), or nullptr.
  vtkShaderProperty* LegacyShaders() const
  {
#if VTKPHONG_VTK_MAPPER_SHADER_REPLACEMENTS
    return this->LegacyShaderProperty;
#else
    return nullptr;
#endif
  }

  vtkPhongBlockMapper(const vtkPhongBlockMapper&) = delete;
  void operator=(const vtkPhongBlockMapper&) = delete;
};

#endif
