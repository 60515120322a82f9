/**
 * @class   vtkPhongBufferBlocks
 * @brief   the polydata a mapper's vertex buffer holds, and their points in its order (private)
 *
 * A polydata mapper's vertex buffer holds one polydata's points; a composite mapper's block
 * mapper's holds several blocks one after the other (blocks with the same points array share
 * its vertices: VTK uploads it once). The visibility work (vtkPhongClosedSurface,
 * vtkPhongVisibleClusters) reads the triangles through VTK's index buffer, whose indices
 * name the buffer's vertices: Points() gives those vertices' positions.
 */

#ifndef vtkPhongBufferBlocks_h
#define vtkPhongBufferBlocks_h

#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkType.h"         // for vtkIdType

#include <vector> // for std::vector

class vtkOpenGLVertexBufferObjectGroup;
class vtkPolyData;

/**
 * A polydata whose points the vertex buffer holds from FirstPoint on.
 */
struct vtkPhongBufferBlock
{
  vtkPolyData* Data = nullptr;
  vtkIdType FirstPoint = 0;
};

class vtkPhongBufferBlocks
{
public:
  /**
   * The points of the vertex buffer the blocks share, in its order (the one block itself
   * when it starts the buffer); nullptr when two blocks claim the same vertices with points
   * of their own. Vertices no block claims are NaN.
   */
  static vtkSmartPointer<vtkPolyData> Points(const std::vector<vtkPhongBufferBlock>& blocks);

  /**
   * A polydata holding a deep copy of `input`'s points and nothing else: what an analysis on
   * another thread reads while the input may change (vtkPhongBackgroundTask).
   */
  static vtkSmartPointer<vtkPolyData> CopyOfPoints(vtkPolyData* input);

  /**
   * Frees what VTK keeps of the arrays it packed for upload. A vertex buffer object packs an
   * array into a vector of its own when the buffer's layout differs from the array's (double
   * points, shifted and scaled coordinates, colours, a composite mapper's blocks appended one
   * after the other), uploads it, and empties the vector with `resize(0)`, which keeps its
   * memory: as large as the buffer, kept for the next upload, a copy of every big mesh's
   * points and normals that nothing reads (VTK 9.1 to 9.7). A later upload packs again.
   */
  static void ReleasePackedCopies(vtkOpenGLVertexBufferObjectGroup* buffers);
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongBufferBlocks.h
