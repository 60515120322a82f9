/**
 * @class   vtkPhongSeamFacesExchange
 * @brief   gives each rank's polydata piece, as ghost cells, the other ranks' faces around
 *          the points where their pieces meet
 *
 * Under MPI each rank computes the normals of its own piece, and a point on a cut between
 * pieces gets the same normal on every rank only when each rank sees all the faces around
 * it. vtkGhostCellsGenerator gives a piece a whole level of ghost cells, at a cost that
 * grows with the piece (about 48 s and 2.9 GB a rank for a 16M-triangle surface on 2
 * ranks). For polydata the points on a cut are known without it: a point where pieces meet
 * is on a boundary edge of each piece (its fan of faces is open on every rank). So this
 * filter, collective over the controller's ranks:
 *
 * 1. finds its piece's boundary points (a point is interior when each of its neighbours in
 *    its faces is named by two of them: their hashes cancel);
 * 2. gathers every rank's boundary points' positions (a small exchange: cuts, not pieces);
 * 3. matches its boundary points to each other rank's, within Tolerance times the diagonal
 *    of all pieces' bounds (pieces hold their own copies of the points on their cuts, which
 *    a source may compute a float step apart);
 * 4. sends each rank that matched the faces around the matched points (polygons and strip
 *    triangles, with their point and cell data), and receives that rank's;
 * 5. outputs its piece with the received faces appended as polygons flagged
 *    vtkDataSetAttributes::DUPLICATECELL (ghost cells), each received point that matches
 *    one of its boundary points replaced by that point, so the faces share its vertices.
 *
 * The input's own ghost cells, if any, are removed first (their faces would count twice).
 * With one rank, or no match, the output is the input (a shallow copy).
 *
 * Points that two pieces share without either piece's fan being open there (two sheets
 * touching at a vertex inside both) are not found: the seams of a partitioned surface are.
 *
 * @sa vtkPhongSurfaceRepresentation vtkPhongGhostCellsStash vtkOpenMeshNormals
 */

#ifndef vtkPhongSeamFacesExchange_h
#define vtkPhongSeamFacesExchange_h

#include "vtkPhongRepresentationsModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class vtkMultiProcessController;

class VTKPHONGREPRESENTATIONS_EXPORT vtkPhongSeamFacesExchange : public vtkPolyDataAlgorithm
{
public:
  static vtkPhongSeamFacesExchange* New();
  vtkTypeMacro(vtkPhongSeamFacesExchange, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The ranks that exchange. Default: the global controller at construction (none: the
   * output is the input).
   */
  virtual void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  ///@{
  /**
   * How far apart two pieces' copies of a point may be, as a fraction of the diagonal of
   * all pieces' bounds. Default 1e-6, [0, 1e-3].
   */
  vtkSetClampMacro(Tolerance, double, 0.0, 1e-3);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /**
   * What the last execution did: the boundary points of this rank's piece, the ranks it
   * exchanged faces with, and the faces it received (the ghost cells it appended).
   */
  vtkGetMacro(NumberOfBoundaryPoints, vtkIdType);
  vtkGetMacro(NumberOfPartners, int);
  vtkGetMacro(NumberOfReceivedFaces, vtkIdType);
  ///@}

protected:
  vtkPhongSeamFacesExchange();
  ~vtkPhongSeamFacesExchange() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  vtkMultiProcessController* Controller = nullptr;
  double Tolerance = 1e-6;
  vtkIdType NumberOfBoundaryPoints = 0;
  int NumberOfPartners = 0;
  vtkIdType NumberOfReceivedFaces = 0;

private:
  vtkPhongSeamFacesExchange(const vtkPhongSeamFacesExchange&) = delete;
  void operator=(const vtkPhongSeamFacesExchange&) = delete;
};

#endif
