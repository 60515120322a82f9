#include "vtkPhongGhostCellsStash.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <vector>

vtkStandardNewMacro(vtkPhongGhostCellsStash);

//------------------------------------------------------------------------------
vtkPhongGhostCellsStash::vtkPhongGhostCellsStash() = default;

//------------------------------------------------------------------------------
vtkPhongGhostCellsStash::~vtkPhongGhostCellsStash() = default;

//------------------------------------------------------------------------------
int vtkPhongGhostCellsStash::FillInputPortInformation(int, vtkInformation* info)
{
  // Data sets only: the composite pipeline then runs this filter on each leaf. Other leaves
  // (hyper-tree grids) are passed by the executive as they are.
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  return 1;
}

//------------------------------------------------------------------------------
bool vtkPhongGhostCellsStash::RenameCellArray(vtkDataSet* data, const char* from, const char* to)
{
  vtkCellData* cellData = data->GetCellData();
  vtkDataArray* array = cellData->GetArray(from);
  if (!array)
  {
    return false;
  }
  auto renamed = vtkSmartPointer<vtkDataArray>::Take(array->NewInstance());
  renamed->ShallowCopy(array);
  renamed->SetName(to);
  cellData->RemoveArray(from);
  cellData->AddArray(renamed);
  return true;
}

//------------------------------------------------------------------------------
void vtkPhongGhostCellsStash::TrimGhostCells(vtkPolyData* surface)
{
  vtkDataArray* stashed = surface->GetCellData()->GetArray(StashedGhostArrayName());
  if (!stashed || surface->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()))
  {
    return;
  }
  const vtkIdType cells = surface->GetNumberOfCells();
  auto isGhost = [stashed](vtkIdType cell)
  {
    return (static_cast<int>(stashed->GetComponent(cell, 0)) &
             vtkDataSetAttributes::DUPLICATECELL) != 0;
  };
  std::vector<char> piecePoint(surface->GetNumberOfPoints(), 0);
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (vtkIdType cell = 0; cell < cells; ++cell)
  {
    if (!isGhost(cell))
    {
      surface->GetCellPoints(cell, count, ids);
      for (vtkIdType i = 0; i < count; ++i)
      {
        piecePoint[ids[i]] = 1;
      }
    }
  }
  // vtkPolyData removes cells (with their cell data) by ghost flags: flag the faces to drop
  // in a temporary ghost array, remove them, then drop that array.
  vtkNew<vtkUnsignedCharArray> drop;
  drop->SetName(vtkDataSetAttributes::GhostArrayName());
  drop->SetNumberOfTuples(cells);
  vtkIdType dropped = 0;
  for (vtkIdType cell = 0; cell < cells; ++cell)
  {
    bool touchesPiece = !isGhost(cell);
    surface->GetCellPoints(cell, count, ids);
    for (vtkIdType i = 0; i < count && !touchesPiece; ++i)
    {
      touchesPiece = piecePoint[ids[i]] != 0;
    }
    drop->SetValue(cell, touchesPiece ? 0 : vtkDataSetAttributes::DUPLICATECELL);
    dropped += touchesPiece ? 0 : 1;
  }
  if (dropped > 0)
  {
    surface->GetCellData()->AddArray(drop);
    surface->RemoveGhostCells();
    surface->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  }
}

//------------------------------------------------------------------------------
int vtkPhongGhostCellsStash::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0], 0);
  vtkDataSet* output = vtkDataSet::GetData(outputVector, 0);
  if (!input || !output)
  {
    vtkErrorMacro("Expected a data set in and out.");
    return 0;
  }
  output->ShallowCopy(input);
  const char* ghosts = vtkDataSetAttributes::GhostArrayName();
  auto* polyData = vtkPolyData::SafeDownCast(output);
  switch (this->Mode)
  {
    case Stash:
      vtkPhongGhostCellsStash::RenameCellArray(output, ghosts, StashedGhostArrayName());
      break;
    case Trim:
      if (polyData)
      {
        vtkPhongGhostCellsStash::TrimGhostCells(polyData);
      }
      break;
    default:
      if (vtkPhongGhostCellsStash::RenameCellArray(output, StashedGhostArrayName(), ghosts) &&
        polyData)
      {
        polyData->RemoveGhostCells();
      }
      break;
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkPhongGhostCellsStash::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const names[] = { "Stash", "Trim", "Unstash" };
  os << indent << "Mode: " << names[this->Mode] << "\n";
}
