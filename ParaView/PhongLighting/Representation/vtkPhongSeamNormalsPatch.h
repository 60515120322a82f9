/**
 * @class   vtkPhongSeamNormalsPatch
 * @brief   gives the points where MPI ranks' pieces meet the normals of the whole surface
 *
 * Input 0: a rank's piece with the point normals computed on that piece alone
 * (vtkOpenMeshNormals). Input 1 (optional): the seam mesh of vtkPhongSeamFacesExchange with
 * its point normals, computed by a vtkOpenMeshNormals with the same settings: the piece's
 * faces around its cut points and the other ranks' faces there, whose point array
 * vtkPhongSeamFacesExchange::PiecePointIdsArrayName() names each point of the piece.
 *
 * A point's normal depends on its own faces only, so of the piece's points only the cut
 * points had a part of their fan; the seam mesh holds the whole of it. The output is input
 * 0 with a new normals array in which each cut point has the seam mesh's normal, except a
 * point that either normals filter split (a sharp edge through it: its copies' corners are
 * assigned differently in the two meshes), which keeps its own. Without a seam mesh, or
 * normals on either input, the output is input 0.
 *
 * @sa vtkPhongSeamFacesExchange vtkOpenMeshNormals vtkPhongSurfaceRepresentation
 */

#ifndef vtkPhongSeamNormalsPatch_h
#define vtkPhongSeamNormalsPatch_h

#include "vtkPhongRepresentationsModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKPHONGREPRESENTATIONS_EXPORT vtkPhongSeamNormalsPatch : public vtkPolyDataAlgorithm
{
public:
  static vtkPhongSeamNormalsPatch* New();
  vtkTypeMacro(vtkPhongSeamNormalsPatch, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The point array in which the normals filters give each output point's input point
   * (vtkOpenMeshNormals::SetOriginalPointIdsArrayName): how split points are recognized.
   * Default "vtkOriginalPointIds".
   */
  vtkSetStringMacro(OriginalPointIdsArrayName);
  vtkGetStringMacro(OriginalPointIdsArrayName);
  ///@}

  ///@{
  /**
   * What the last execution did: the cut points given the seam mesh's normal, and those
   * left with their own because a normals filter split them.
   */
  vtkGetMacro(NumberOfPatchedPoints, vtkIdType);
  vtkGetMacro(NumberOfSplitSeamPoints, vtkIdType);
  ///@}

protected:
  vtkPhongSeamNormalsPatch();
  ~vtkPhongSeamNormalsPatch() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  char* OriginalPointIdsArrayName = nullptr;
  vtkIdType NumberOfPatchedPoints = 0;
  vtkIdType NumberOfSplitSeamPoints = 0;

private:
  vtkPhongSeamNormalsPatch(const vtkPhongSeamNormalsPatch&) = delete;
  void operator=(const vtkPhongSeamNormalsPatch&) = delete;
};

#endif
