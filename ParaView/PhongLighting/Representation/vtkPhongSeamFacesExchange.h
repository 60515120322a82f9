/**
 * @class   vtkPhongSeamFacesExchange
 * @brief   the faces around the points where MPI ranks' polydata pieces meet, gathered
 *          from every rank that holds some
 *
 * Under MPI each rank computes the normals of its own piece, and a point on a cut between
 * pieces gets the normal of the whole surface only from all the faces around it.
 * vtkGhostCellsGenerator gives a piece a whole level of ghost cells, at a cost that grows
 * with the piece (about 48 s and 2.9 GB a rank for a 16M-triangle surface on 2 ranks), and
 * appending faces to the piece and removing them after the normals copies it twice. Only
 * the cut points' normals are wrong without it, and for polydata those points are known: a
 * point where pieces meet is on a boundary edge of each piece (its fan of faces is open on
 * every rank). So this filter, collective over the controller's ranks:
 *
 * 1. finds its piece's boundary points (a point is interior when each of its neighbours in
 *    its faces is named by two of them: their hashes cancel);
 * 2. gathers every rank's boundary points' positions (a small exchange: cuts, not pieces);
 * 3. matches its boundary points to each other rank's, within Tolerance times the diagonal
 *    of all pieces' bounds (pieces hold their own copies of the points on their cuts, which
 *    a source may compute a float step apart);
 * 4. sends each rank that matched the faces around the matched points (polygons and strip
 *    triangles; positions only), and receives that rank's;
 * 5. outputs the seam mesh: its piece's faces around its matched points (its cut points)
 *    and the received faces, the received copies of its cut points replaced by its own, and
 *    the point array PiecePointIdsArrayName() giving each cut point's id in the piece (-1
 *    for every other point: its fan is partial here).
 *
 * The normals of the seam mesh at the cut points are the whole surface's there;
 * vtkPhongSeamNormalsPatch puts them into the piece's normals. Ghost cells of the input
 * (flagged in vtkGhostType, or in vtkPhongGhostCellsStash's renamed array) are left out.
 * With one rank, Enabled off or no match, the output is empty.
 *
 * Points that two pieces share without either piece's fan being open there (two sheets
 * touching at a vertex inside both) are not found: the seams of a partitioned surface are.
 *
 * @sa vtkPhongSeamNormalsPatch vtkPhongSurfaceRepresentation vtkOpenMeshNormals
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
   * Whether the filter exchanges at all (default on); off, its output is empty and it makes
   * no collective call. Every rank must set the same.
   */
  vtkSetMacro(Enabled, vtkTypeBool);
  vtkGetMacro(Enabled, vtkTypeBool);
  vtkBooleanMacro(Enabled, vtkTypeBool);
  ///@}

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
   * exchanged faces with, and the faces it received.
   */
  vtkGetMacro(NumberOfBoundaryPoints, vtkIdType);
  vtkGetMacro(NumberOfPartners, int);
  vtkGetMacro(NumberOfReceivedFaces, vtkIdType);
  ///@}

  /**
   * The seam mesh's point array of each cut point's id in the piece (-1: any other point).
   */
  static const char* PiecePointIdsArrayName() { return "vtkPhongPiecePointIds"; }

protected:
  vtkPhongSeamFacesExchange();
  ~vtkPhongSeamFacesExchange() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  vtkTypeBool Enabled = 1;
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
