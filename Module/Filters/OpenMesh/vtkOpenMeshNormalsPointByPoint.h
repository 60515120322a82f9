/**
 * @class   vtkOpenMeshNormalsPointByPoint
 * @brief   vtkOpenMeshNormals' point normals one point at a time, in bounded memory (private)
 *
 * Most meshes that reach a renderer without normals are smooth, consistently oriented
 * triangle meshes: a terrain, an isosurface, a sphere. On them vtkOpenMeshNormals' topology
 * (the faces' twins, orientation, halfedge mesh and fans; about 170 bytes a triangle) only
 * confirms that nothing is to be turned, cut or copied. This path confirms it point by
 * point instead: the corners at a range of points are gathered, each point's fan is walked
 * across its corners' neighbours exactly as vtkOpenMeshNormalsTopology would walk it, and
 * its normal is summed in the same order with the same weights (vtkOpenMeshNormalsFanRules.h),
 * so that the output is the same, bit for bit.
 *
 * It gives up (NeedsTopology) at the first point whose fan the topology would treat
 * otherwise: a repeated vertex index, an edge of more than two faces or of two faces running
 * the same way (a face to turn, or a non-manifold edge), several fans at one point, or,
 * with splitting, a sharp edge or a cone's apex inside a fan. vtkOpenMeshNormals then builds
 * the topology as before.
 *
 * Memory: the output's normals (and original point ids), one 32-bit corner count per point,
 * and the corners of one range of points at a time: a quarter of the mesh's corners, at
 * most 2^24 (64 MB). The output shares the input's points, cells and data arrays.
 *
 * Neither wrapped nor installed.
 *
 * @sa vtkOpenMeshNormals vtkOpenMeshNormalsTopology vtkOpenMeshNormalsExecution
 */

#ifndef vtkOpenMeshNormalsPointByPoint_h
#define vtkOpenMeshNormalsPointByPoint_h

#include "vtkOpenMeshNormalsBuffers.h"

class vtkAlgorithm;
class vtkPolyData;

class vtkOpenMeshNormalsPointByPoint : public vtkOpenMeshNormalsTypes
{
public:
  /**
   * The filter's settings this path needs (it is not taken with cell normals,
   * AutoOrientNormals or FlipNormals, which the topology serves).
   */
  struct Settings
  {
    int Weighting;       // vtkOpenMeshNormals::Weightings
    double FeatureAngle; // degrees
    bool Splitting;
    const char* OriginalPointIdsArrayName; // not null
  };

  enum class Result
  {
    Computed,      // the output is written
    NeedsTopology, // some point's fan needs the topology; the output is untouched
    Aborted        // the filter's AbortExecute; the output is untouched
  };

  /**
   * Whether the input has the form this path reads: polygons that are all triangles, no
   * strips, float or double points, fewer than 2^31 corners.
   */
  static bool Takes(vtkPolyData* input);

  /**
   * The point normals of an input that Takes(), into output (see the class
   * documentation); progress and abort through filter.
   */
  static Result Compute(
    const Settings& settings, vtkPolyData* input, vtkPolyData* output, vtkAlgorithm* filter);
};

#endif
