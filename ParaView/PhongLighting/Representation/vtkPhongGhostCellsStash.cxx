#include "vtkPhongGhostCellsStash.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
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

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkPhongGhostCellsStash);

namespace
{
// Calls cell(cellId, size, ids) for every cell, in the polydata's order of cells.
template <typename Cell>
void ForEachCell(vtkPolyData* surface, Cell&& cell)
{
  vtkIdType cellId = 0;
  for (vtkCellArray* cells :
    { surface->GetVerts(), surface->GetLines(), surface->GetPolys(), surface->GetStrips() })
  {
    auto iterator = vtk::TakeSmartPointer(cells->NewIterator());
    for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal();
         iterator->GoToNextCell(), ++cellId)
    {
      vtkIdType size;
      const vtkIdType* ids;
      iterator->GetCurrentCell(size, ids);
      cell(cellId, size, ids);
    }
  }
}

// The cell array without the cells whose flag (from `first` on) is set.
vtkSmartPointer<vtkCellArray> KeptCells(
  vtkCellArray* cells, const std::vector<char>& remove, vtkIdType first)
{
  const vtkIdType count = cells->GetNumberOfCells();
  if (std::none_of(
        remove.begin() + first, remove.begin() + first + count, [](char r) { return r != 0; }))
  {
    return cells;
  }
  auto kept = vtkSmartPointer<vtkCellArray>::New();
  kept->AllocateExact(count, cells->GetNumberOfConnectivityIds());
  auto iterator = vtk::TakeSmartPointer(cells->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    if (!remove[first + iterator->GetCurrentCellId()])
    {
      vtkIdType size;
      const vtkIdType* ids;
      iterator->GetCurrentCell(size, ids);
      kept->InsertNextCell(size, ids);
    }
  }
  return kept;
}

// Removes the flagged cells with their cell data, in blocks. Every point stays (a removed
// ghost cell's own points are left unused): vtkPolyData::RemoveGhostCells copies every
// cell and point one at a time, about 10 s for 8M triangles.
void RemoveCells(vtkPolyData* surface, const std::vector<char>& remove)
{
  const vtkIdType total = surface->GetNumberOfCells();
  const vtkIdType removed = std::count(remove.begin(), remove.end(), 1);
  if (removed == 0 || static_cast<vtkIdType>(remove.size()) != total)
  {
    return;
  }
  const vtkIdType verts = surface->GetNumberOfVerts(), lines = surface->GetNumberOfLines();
  const vtkIdType polys = surface->GetNumberOfPolys();
  auto keptVerts = KeptCells(surface->GetVerts(), remove, 0);
  auto keptLines = KeptCells(surface->GetLines(), remove, verts);
  auto keptPolys = KeptCells(surface->GetPolys(), remove, verts + lines);
  auto keptStrips = KeptCells(surface->GetStrips(), remove, verts + lines + polys);
  vtkCellData* cellData = surface->GetCellData();
  vtkNew<vtkCellData> keptData;
  keptData->CopyAllOn(vtkDataSetAttributes::COPYTUPLE);
  keptData->CopyAllocate(cellData, total - removed);
  vtkIdType to = 0;
  for (vtkIdType from = 0; from < total;)
  {
    vtkIdType end = from;
    while (end < total && !remove[end])
    {
      ++end;
    }
    keptData->CopyData(cellData, to, end - from, from);
    to += end - from;
    from = end + 1; // past the removed cell
  }
  surface->DeleteCells();
  surface->SetVerts(keptVerts);
  surface->SetLines(keptLines);
  surface->SetPolys(keptPolys);
  surface->SetStrips(keptStrips);
  cellData->ShallowCopy(keptData);
}
}

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
std::vector<char> vtkPhongGhostCellsStash::GhostFlags(vtkDataArray* flags)
{
  const int ghost = vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL;
  std::vector<char> isGhost(static_cast<size_t>(flags->GetNumberOfTuples()));
  for (vtkIdType cell = 0; cell < flags->GetNumberOfTuples(); ++cell)
  {
    isGhost[cell] = (static_cast<int>(flags->GetComponent(cell, 0)) & ghost) != 0;
  }
  return isGhost;
}

//------------------------------------------------------------------------------
void vtkPhongGhostCellsStash::TrimGhostCells(vtkPolyData* surface)
{
  vtkDataArray* stashed = surface->GetCellData()->GetArray(StashedGhostArrayName());
  if (!stashed || surface->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()))
  {
    return;
  }
  const std::vector<char> ghost = GhostFlags(stashed);
  if (std::none_of(ghost.begin(), ghost.end(), [](char g) { return g != 0; }))
  {
    return;
  }
  const vtkIdType points = surface->GetNumberOfPoints();
  auto inSurface = [points](vtkIdType p) { return p >= 0 && p < points; };
  std::vector<char> piecePoint(static_cast<size_t>(points), 0);
  ForEachCell(surface,
    [&](vtkIdType cell, vtkIdType size, const vtkIdType* ids)
    {
      for (vtkIdType i = 0; i < size && !ghost[cell]; ++i)
      {
        if (inSurface(ids[i]))
        {
          piecePoint[ids[i]] = 1;
        }
      }
    });
  std::vector<char> drop(ghost.size(), 0);
  ForEachCell(surface,
    [&](vtkIdType cell, vtkIdType size, const vtkIdType* ids)
    {
      drop[cell] = ghost[cell] &&
        std::none_of(ids, ids + size, [&](vtkIdType p) { return inSurface(p) && piecePoint[p]; });
    });
  RemoveCells(surface, drop);
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
      if (!polyData)
      {
        vtkPhongGhostCellsStash::RenameCellArray(output, StashedGhostArrayName(), ghosts);
      }
      else if (vtkDataArray* stashed = polyData->GetCellData()->GetArray(StashedGhostArrayName()))
      {
        const std::vector<char> ghost = vtkPhongGhostCellsStash::GhostFlags(stashed);
        polyData->GetCellData()->RemoveArray(StashedGhostArrayName());
        RemoveCells(polyData, ghost);
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
