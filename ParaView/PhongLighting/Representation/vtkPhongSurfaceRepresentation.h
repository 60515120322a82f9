/**
 * @class   vtkPhongSurfaceRepresentation
 * @brief   ParaView's surface representation, lit by vtkPhong ("Phong Surface")
 *
 * vtkPhongSurfaceRepresentation is a vtkGeometryRepresentationWithFaces whose mappers are
 * vtkPhongCompositePolyDataMapper and whose material is a vtkPhongProperty, so everything
 * ParaView shows as a surface (polydata, unstructured grids, multiblocks, each rank's piece
 * under pvbatch or pvserver) is lit by the lighting model of docs/lighting-model.md with the
 * lights of ParaView's view. ParaView's own surface properties (colours, Ambient, Diffuse,
 * Specular, SpecularPower, Interpolation, Opacity, block colours) keep working; the
 * properties below add vtkPhong's.
 *
 * Normals: vtkOpenMeshNormals computes them (Max weighting, 30 degree feature angle,
 * splitting on) between ParaView's geometry filter and the view, so every rank computes the
 * normals of its own piece; ComputeNormals off draws the normals the surface carries.
 *
 * @sa vtkPhongCompositePolyDataMapper vtkPhongProperty vtkOpenMeshNormals
 */

#ifndef vtkPhongSurfaceRepresentation_h
#define vtkPhongSurfaceRepresentation_h

#include "vtkGeometryRepresentationWithFaces.h"
#include "vtkNew.h"                        // for vtkNew
#include "vtkPhongRepresentationsModule.h" // for export macro

class vtkOpenMeshNormals;

class VTKPHONGREPRESENTATIONS_EXPORT vtkPhongSurfaceRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkPhongSurfaceRepresentation* New();
  vtkTypeMacro(vtkPhongSurfaceRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The lobe: 0 Phong, 1 Blinn-Phong (default), 2 normalized Phong, 3 normalized
   * Blinn-Phong (vtkPhongProperty::LightingModels).
   */
  void SetLightingModel(int model);

  /**
   * The shininess exponent over [0, 1e6]; default 100. Replaces ParaView's SpecularPower
   * (which vtkProperty clamps at 128) for this representation.
   */
  void SetShininess(double shininess);

  /**
   * Emitted colour, added whatever the lights; default black.
   */
  void SetEmission(double red, double green, double blue);

  /**
   * Light per vertex and interpolate colours (true Gouraud) instead of per fragment.
   * Default off.
   */
  void SetPerVertexGouraud(int perVertex);

  /**
   * The mapper's debug view (vtkPhongPolyDataMapper::DebugViews; default 0, Final) and the
   * light the SingleLight view shows.
   */
  void SetDebugView(int view);
  void SetDebugLightIndex(int index);

  /**
   * On (default): the surface's normals are computed by vtkOpenMeshNormals. Off: the normals
   * the surface carries are drawn (none: faceted, as ParaView's Surface representation).
   */
  void SetComputeNormals(int compute);

  /**
   * The normals' vertex weighting: 0 uniform, 1 area, 2 angle, 3 Max (default), as
   * vtkOpenMeshNormals::SetWeighting; and its feature angle in degrees (default 30, [0, 180]).
   */
  void SetNormalsWeighting(int weighting);
  void SetNormalsFeatureAngle(double degrees);

protected:
  vtkPhongSurfaceRepresentation();
  ~vtkPhongSurfaceRepresentation() override;

  /**
   * The superclass' pipeline, with vtkOpenMeshNormals between the geometry filter and the
   * multiblock maker when ComputeNormals is on.
   */
  void SetupDefaults() override;

  /**
   * Feed the multiblock maker from the normals filter (ComputeNormals on) or straight from
   * the geometry filter.
   */
  void ConnectNormals();

  bool ComputeNormals = true;
  vtkNew<vtkOpenMeshNormals> Normals;

private:
  vtkPhongSurfaceRepresentation(const vtkPhongSurfaceRepresentation&) = delete;
  void operator=(const vtkPhongSurfaceRepresentation&) = delete;
};

#endif
