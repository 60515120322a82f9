#include "vtkPhongSurfaceRepresentation.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCommunicator.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkGhostCellsGenerator.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOpenMeshNormals.h"
#include "vtkPVLODActor.h"
#include "vtkPVTrivialProducer.h"
#include "vtkPhongCompositePolyDataMapper.h"
#include "vtkPhongGhostCellsStash.h"
#include "vtkPhongLightingSettings.h"
#include "vtkPhongProperty.h"
#include "vtkPhongSeamFacesExchange.h"
#include "vtkPhongSeamNormalsPatch.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>

vtkStandardNewMacro(vtkPhongSurfaceRepresentation);

//------------------------------------------------------------------------------
vtkPhongSurfaceRepresentation::vtkPhongSurfaceRepresentation()
{
  // The superclass made stock mappers and a plain vtkProperty: replace them, keeping the
  // array names its selection needs, then wire the pipeline again.
  auto* mapper = vtkPhongCompositePolyDataMapper::New();
  mapper->SetProcessIdArrayName("vtkProcessId");
  mapper->SetCompositeIdArrayName("vtkCompositeIndex");
  this->Mapper->Delete();
  this->Mapper = mapper;
  this->LODMapper->Delete();
  this->LODMapper = vtkPhongCompositePolyDataMapper::New();
  // One lighting settings object, which the properties below set, for both mappers.
  for (vtkMapper* drawing : { this->Mapper, this->LODMapper })
  {
    vtkPhongCompositePolyDataMapper::SafeDownCast(drawing)->SetLightingSettings(
      this->LightingSettings);
  }
  this->SetArrayIdNames(nullptr, nullptr);

  auto* material = vtkPhongProperty::New();
  material->DeepCopy(this->Property);
  material->SetLightingModelToBlinnPhong();
  material->SetShininess(100.0);
  this->Property->Delete();
  this->Property = material;

  this->Normals->SetWeighting(vtkOpenMeshNormals::Max);
  this->Normals->SetFeatureAngle(30.0);
  this->Normals->SplittingOn();
  this->GhostCells->BuildIfRequiredOff();
  this->GhostCells->SetNumberOfGhostLayers(1);
  this->GhostStash->SetModeToStash();
  this->GhostTrim->SetModeToTrim();
  this->GhostRemoval->SetModeToUnstash();
  this->SetupDefaults();
}

//------------------------------------------------------------------------------
vtkPhongSurfaceRepresentation::~vtkPhongSurfaceRepresentation() = default;

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetupDefaults()
{
  this->Superclass::SetupDefaults();
  this->ConnectNormals();
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::ConnectNormals()
{
  if (this->ComputesNormals)
  {
    // Trim and removal run whether or not the stash did: without stashed flags they only
    // pass the data on.
    this->GhostTrim->SetInputConnection(this->GeometryFilter->GetOutputPort());
    this->Normals->SetInputConnection(this->GhostTrim->GetOutputPort());
    this->GhostRemoval->SetInputConnection(this->Normals->GetOutputPort());
    this->SeamFaces->SetInputConnection(this->GeometryFilter->GetOutputPort());
    this->SeamNormals->SetInputConnection(this->SeamFaces->GetOutputPort());
    this->SeamPatch->SetInputConnection(0, this->GhostRemoval->GetOutputPort());
    this->SeamPatch->SetInputConnection(1, this->SeamNormals->GetOutputPort());
    this->MultiBlockMaker->SetInputConnection(
      this->PatchesSeams ? this->SeamPatch->GetOutputPort() : this->GhostRemoval->GetOutputPort());
  }
  else
  {
    this->MultiBlockMaker->SetInputConnection(this->GeometryFilter->GetOutputPort());
  }
  this->ApplyNormalArray();
}

//------------------------------------------------------------------------------
vtkAlgorithmOutput* vtkPhongSurfaceRepresentation::GetInternalOutputPort(int port, int connection)
{
  vtkAlgorithmOutput* internal = this->Superclass::GetInternalOutputPort(port, connection);
  if (!internal || !this->StashesGhostCells())
  {
    return internal;
  }
  // Data sets and composite data only (not hyper-tree grids). The decision must be the same
  // on every rank, the ghost-cell generator being collective: it depends on the number of
  // ranks and the input's type, never on a rank's own piece.
  vtkDataObject* data = internal->GetProducer()->GetOutputDataObject(internal->GetIndex());
  if (!vtkDataSet::SafeDownCast(data) && !vtkCompositeDataSet::SafeDownCast(data))
  {
    return internal;
  }
  if (vtkPhongSurfaceRepresentation::IsParallel() &&
    !vtkPhongSurfaceRepresentation::ExchangesSeamFaces(data))
  {
    this->GhostCells->SetInputConnection(internal);
    this->GhostStash->SetInputConnection(this->GhostCells->GetOutputPort());
  }
  else
  {
    this->GhostStash->SetInputConnection(internal);
  }
  return this->GhostStash->GetOutputPort();
}

//------------------------------------------------------------------------------
bool vtkPhongSurfaceRepresentation::IsParallel()
{
  auto* controller = vtkMultiProcessController::GetGlobalController();
  return controller && controller->GetNumberOfProcesses() > 1;
}

//------------------------------------------------------------------------------
bool vtkPhongSurfaceRepresentation::ExchangesSeamFaces(vtkDataObject* input)
{
  return vtkPolyData::SafeDownCast(input) && vtkPhongSurfaceRepresentation::IsParallel();
}

//------------------------------------------------------------------------------
int vtkPhongSurfaceRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // Every rank runs this on every update (the collective steps below rely on it).
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  const bool computes = this->ComputeNormals == Always ||
    (this->ComputeNormals == WhereMissing &&
      !vtkPhongSurfaceRepresentation::HasPointNormals(input));
  if (computes != this->ComputesNormals)
  {
    this->ComputesNormals = computes;
    this->ConnectNormals();
  }
  const bool acrossPieces =
    this->StashesGhostCells() && vtkPhongSurfaceRepresentation::IsParallel();
  if (acrossPieces)
  {
    // Collective: every rank must run them on every update, as ParaView does with its
    // geometry filter, whether or not its own piece changed.
    this->GhostCells->Modified();
    this->SeamFaces->Modified();
  }
  // Polydata: the piece's normals, then its cut points' from the seam mesh. Other data: a
  // piece's points on a cut, and the ghost cells' points, come as copies (a source's own
  // pieces compute them by different sums): the normals join them. The seam mesh already
  // has the piece's own copies, and a piece's points are not joined serially either.
  const bool seams = acrossPieces && vtkPhongSurfaceRepresentation::ExchangesSeamFaces(input);
  this->SeamFaces->SetEnabled(seams);
  this->Normals->SetJoinCoincidentPoints(acrossPieces && !seams);
  this->ConfigureSeamNormals();
  if (seams != this->PatchesSeams)
  {
    this->PatchesSeams = seams;
    this->ConnectNormals();
  }
  const auto wholeExtent = vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT();
  if (this->StashesGhostCells() && inputVector[0]->GetNumberOfInformationObjects() == 1 &&
    inputVector[0]->GetInformationObject(0)->Has(wholeExtent))
  {
    vtkAlgorithmOutput* internal = this->Superclass::GetInternalOutputPort(0, 0);
    if (auto* producer = vtkPVTrivialProducer::SafeDownCast(internal->GetProducer()))
    {
      producer->SetWholeExtent(inputVector[0]->GetInformationObject(0)->Get(wholeExtent));
    }
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::ConfigureSeamNormals()
{
  this->SeamNormals->SetWeighting(this->Normals->GetWeighting());
  this->SeamNormals->SetFeatureAngle(this->Normals->GetFeatureAngle());
  this->SeamNormals->SetSplitting(this->Normals->GetSplitting());
  this->SeamNormals->SetJoinCoincidentPoints(false);
  const char* originalIds = this->Normals->GetOriginalPointIdsArrayName();
  this->SeamPatch->SetOriginalPointIdsArrayName(originalIds ? originalIds : "vtkOriginalPointIds");
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetNormalArray(const char* name)
{
  this->NormalArray = name ? name : "";
  this->ApplyNormalArray();
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::ApplyNormalArray()
{
  // An empty name makes the multiblock maker leave the active normals alone.
  this->Superclass::SetNormalArray(this->ComputesNormals ? "" : this->NormalArray.c_str());
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetLightingModel(int model)
{
  vtkPhongProperty::SafeDownCast(this->Property)->SetLightingModel(model);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetShininess(double shininess)
{
  vtkPhongProperty::SafeDownCast(this->Property)->SetShininess(shininess);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetEmission(double red, double green, double blue)
{
  vtkPhongProperty::SafeDownCast(this->Property)->SetEmission(red, green, blue);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetPerVertexGouraud(int perVertex)
{
  vtkPhongProperty::SafeDownCast(this->Property)->SetPerVertexGouraud(perVertex != 0);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetDebugView(int view)
{
  this->LightingSettings->SetDebugView(view);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetDebugLightIndex(int index)
{
  this->LightingSettings->SetDebugLightIndex(index);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetLightCullingBound(double bound)
{
  this->LightingSettings->SetLightCullingBound(bound);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetErrorBudget(double levels)
{
  this->LightingSettings->SetErrorBudget(levels);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetSpecularAntiAliasing(int on)
{
  this->LightingSettings->SetSpecularAntiAliasing(on != 0);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetLightingWithoutLights(int on)
{
  this->LightingSettings->SetLightingWithoutLights(on != 0);
}

//------------------------------------------------------------------------------
int vtkPhongSurfaceRepresentation::GetUsedBudgetMode()
{
  return vtkPhongCompositePolyDataMapper::SafeDownCast(this->Mapper)->GetBudgetMode();
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetClosedSurfaceCulling(int cull)
{
  this->LightingSettings->SetClosedSurfaceCulling(cull != 0);
}

//------------------------------------------------------------------------------
int vtkPhongSurfaceRepresentation::GetUsedClosedSurfaceCulling()
{
  // The full-resolution mapper's: the level-of-detail one keeps what it did when last used.
  return vtkPhongCompositePolyDataMapper::SafeDownCast(this->Mapper)->GetUsedClosedSurfaceCulling()
    ? 1
    : 0;
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetDepthPrePass(int mode)
{
  this->LightingSettings->SetDepthPrePass(mode);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetDepthPrePassOcclusionCulling(int cull)
{
  this->LightingSettings->SetDepthPrePassOcclusionCulling(cull != 0);
}

//------------------------------------------------------------------------------
int vtkPhongSurfaceRepresentation::GetUsedDepthPrePass()
{
  return vtkPhongCompositePolyDataMapper::SafeDownCast(this->Mapper)->GetUsedDepthPrePass() ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetMaximumNumberOfShaderPrograms(int count)
{
  this->LightingSettings->SetMaximumNumberOfShaderPrograms(count);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetComputeNormals(int mode)
{
  mode = std::min(std::max(mode, static_cast<int>(Never)), static_cast<int>(Always));
  if (this->ComputeNormals != mode)
  {
    this->ComputeNormals = mode;
    // What it means for the data is decided in RequestData, which the change causes; there
    // only the one connection changes (SetupDefaults would also replace the mappers' block
    // attributes, colours and visibilities, and the selection).
    this->MarkModified();
  }
}

//------------------------------------------------------------------------------
bool vtkPhongSurfaceRepresentation::HasPointNormals(vtkDataObject* input)
{
  auto carries = [](vtkDataSet* piece)
  { return piece->GetNumberOfPoints() == 0 || piece->GetPointData()->GetNormals() != nullptr; };
  int all = 0;
  if (auto* piece = vtkDataSet::SafeDownCast(input))
  {
    all = carries(piece);
  }
  else if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    all = 1;
    auto leaves = vtk::TakeSmartPointer(composite->NewIterator());
    for (leaves->InitTraversal(); all && !leaves->IsDoneWithTraversal(); leaves->GoToNextItem())
    {
      auto* leaf = vtkDataSet::SafeDownCast(leaves->GetCurrentDataObject());
      all = leaf && carries(leaf);
    }
  }
  if (vtkPhongSurfaceRepresentation::IsParallel())
  {
    int everywhere = all;
    vtkMultiProcessController::GetGlobalController()->AllReduce(
      &all, &everywhere, 1, vtkCommunicator::MIN_OP);
    all = everywhere;
  }
  return all != 0;
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetNormalsAcrossPieces(int across)
{
  if (this->NormalsAcrossPieces != (across != 0))
  {
    this->NormalsAcrossPieces = across != 0;
    this->MarkModified();
  }
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetNormalsWeighting(int weighting)
{
  if (this->Normals->GetWeighting() != weighting)
  {
    this->Normals->SetWeighting(weighting);
    this->MarkModified();
  }
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetNormalsFeatureAngle(double degrees)
{
  if (this->Normals->GetFeatureAngle() != degrees)
  {
    this->Normals->SetFeatureAngle(degrees);
    this->MarkModified();
  }
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const modes[] = { "Never", "WhereMissing", "Always" };
  os << indent << "ComputeNormals: " << modes[this->ComputeNormals] << "\n";
  os << indent << "ComputesNormals: " << (this->ComputesNormals ? "yes" : "no") << "\n";
  os << indent << "NormalsAcrossPieces: " << (this->NormalsAcrossPieces ? "On" : "Off") << "\n";
  os << indent << "NormalArray: " << (this->NormalArray.empty() ? "(none)" : this->NormalArray)
     << "\n";
  os << indent << "Normals:\n";
  this->Normals->PrintSelf(os, indent.GetNextIndent());
  os << indent << "LightingSettings:\n";
  this->LightingSettings->PrintSelf(os, indent.GetNextIndent());
  os << indent << "GhostCells:\n";
  this->GhostCells->PrintSelf(os, indent.GetNextIndent());
  os << indent << "PatchesSeams: " << (this->PatchesSeams ? "yes" : "no") << "\n";
  os << indent << "SeamFaces:\n";
  this->SeamFaces->PrintSelf(os, indent.GetNextIndent());
  os << indent << "SeamNormals:\n";
  this->SeamNormals->PrintSelf(os, indent.GetNextIndent());
  os << indent << "SeamPatch:\n";
  this->SeamPatch->PrintSelf(os, indent.GetNextIndent());
  os << indent << "GhostStash:\n";
  this->GhostStash->PrintSelf(os, indent.GetNextIndent());
  os << indent << "GhostTrim:\n";
  this->GhostTrim->PrintSelf(os, indent.GetNextIndent());
  os << indent << "GhostRemoval:\n";
  this->GhostRemoval->PrintSelf(os, indent.GetNextIndent());
}
