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
#include "vtkPhongBufferBlocks.h"
#include "vtkPhongClampedSetter.h"
#include "vtkPhongLightingMapper.txx"
#include "vtkPhongMapperCore.h"
#include "vtkPhongValidBlocks.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProperty.h"
#include "vtkUnsignedCharArray.h"

#include "vtkPhongOpenGL.h"
#include <algorithm>

template class vtkPhongLightingMapper<vtkOpenGLPolyDataMapper>;

vtkStandardNewMacro(vtkPhongPolyDataMapper);

struct vtkPhongPolyDataMapper::Internals
{
  vtkPhongLightingSettingsHolder Settings;
  vtkNew<vtkOpenMeshNormals> Normals;
  // The mapper named vtkOriginalPointIds for picking itself (and may unname it).
  bool NamedPointIds = false;
  // The input, or the copy drawn instead when cells name missing points.
  vtkPhongValidBlocks ValidInputs;
  // The input drawn before the normals filter replaced it (see StockNeedToRebuildShaders).
  vtkPolyData* InputWithoutNormals = nullptr;
};

//------------------------------------------------------------------------------
vtkPhongPolyDataMapper::vtkPhongPolyDataMapper()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkPhongPolyDataMapper::~vtkPhongPolyDataMapper() = default;

//------------------------------------------------------------------------------
vtkPhongLightingSettings* vtkPhongPolyDataMapper::GetLightingSettings()
{
  return this->Internal->Settings.Get();
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::SetLightingSettings(vtkPhongLightingSettings* settings)
{
  if (this->Internal->Settings.Set(settings, this))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkPhongPolyDataMapper::GetMTime()
{
  return this->Internal->Settings.MTime(this->Superclass::GetMTime());
}

//------------------------------------------------------------------------------
vtkPhongLightingSettings* vtkPhongPolyDataMapper::LightingSettings()
{
  return this->GetLightingSettings();
}

//------------------------------------------------------------------------------
int vtkPhongPolyDataMapper::GetNumberOfCulledLights()
{
  return this->GetCore()->GetNumberOfCulledLights();
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
int vtkPhongPolyDataMapper::GetNumberOfCompiledShaderPrograms()
{
  return this->GetCore()->GetNumberOfCompiledPrograms();
}

//------------------------------------------------------------------------------
int vtkPhongPolyDataMapper::GetNumberOfReleasedShaderPrograms()
{
  return this->GetCore()->GetNumberOfReleasedPrograms();
}

//------------------------------------------------------------------------------
int vtkPhongPolyDataMapper::GetShaderCompileCount()
{
  return this->GetCore()->GetShaderCompileCount();
}

//------------------------------------------------------------------------------
int vtkPhongPolyDataMapper::GetNumberOfShaderVariants()
{
  return this->GetCore()->GetNumberOfShaderVariants();
}

//------------------------------------------------------------------------------
double vtkPhongPolyDataMapper::GetLastShaderBuildTime()
{
  return this->GetCore()->GetLastShaderBuildTime();
}

//------------------------------------------------------------------------------
const char* vtkPhongPolyDataMapper::GetLastShaderSignature()
{
  return this->GetCore()->GetLastShaderSignature().c_str();
}

//------------------------------------------------------------------------------
const char* vtkPhongPolyDataMapper::GetLastVertexShaderSource()
{
  return this->GetCore()->GetLastVertexShaderSource().c_str();
}

//------------------------------------------------------------------------------
const char* vtkPhongPolyDataMapper::GetLastFragmentShaderSource()
{
  return this->GetCore()->GetLastFragmentShaderSource().c_str();
}

//------------------------------------------------------------------------------
const char* vtkPhongPolyDataMapper::GetLastGeometryShaderSource()
{
  return this->GetCore()->GetLastGeometryShaderSource().c_str();
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
  const bool rebuild = this->Superclass::StockNeedToRebuildShaders(cellBO, ren, act);
  this->CurrentInput = drawn;
  return rebuild;
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
std::vector<vtkPolyData*> vtkPhongPolyDataMapper::LitBlocks()
{
  std::vector<vtkPolyData*> blocks;
  if (this->CurrentInput)
  {
    blocks.push_back(this->CurrentInput);
  }
  return blocks;
}

//------------------------------------------------------------------------------
bool vtkPhongPolyDataMapper::BlocksInBuffer(std::vector<vtkPhongBufferBlock>& blocks)
{
  if (this->CurrentInput)
  {
    blocks.push_back({ this->CurrentInput, 0 });
  }
  return !blocks.empty();
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::SurfaceBounds(double bounds[6])
{
  this->CurrentInput->GetBounds(bounds);
}

//------------------------------------------------------------------------------
bool vtkPhongPolyDataMapper::GetUsedDepthPrePass()
{
  return this->Superclass::GetUsedDepthPrePass();
}

//------------------------------------------------------------------------------
double vtkPhongPolyDataMapper::GetDepthComplexity()
{
  return this->Superclass::GetDepthComplexity();
}

//------------------------------------------------------------------------------
double vtkPhongPolyDataMapper::GetDepthPassTriangles()
{
  return this->Superclass::GetDepthPassTriangles();
}

//------------------------------------------------------------------------------
double vtkPhongPolyDataMapper::GetErrorBound()
{
  return this->GetCore()->GetErrorBound();
}

//------------------------------------------------------------------------------
int vtkPhongPolyDataMapper::GetBudgetMode()
{
  return this->GetCore()->GetBudgetMode();
}

//------------------------------------------------------------------------------
const char* vtkPhongPolyDataMapper::GetBudgetModeAsString()
{
  return vtkPhongLightingSettings::GetBudgetModeAsString(this->GetBudgetMode());
}

//------------------------------------------------------------------------------
int vtkPhongPolyDataMapper::GetSquaredShininess()
{
  return this->GetCore()->GetSquaredShininess();
}

//------------------------------------------------------------------------------
bool vtkPhongPolyDataMapper::GetUsedClosedSurfaceCulling()
{
  return this->Superclass::GetUsedClosedSurfaceCulling();
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ComputeMissingNormals: " << (this->ComputeMissingNormals ? "On" : "Off") << "\n";
  os << indent << "NormalsWeighting: " << this->NormalsWeighting << "\n";
  os << indent << "NormalsFeatureAngle: " << this->NormalsFeatureAngle << "\n";
  os << indent << "NormalsSplitting: " << (this->NormalsSplitting ? "On" : "Off") << "\n";
  os << indent << "UsedGeneratedNormals: " << (this->UsedGeneratedNormals ? "yes" : "no") << "\n";
  os << indent << "UsedDepthPrePass: " << (this->GetUsedDepthPrePass() ? "yes" : "no") << "\n";
  os << indent << "DepthComplexity: " << this->GetDepthComplexity() << "\n";
  os << indent << "DepthPassTriangles: " << this->GetDepthPassTriangles() << "\n";
  os << indent
     << "UsedClosedSurfaceCulling: " << (this->GetUsedClosedSurfaceCulling() ? "yes" : "no")
     << "\n";
  os << indent << "LightingSettings:\n";
  this->Internal->Settings.Get()->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Lighting:\n";
  this->GetCore()->PrintSelf(os, indent.GetNextIndent());
}

//------------------------------------------------------------------------------
void vtkPhongPolyDataMapper::ShallowCopy(vtkAbstractMapper* mapper)
{
  if (auto* phong = vtkPhongPolyDataMapper::SafeDownCast(mapper))
  {
    this->GetLightingSettings()->DeepCopy(phong->GetLightingSettings());
    this->SetComputeMissingNormals(phong->GetComputeMissingNormals());
    this->SetNormalsWeighting(phong->GetNormalsWeighting());
    this->SetNormalsFeatureAngle(phong->GetNormalsFeatureAngle());
    this->SetNormalsSplitting(phong->GetNormalsSplitting());
  }
  this->Superclass::ShallowCopy(mapper);
}
