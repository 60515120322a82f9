/**
 * @class   vtkOpenMeshNormalsJoin
 * @brief   normals across the copies of a point that pieces of one surface each hold
 *
 * Pieces of a surface (ParaView's ranks, a source's pieces, appended blocks) each hold their
 * own copy of the points on their cuts, and a normal computed on such a mesh stops at the cut:
 * a seam. Copies (points that share a global id, the point data's GlobalIds, or without
 * them points within a tolerance of each other) are one vertex for the normals: the polygons are
 * renumbered onto one representative per group of copies, the normals are computed on that joined
 * copy, and each corner's normal is then given back to the input's own point, so that every copy
 * keeps its own point data (texture coordinates, scalars). A point whose corners got different
 * normals (split at a sharp edge) gets a copy per normal, as vtkOpenMeshNormals' splitting does.
 *
 * Private to vtkOpenMeshNormals (JoinCoincidentPoints).
 */

#ifndef vtkOpenMeshNormalsJoin_h
#define vtkOpenMeshNormalsJoin_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <vector>

class vtkPolyData;

class vtkOpenMeshNormalsJoin
{
public:
  /**
   * For each point, the one point that stands for its copies: the first with its global id,
   * or, without global point ids, one within tolerance * the bounding-box diagonal. Empty
   * when no point has a copy.
   */
  static std::vector<vtkIdType> Representatives(vtkPolyData* input, double tolerance);

  /**
   * The input with its polygons renumbered onto the representatives; its points, strips,
   * vertices, lines and data are the input's own.
   */
  static vtkSmartPointer<vtkPolyData> JoinedCopy(
    vtkPolyData* input, const std::vector<vtkIdType>& representative);

  /**
   * The output: the input's points (and copies where a point's corners got different
   * normals), with the normals the joined copy's corners got; the joined output's cells and
   * cell data. originalIdsName: the joined output's array of original point ids (null when
   * the normals were not split, and the joined output has no added point), written again for
   * the output's points.
   */
  static void GiveNormalsBack(vtkPolyData* input, const std::vector<vtkIdType>& representative,
    vtkPolyData* joined, vtkPolyData* output, const char* originalIdsName);
};

#endif
