/**
 * @class   vtkPhongGhostCellsStash
 * @brief   hides a piece's ghost cells from ParaView's geometry filter until normals are made
 *
 * Under MPI each rank computes the normals of its own piece. A point where pieces meet gets
 * the same normal on every rank only when each rank sees all the faces around it, that is
 * its piece with one level of ghost cells. ParaView's vtkPVGeometryFilter removes ghost
 * cells from the surface it extracts (ParaView 5.11 and 5.13 alike), before any filter that
 * follows it could use them. vtkPhongSurfaceRepresentation therefore puts this filter twice
 * around its geometry filter and normals:
 *
 * - Stash on (before the geometry filter): the ghost-cell flags (vtkGhostType in the cell
 *   data) are renamed StashedGhostArrayName(), so the geometry filter extracts the surface
 *   of the piece and its ghost cells together and passes the renamed flags along as an
 *   ordinary cell array;
 * - Stash off (after the normals): the ghost cells are removed from polydata (their points
 *   stay, unused), so the view draws each cell once, and the flags with them; other data
 *   gets its flags back under their name.
 *
 * Data without ghost cells passes through unchanged (shallow copies). Composite data is
 * handled leaf by leaf by the composite pipeline; other data objects pass through.
 *
 * @sa vtkPhongSurfaceRepresentation vtkOpenMeshNormals
 */

#ifndef vtkPhongGhostCellsStash_h
#define vtkPhongGhostCellsStash_h

#include "vtkPassInputTypeAlgorithm.h"
#include "vtkPhongRepresentationsModule.h" // for export macro

#include <vector> // for std::vector

class vtkDataArray;
class vtkDataSet;
class vtkPolyData;

class VTKPHONGREPRESENTATIONS_EXPORT vtkPhongGhostCellsStash : public vtkPassInputTypeAlgorithm
{
public:
  static vtkPhongGhostCellsStash* New();
  vtkTypeMacro(vtkPhongGhostCellsStash, vtkPassInputTypeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Modes
  {
    Stash = 0,
    Trim = 1,
    Unstash = 2
  };

  ///@{
  /**
   * What this stage does (Modes, above): Stash (default), Trim or Unstash.
   */
  vtkSetClampMacro(Mode, int, Stash, Unstash);
  vtkGetMacro(Mode, int);
  void SetModeToStash() { this->SetMode(Stash); }
  void SetModeToTrim() { this->SetMode(Trim); }
  void SetModeToUnstash() { this->SetMode(Unstash); }
  ///@}

  /**
   * The name the ghost-cell flags carry between the two stages.
   */
  static const char* StashedGhostArrayName() { return "vtkPhongStashedGhostType"; }

  /**
   * Per tuple of `flags` (ghost-cell flags, stashed or not): whether they make the cell a
   * ghost that vtkPolyData::RemoveGhostCells would remove (a duplicate or a hidden cell).
   */
  static std::vector<char> GhostFlags(vtkDataArray* flags);

protected:
  vtkPhongGhostCellsStash();
  ~vtkPhongGhostCellsStash() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /**
   * Give the cell array `from` the name `to` (a shallow copy of it: the input is never
   * touched). Returns false when there is no array `from`.
   */
  static bool RenameCellArray(vtkDataSet* data, const char* from, const char* to);

  /**
   * Remove the stashed ghost cells that share no point with a cell of the piece.
   */
  static void TrimGhostCells(vtkPolyData* surface);

  int Mode = Stash;

private:
  vtkPhongGhostCellsStash(const vtkPhongGhostCellsStash&) = delete;
  void operator=(const vtkPhongGhostCellsStash&) = delete;
};

#endif
