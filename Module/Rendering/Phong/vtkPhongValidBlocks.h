/**
 * @class   vtkPhongValidBlocks
 * @brief   the mappers' view of their polydata with cells naming missing points collapsed
 *
 * VTK's bounds (vtkPolyData::GetCellsBounds) and buffer upload read points through the cell
 * ids unchecked, so a cell naming a point that does not exist makes them read out of bounds.
 * Each mapper asks this cache for the polydata it draws: the block itself when all its cells
 * are valid, else a copy made by vtkPhongCellValidator::CollapseInvalidCells (every cell kept
 * with its size and id, the bad ones collapsed onto an existing point). A block is scanned
 * once per modification and reported once, with a warning naming the mapper.
 *
 * Private to the rendering module; used by vtkPhongPolyDataMapper (one block: its input) and
 * by vtkPhongCompositePolyDataMapper and its block mappers (every leaf).
 *
 * @sa vtkPhongCellValidator
 */

#ifndef vtkPhongValidBlocks_h
#define vtkPhongValidBlocks_h

#include "vtkSmartPointer.h"
#include "vtkType.h"
#include "vtkWeakPointer.h"

#include <cstddef>
#include <map>

class vtkCompositeDataSet;
class vtkObject;
class vtkPolyData;

class vtkPhongValidBlocks
{
public:
  /**
   * The block when its cells are valid, else its collapsed copy (nullptr for nullptr). A
   * block seen for the first time or modified since is scanned, and its invalid cells are
   * reported through `reporter` (may be nullptr: no report).
   */
  vtkPolyData* Get(vtkPolyData* block, vtkObject* reporter);

  /**
   * Whether any polydata leaf of `input` (or `input` itself when it is polydata) has cells
   * naming missing points. Scans through Get, so the copies are ready for drawing.
   */
  bool AnyInvalid(vtkCompositeDataSet* input, vtkObject* reporter);

  /**
   * Drops the entries of blocks that no longer exist (Get also does, as the table grows).
   */
  void Prune();

private:
  struct Entry
  {
    vtkWeakPointer<vtkPolyData> Block; // to tell a reused address from the block
    vtkMTimeType Time = 0;
    vtkSmartPointer<vtkPolyData> Copy; // nullptr when the block is valid
  };
  std::map<vtkPolyData*, Entry> Entries;
  std::size_t SizeAfterPrune = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongValidBlocks.h
