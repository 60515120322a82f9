#include "vtkPhongValidBlocks.h"

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkObject.h"
#include "vtkPhongCellValidator.h"
#include "vtkPolyData.h"
#include "vtkSetGet.h"

#include <iterator>

//------------------------------------------------------------------------------
vtkPolyData* vtkPhongValidBlocks::Get(vtkPolyData* block, vtkObject* reporter)
{
  if (!block)
  {
    return nullptr;
  }
  // Entries of deleted blocks are dropped whenever the table has doubled since the last
  // pruning: a few words per block, linear time overall.
  if (this->Entries.size() >= 2 * this->SizeAfterPrune + 16)
  {
    this->Prune();
  }
  Entry& entry = this->Entries[block];
  if (entry.Block != block || entry.Time != block->GetMTime())
  {
    entry.Block = block;
    entry.Time = block->GetMTime();
    entry.Copy = nullptr;
    const vtkIdType invalid = vtkPhongCellValidator::CountInvalidCells(block);
    if (invalid > 0)
    {
      if (reporter)
      {
        vtkWarningWithObjectMacro(reporter, << invalid << " cells of a polydata of "
                                            << block->GetNumberOfPoints()
                                            << " points name point ids outside [0, "
                                            << block->GetNumberOfPoints()
                                            << "); they are not drawn.");
      }
      entry.Copy = vtkPhongCellValidator::CollapseInvalidCells(block);
    }
  }
  return entry.Copy ? entry.Copy.Get() : block;
}

//------------------------------------------------------------------------------
bool vtkPhongValidBlocks::AnyInvalid(vtkCompositeDataSet* input, vtkObject* reporter)
{
  bool any = false;
  if (!input)
  {
    return any;
  }
  vtkSmartPointer<vtkCompositeDataIterator> leaves;
  leaves.TakeReference(input->NewIterator());
  for (leaves->InitTraversal(); !leaves->IsDoneWithTraversal(); leaves->GoToNextItem())
  {
    auto* block = vtkPolyData::SafeDownCast(leaves->GetCurrentDataObject());
    any = (block && this->Get(block, reporter) != block) || any;
  }
  return any;
}

//------------------------------------------------------------------------------
void vtkPhongValidBlocks::Prune()
{
  for (auto entry = this->Entries.begin(); entry != this->Entries.end();)
  {
    entry = entry->second.Block ? std::next(entry) : this->Entries.erase(entry);
  }
  this->SizeAfterPrune = this->Entries.size();
}
