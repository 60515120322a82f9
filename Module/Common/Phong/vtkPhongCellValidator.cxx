#include "vtkPhongCellValidator.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <vector>

vtkStandardNewMacro(vtkPhongCellValidator);

namespace
{
bool IdsInRange(vtkIdType size, const vtkIdType* ids, vtkIdType numberOfPoints)
{
  for (vtkIdType i = 0; i < size; ++i)
  {
    if (ids[i] < 0 || ids[i] >= numberOfPoints)
    {
      return false;
    }
  }
  return true;
}

// The cell arrays of a polydata, in VTK's cell id order.
std::array<vtkCellArray*, 4> CellArraysOf(vtkPolyData* polyData)
{
  return { polyData->GetVerts(), polyData->GetLines(), polyData->GetPolys(),
    polyData->GetStrips() };
}
}

//------------------------------------------------------------------------------
bool vtkPhongCellValidator::AllIdsInRange(vtkCellArray* cells, vtkIdType numberOfPoints)
{
  if (!cells || cells->GetNumberOfConnectivityIds() == 0)
  {
    return true;
  }
  double range[2];
  cells->GetConnectivityArray()->GetRange(range, 0);
  return range[0] >= 0.0 && range[1] < static_cast<double>(numberOfPoints);
}

//------------------------------------------------------------------------------
vtkIdType vtkPhongCellValidator::CountInvalidCells(vtkCellArray* cells, vtkIdType numberOfPoints)
{
  if (AllIdsInRange(cells, numberOfPoints))
  {
    return 0;
  }
  vtkIdType invalid = 0;
  auto iterator = vtk::TakeSmartPointer(cells->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    invalid += IdsInRange(size, ids, numberOfPoints) ? 0 : 1;
  }
  return invalid;
}

//------------------------------------------------------------------------------
vtkIdType vtkPhongCellValidator::CountInvalidCells(vtkPolyData* polyData)
{
  if (!polyData)
  {
    return 0;
  }
  vtkIdType invalid = 0;
  for (vtkCellArray* cells : CellArraysOf(polyData))
  {
    invalid += CountInvalidCells(cells, polyData->GetNumberOfPoints());
  }
  return invalid;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkCellArray> vtkPhongCellValidator::CollapseInvalidCells(
  vtkCellArray* cells, vtkIdType numberOfPoints)
{
  if (AllIdsInRange(cells, numberOfPoints))
  {
    return cells;
  }
  vtkNew<vtkCellArray> valid;
  valid->AllocateExact(cells->GetNumberOfCells(), cells->GetNumberOfConnectivityIds());
  std::vector<vtkIdType> collapsed;
  auto iterator = vtk::TakeSmartPointer(cells->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    if (IdsInRange(size, ids, numberOfPoints))
    {
      valid->InsertNextCell(size, ids);
      continue;
    }
    const vtkIdType* found = std::find_if(
      ids, ids + size, [numberOfPoints](vtkIdType id) { return id >= 0 && id < numberOfPoints; });
    collapsed.assign(size, found != ids + size ? *found : 0);
    valid->InsertNextCell(size, collapsed.data());
  }
  return valid;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkPhongCellValidator::CollapseInvalidCells(vtkPolyData* polyData)
{
  if (CountInvalidCells(polyData) == 0)
  {
    return polyData;
  }
  const vtkIdType numberOfPoints = polyData->GetNumberOfPoints();
  if (numberOfPoints == 0)
  {
    return vtkSmartPointer<vtkPolyData>::New(); // no point for a cell to collapse onto
  }
  auto valid = vtkSmartPointer<vtkPolyData>::New();
  valid->ShallowCopy(polyData);
  valid->SetVerts(CollapseInvalidCells(polyData->GetVerts(), numberOfPoints));
  valid->SetLines(CollapseInvalidCells(polyData->GetLines(), numberOfPoints));
  valid->SetPolys(CollapseInvalidCells(polyData->GetPolys(), numberOfPoints));
  valid->SetStrips(CollapseInvalidCells(polyData->GetStrips(), numberOfPoints));
  return valid;
}

//------------------------------------------------------------------------------
void vtkPhongCellValidator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
