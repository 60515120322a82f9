#include "vtkOpenMeshNormals.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenMeshNormalsExecution.h"
#include "vtkOpenMeshNormalsJoin.h"
#include "vtkOpenMeshNormalsPointByPoint.h"
#include "vtkOpenMeshNormalsTopology.h"
#include "vtkPhongCellValidator.h"
#include "vtkPhongClampedSetter.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkOpenMeshNormals);

// What the filter keeps between executions: the topology, reused while only
// the points move, and the arrays of the executions, whose memory is reused.
struct vtkOpenMeshNormals::Internals
{
  vtkOpenMeshNormalsTopology Topology;
  vtkOpenMeshNormalsWorkspace Workspace;
  // The cells of the last execution computed point by point: the same cells again (only the
  // points moved) are an animation, which the kept topology serves faster.
  vtkOpenMeshNormalsDetail::CellsStamp PointByPointCells;
};

//------------------------------------------------------------------------------
vtkOpenMeshNormals::vtkOpenMeshNormals()
  : Internal(new Internals)
{
  this->SetOriginalPointIdsArrayName("vtkOriginalPointIds");
}

//------------------------------------------------------------------------------
vtkOpenMeshNormals::~vtkOpenMeshNormals()
{
  this->SetOriginalPointIdsArrayName(nullptr);
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormals::SetFeatureAngle(double angle)
{
  vtkPhongSetClamped(this, "FeatureAngle", this->FeatureAngle, angle, 0.0, 180.0);
}

//------------------------------------------------------------------------------
const char* vtkOpenMeshNormals::GetWeightingAsString()
{
  switch (this->Weighting)
  {
    case Uniform:
      return "Uniform";
    case Area:
      return "Area";
    case Angle:
      return "Angle";
    case Max:
    default:
      return "Max";
  }
}

//------------------------------------------------------------------------------
// The steps of docs/normals.md, in order; each is one call.
int vtkOpenMeshNormals::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfInvalidCells = this->NumberOfNonManifoldFaces = 0;
  this->NumberOfFacesWithRepeatedPoints = 0;
  this->NumberOfDegenerateFaces = this->NumberOfReorientedFaces = this->NumberOfSplitPoints = 0;
  this->NumberOfJoinedPoints = 0;
  this->TopologyReused = this->ComputedPointByPoint = false;
  const vtkSmartPointer<vtkPolyData> input =
    this->CheckCellPointIds(vtkPolyData::GetData(inputVector[0]));
  if (!input || !input->GetPoints() || input->GetNumberOfPoints() == 0)
  {
    output->ShallowCopy(input); // empty input: nothing to compute
    return 1;
  }
  const std::vector<vtkIdType> representative =
    this->JoinCoincidentPoints && this->ComputePointNormals
    ? vtkOpenMeshNormalsJoin::Representatives(input, this->JoinTolerance)
    : std::vector<vtkIdType>();
  const bool computed = representative.empty()
    ? this->ComputeNormals(input, output)
    : this->ComputeJoinedNormals(input, representative, output);
  if (!computed)
  {
    output->Initialize(); // aborted, or too large
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkOpenMeshNormals::ComputeJoinedNormals(
  vtkPolyData* input, const std::vector<vtkIdType>& representative, vtkPolyData* output)
{
  vtkNew<vtkPolyData> joinedOutput;
  if (!this->ComputeNormals(
        vtkOpenMeshNormalsJoin::JoinedCopy(input, representative), joinedOutput))
  {
    return false;
  }
  const bool splitting = this->Splitting && this->ComputePointNormals;
  vtkOpenMeshNormalsJoin::GiveNormalsBack(
    input, representative, joinedOutput, output, splitting ? this->OriginalIdsName() : nullptr);
  this->NumberOfSplitPoints = output->GetNumberOfPoints() - input->GetNumberOfPoints();
  this->NumberOfJoinedPoints = 0;
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(representative.size()); ++p)
  {
    this->NumberOfJoinedPoints += representative[p] != p ? 1 : 0;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenMeshNormals::ComputeNormals(vtkPolyData* input, vtkPolyData* output)
{
  if (this->MayComputePointByPoint(input))
  {
    const vtkOpenMeshNormalsPointByPoint::Settings settings{ this->Weighting, this->FeatureAngle,
      this->Splitting != 0, this->OriginalIdsName() };
    switch (vtkOpenMeshNormalsPointByPoint::Compute(settings, input, output, this))
    {
      case vtkOpenMeshNormalsPointByPoint::Result::Computed:
        this->ComputedPointByPoint = true;
        this->Internal.reset(new Internals); // a topology of other cells: its memory back
        this->Internal->PointByPointCells.Record(input);
        return true;
      case vtkOpenMeshNormalsPointByPoint::Result::Aborted:
        return false;
      case vtkOpenMeshNormalsPointByPoint::Result::NeedsTopology:
        break;
    }
  }
  if (!this->UpdateTopology(input))
  {
    return false;
  }

  const vtkOpenMeshNormalsExecution::Settings settings{ this->Weighting, this->FeatureAngle,
    this->Splitting && this->ComputePointNormals, this->ComputeCellNormals != 0,
    this->AutoOrientNormals != 0, this->FlipNormals != 0, this->OriginalIdsName() };
  vtkOpenMeshNormalsExecution execution(
    settings, this->Internal->Topology, this->Internal->Workspace, input, output);
  execution.LoadPositions();
  execution.ComputeFaceNormals();
  this->NumberOfReorientedFaces = execution.OrientComponents();
  this->UpdateProgress(0.75);
  if (this->GetAbortExecute())
  {
    return false;
  }

  if (this->ComputePointNormals && !this->Splitting)
  {
    execution.ComputeSharedPointNormals();
  }
  else if (this->ComputePointNormals)
  {
    execution.CutFans();
    this->NumberOfSplitPoints = execution.NumberWedges();
    execution.StoreWedgeNormals();
    execution.FindSplitSources();
  }
  this->UpdateProgress(0.9);
  if (this->GetAbortExecute())
  {
    return false;
  }

  execution.BuildOutputPolys();
  execution.WritePoints();
  execution.WriteCells();
  return true;
}

//------------------------------------------------------------------------------
const char* vtkOpenMeshNormals::OriginalIdsName() const
{
  return this->OriginalPointIdsArrayName ? this->OriginalPointIdsArrayName : "vtkOriginalPointIds";
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkOpenMeshNormals::CheckCellPointIds(vtkPolyData* input)
{
  this->NumberOfInvalidCells = vtkPhongCellValidator::CountInvalidCells(input);
  if (this->NumberOfInvalidCells == 0)
  {
    return input;
  }
  vtkWarningMacro(<< this->NumberOfInvalidCells << " cells name point ids outside [0, "
                  << input->GetNumberOfPoints()
                  << "); they are collapsed onto one of their points (vtkPhongCellValidator) and "
                     "have no normal.");
  return vtkPhongCellValidator::CollapseInvalidCells(input);
}

//------------------------------------------------------------------------------
bool vtkOpenMeshNormals::MayComputePointByPoint(vtkPolyData* input) const
{
  return this->PointByPoint && this->ComputePointNormals && !this->ComputeCellNormals &&
    !this->AutoOrientNormals && !this->FlipNormals && !this->IncrementalConstruction &&
    !this->AlwaysHalfedgeMesh && !this->Internal->PointByPointCells.Matches(input) &&
    !this->Internal->Topology.Matches(input, this->Consistency || this->AutoOrientNormals,
      this->NonManifoldTraversal != 0, false, false) &&
    vtkOpenMeshNormalsPointByPoint::Takes(input);
}

//------------------------------------------------------------------------------
// Reuses the topology when only the points changed, else builds it; false if
// building failed (aborted, or a mesh too large).
bool vtkOpenMeshNormals::UpdateTopology(vtkPolyData* input)
{
  vtkOpenMeshNormalsTopology& topology = this->Internal->Topology;
  const bool consistency = this->Consistency || this->AutoOrientNormals;
  const bool traversal = this->NonManifoldTraversal != 0;
  const bool incremental = this->IncrementalConstruction != 0;
  const bool halfedgeMesh = this->AlwaysHalfedgeMesh != 0;
  if (topology.Matches(input, consistency, traversal, incremental, halfedgeMesh))
  {
    this->TopologyReused = true;
  }
  else
  {
    this->Internal->Workspace.LastPolys = nullptr; // made from other connectivity
    if (!topology.Build(input, consistency, traversal, incremental, halfedgeMesh, this))
    {
      return false;
    }
  }
  this->NumberOfNonManifoldFaces = topology.NonManifoldFaces;
  this->NumberOfFacesWithRepeatedPoints = topology.RepeatedPointFaces;
  this->NumberOfDegenerateFaces = topology.DegenerateFaces;
  if (topology.NonManifoldFaces && !this->TopologyReused)
  {
    vtkWarningMacro(<< topology.NonManifoldFaces
                    << " faces made an edge or a vertex non-manifold; each got its own copies "
                       "of its vertices (it keeps its own normals at those vertices).");
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormals::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Weighting: " << this->GetWeightingAsString() << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "Splitting: " << (this->Splitting ? "On" : "Off") << "\n";
  os << indent << "Consistency: " << (this->Consistency ? "On" : "Off") << "\n";
  os << indent << "AutoOrientNormals: " << (this->AutoOrientNormals ? "On" : "Off") << "\n";
  os << indent << "ComputePointNormals: " << (this->ComputePointNormals ? "On" : "Off") << "\n";
  os << indent << "ComputeCellNormals: " << (this->ComputeCellNormals ? "On" : "Off") << "\n";
  os << indent << "FlipNormals: " << (this->FlipNormals ? "On" : "Off") << "\n";
  os << indent << "NonManifoldTraversal: " << (this->NonManifoldTraversal ? "On" : "Off") << "\n";
  os << indent << "IncrementalConstruction: " << (this->IncrementalConstruction ? "On" : "Off")
     << "\n";
  os << indent << "AlwaysHalfedgeMesh: " << (this->AlwaysHalfedgeMesh ? "On" : "Off") << "\n";
  os << indent << "PointByPoint: " << (this->PointByPoint ? "On" : "Off") << "\n";
  os << indent << "JoinCoincidentPoints: " << (this->JoinCoincidentPoints ? "On" : "Off") << "\n";
  os << indent << "JoinTolerance: " << this->JoinTolerance << "\n";
  os << indent << "OriginalPointIdsArrayName: "
     << (this->OriginalPointIdsArrayName ? this->OriginalPointIdsArrayName : "(none)") << "\n";
  os << indent << "NumberOfInvalidCells: " << this->NumberOfInvalidCells << "\n";
  os << indent << "NumberOfNonManifoldFaces: " << this->NumberOfNonManifoldFaces << "\n";
  os << indent << "NumberOfFacesWithRepeatedPoints: " << this->NumberOfFacesWithRepeatedPoints
     << "\n";
  os << indent << "NumberOfDegenerateFaces: " << this->NumberOfDegenerateFaces << "\n";
  os << indent << "NumberOfReorientedFaces: " << this->NumberOfReorientedFaces << "\n";
  os << indent << "NumberOfSplitPoints: " << this->NumberOfSplitPoints << "\n";
  os << indent << "NumberOfJoinedPoints: " << this->NumberOfJoinedPoints << "\n";
  os << indent << "TopologyReused: " << (this->TopologyReused ? "yes" : "no") << "\n";
  os << indent << "ComputedPointByPoint: " << (this->ComputedPointByPoint ? "yes" : "no") << "\n";
}
