/**
 * @class   vtkPhongCellValidator
 * @brief   finds cells that name points a polydata does not have, and collapses them
 *
 * A cell whose connectivity names a point id below 0 or not below the number of points makes
 * every consumer read or write out of bounds: VTK's own bounds (vtkPolyData::GetCellsBounds),
 * its buffer upload, and any normals computation. Readers make such data from broken files,
 * and user code can build it by hand. vtkOpenMeshNormals and vtkPhongPolyDataMapper check
 * their input with this class before they touch a cell.
 *
 * The check is one pass over the connectivity (a range test of each cell array first, so valid
 * data costs a min/max scan). Cells that fail are collapsed, not removed: each missing point
 * is replaced by the cell's first existing point (point 0 if it has none), so the cell keeps
 * its size and its id, and every cell's data stays where it was. A collapsed polygon, strip or
 * line has no area or length and draws nothing (the normals filter counts it as degenerate);
 * a collapsed vertex draws its point. Empty cells would be simpler but VTK's own cell map
 * (vtkPolyData::BuildCells, used by GetCell and picking) refuses them.
 *
 * @sa vtkOpenMeshNormals
 */

#ifndef vtkPhongCellValidator_h
#define vtkPhongCellValidator_h

#include "vtkCommonPhongModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for the return value

class vtkCellArray;
class vtkPolyData;

class VTKCOMMONPHONG_EXPORT vtkPhongCellValidator : public vtkObject
{
public:
  static vtkPhongCellValidator* New();
  vtkTypeMacro(vtkPhongCellValidator, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The number of cells (verts, lines, polys, strips) of the polydata that name a point id
   * outside [0, number of points). 0 for nullptr.
   */
  static vtkIdType CountInvalidCells(vtkPolyData* polyData);

  /**
   * A shallow copy of the polydata in which every cell that names a missing point is
   * collapsed; the polydata itself when no cell does (or for nullptr). A polydata without
   * points but with cells gives an empty polydata.
   */
  static vtkSmartPointer<vtkPolyData> CollapseInvalidCells(vtkPolyData* polyData);

protected:
  vtkPhongCellValidator() = default;
  ~vtkPhongCellValidator() override = default;

private:
  vtkPhongCellValidator(const vtkPhongCellValidator&) = delete;
  void operator=(const vtkPhongCellValidator&) = delete;

  static bool AllIdsInRange(vtkCellArray* cells, vtkIdType numberOfPoints);
  static vtkIdType CountInvalidCells(vtkCellArray* cells, vtkIdType numberOfPoints);
  static vtkSmartPointer<vtkCellArray> CollapseInvalidCells(
    vtkCellArray* cells, vtkIdType numberOfPoints);
};

#endif
