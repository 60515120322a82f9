#include "vtkPhongCompositePolyDataMapper.h"

// VTK 9.1's vtkCompositeMapperHelper2.h uses these without including them.
#include "vtkColor.h"
#include "vtkHardwareSelector.h"
#include "vtk_glew.h"

#include "vtkActor.h"
#include "vtkCellData.h"
#include "vtkCompositeMapperHelper2.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPhongMapperCore.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkShaderProperty.h"

//------------------------------------------------------------------------------
// The helper that draws the blocks: VTK's composite helper, its lighting handed to
// vtkPhongMapperCore exactly as vtkPhongPolyDataMapper does.
class vtkPhongCompositeMapperHelper : public vtkCompositeMapperHelper2
{
public:
  static vtkPhongCompositeMapperHelper* New();
  vtkTypeMacro(vtkPhongCompositeMapperHelper, vtkCompositeMapperHelper2);

  vtkPhongMapperCore* GetCore() { return this->Core; }

  void ReleaseGraphicsResources(vtkWindow* window) override
  {
    this->Core->ReleaseGraphicsResources();
    this->Superclass::ReleaseGraphicsResources(window);
  }

protected:
  vtkPhongCompositeMapperHelper() = default;
  ~vtkPhongCompositeMapperHelper() override = default;

  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override
  {
    const bool rebuild = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);

    // As vtkPhongPolyDataMapper reads it, except that the normals of every block share
    // the vertex buffer, so every block's normals are scanned.
    vtkPhongShaderBuilder::PrimitiveState state;
    state.LightComplexity = this->PrimitiveInfo[&cellBO].LastLightComplexity;
    state.IsTriangles =
      cellBO.PrimitiveType == PrimitiveTris || cellBO.PrimitiveType == PrimitiveTriStrips;
    state.HasPointNormals = this->VBOs->GetNumberOfComponents("normalMC") == 3;
    state.HasCellNormals = this->HaveCellNormals;
    for (const auto& block : this->Data)
    {
      vtkDataArray* normals = state.HasPointNormals ? block.first->GetPointData()->GetNormals()
                                                    : block.first->GetCellData()->GetNormals();
      state.NormalsMayBeInvalid =
        state.NormalsMayBeInvalid || this->Core->HasUnusableVectors(normals);
    }
    state.NormalsFromShape = this->DrawingTubesOrSpheres(cellBO, act);
    state.HasGeometryShader = this->DrawingEdges(ren, act) || this->HaveWideLines(ren, act) ||
      act->GetShaderProperty()->HasGeometryShaderCode();
    state.DrawingVertices = this->DrawingVertices;
    state.DrawingSelection = this->DrawingSelection;

    if (auto* parent = vtkPhongCompositePolyDataMapper::SafeDownCast(this->Parent))
    {
      this->Core->Options.DebugView = parent->GetDebugView();
      this->Core->Options.DebugLightIndex = parent->GetDebugLightIndex();
      this->Core->Options.Specialize = parent->GetShaderSpecialization();
    }
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
    this->Core->ShadersBuilt(shaders, this->LastBoundBO);
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

  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override
  {
    this->Superclass::RenderPieceFinish(ren, act);
    this->Core->ReportProblems(this->Reporter());
  }

  // Errors name the mapper the user made, not its helper.
  vtkObject* Reporter() { return this->Parent ? static_cast<vtkObject*>(this->Parent) : this; }

  vtkNew<vtkPhongMapperCore> Core;

private:
  vtkPhongCompositeMapperHelper(const vtkPhongCompositeMapperHelper&) = delete;
  void operator=(const vtkPhongCompositeMapperHelper&) = delete;
};

vtkStandardNewMacro(vtkPhongCompositeMapperHelper);

//------------------------------------------------------------------------------
vtkStandardNewMacro(vtkPhongCompositePolyDataMapper);

//------------------------------------------------------------------------------
vtkPhongCompositePolyDataMapper::vtkPhongCompositePolyDataMapper() = default;

//------------------------------------------------------------------------------
vtkPhongCompositePolyDataMapper::~vtkPhongCompositePolyDataMapper() = default;

//------------------------------------------------------------------------------
vtkCompositeMapperHelper2* vtkPhongCompositePolyDataMapper::CreateHelper()
{
  return vtkPhongCompositeMapperHelper::New();
}

//------------------------------------------------------------------------------
namespace
{
// A statistic of the helpers' cores, summed.
int SumOverHelpers(const std::map<const std::string, vtkCompositeMapperHelper2*>& helpers,
  int (vtkPhongMapperCore::*statistic)() const)
{
  int sum = 0;
  for (const auto& helper : helpers)
  {
    if (auto* phong = vtkPhongCompositeMapperHelper::SafeDownCast(helper.second))
    {
      sum += (phong->GetCore()->*statistic)();
    }
  }
  return sum;
}
}

//------------------------------------------------------------------------------
int vtkPhongCompositePolyDataMapper::GetShaderCompileCount()
{
  return SumOverHelpers(this->Helpers, &vtkPhongMapperCore::GetShaderCompileCount);
}

//------------------------------------------------------------------------------
int vtkPhongCompositePolyDataMapper::GetNumberOfShaderVariants()
{
  return SumOverHelpers(this->Helpers, &vtkPhongMapperCore::GetNumberOfShaderVariants);
}

//------------------------------------------------------------------------------
const char* vtkPhongCompositePolyDataMapper::GetLastShaderSignature()
{
  this->LastSignature.clear();
  for (const auto& helper : this->Helpers)
  {
    auto* phong = vtkPhongCompositeMapperHelper::SafeDownCast(helper.second);
    if (phong && !phong->GetCore()->GetLastShaderSignature().empty())
    {
      this->LastSignature = phong->GetCore()->GetLastShaderSignature();
    }
  }
  return this->LastSignature.c_str();
}

//------------------------------------------------------------------------------
void vtkPhongCompositePolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DebugView: " << this->DebugView << "\n";
  os << indent << "DebugLightIndex: " << this->DebugLightIndex << "\n";
  os << indent << "ShaderSpecialization: " << (this->ShaderSpecialization ? "On" : "Off") << "\n";
  os << indent << "NumberOfHelpers: " << this->Helpers.size() << "\n";
  os << indent << "ShaderCompileCount: " << this->GetShaderCompileCount() << "\n";
  os << indent << "NumberOfShaderVariants: " << this->GetNumberOfShaderVariants() << "\n";
  os << indent << "LastShaderSignature: " << this->GetLastShaderSignature() << "\n";
}
