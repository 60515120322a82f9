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
 * Normals: where the data has no point normals, vtkOpenMeshNormals computes them (Max
 * weighting, 30 degree feature angle, splitting on) between ParaView's geometry filter and
 * the view, so every rank computes the normals of its own piece; data that carries point
 * normals is drawn with its own, as ParaView's Surface draws it (ComputeNormals).
 * Under MPI the pieces' normals agree where pieces meet (NormalsAcrossPieces, default on):
 * the representation gives each piece ghost cells and keeps them through the geometry filter
 * (vtkPhongGhostCellsStash) until the normals are made, then drops them. Polydata pieces
 * need less: each rank computes its piece's normals alone, and then the normals of its cut
 * points over the faces around them, its own and the other ranks' (vtkPhongSeamFacesExchange,
 * a second vtkOpenMeshNormals, vtkPhongSeamNormalsPatch). Other data gets one level of ghost
 * cells (vtkGhostCellsGenerator: ParaView's sources and filters, RedistributeDataSet
 * included, mostly ignore ghost requests), which costs far more. Pieces hold copies of the
 * points on their cuts; a source's own pieces (ParaView's Sphere under MPI) compute them by
 * different sums, a few float steps apart. The seam mesh puts the faces it brings on the
 * piece's own copies (by position, within a millionth of the diagonal). The ghost cells bring
 * copies along, and on that path the normals treat the copies of a point (by global point id
 * where the data has them, else by position) as one vertex: vtkOpenMeshNormals'
 * JoinCoincidentPoints.
 *
 * @sa vtkPhongCompositePolyDataMapper vtkPhongProperty vtkOpenMeshNormals
 */

#ifndef vtkPhongSurfaceRepresentation_h
#define vtkPhongSurfaceRepresentation_h

#include "vtkGeometryRepresentationWithFaces.h"
#include "vtkNew.h"                        // for vtkNew
#include "vtkPhongRepresentationsModule.h" // for export macro

#include <string> // for std::string

class vtkGhostCellsGenerator;
class vtkOpenMeshNormals;
class vtkPhongLightingSettings;
class vtkPhongGhostCellsStash;
class vtkPhongSeamFacesExchange;
class vtkPhongSeamNormalsPatch;

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
   * The lighting settings of both mappers (full resolution and level of detail), one
   * vtkPhongLightingSettings object (where each is documented): the debug view
   * (vtkPhongLightingSettings::DebugViews; default 0, Final), the light the SingleLight view
   * shows, light culling's bound (default 0.5 / 255; NaN refused), the error budget in
   * 8-bit levels (default 0, the exact mode; vtkPhongLightingSettings::SetErrorBudget),
   * specular anti-aliasing (default off; vtkPhongLightingSettings::SetSpecularAntiAliasing),
   * and whether surfaces with no light switched on show emission and ambient (default off:
   * unlit, as ParaView's Surface).
   */
  void SetDebugView(int view);
  void SetDebugLightIndex(int index);
  void SetLightCullingBound(double bound);
  void SetErrorBudget(double levels);
  void SetSpecularAntiAliasing(int on);
  void SetLightingWithoutLights(int on);

  /**
   * Where the last render's light sums went under the error budget, the most approximate of
   * the blocks' modes (vtkPhongLightingSettings::BudgetModes: 0 per fragment, 1 the specular
   * sums per vertex, 2 every sum per vertex).
   */
  int GetUsedBudgetMode();

  /**
   * Culling of the hidden back faces of closed surfaces seen from outside
   * (vtkPhongLightingSettings::SetClosedSurfaceCulling; default on, the picture is the
   * same) and whether the last render culled them (1) or not (0): a piece of a surface split
   * between ranks is not closed, and is drawn whole.
   */
  void SetClosedSurfaceCulling(int cull);
  int GetUsedClosedSurfaceCulling();

  /**
   * The depth pre-pass (vtkPhongLightingSettings::SetDepthPrePass: 0 off, 1 on, 2 automatic,
   * the default), its occlusion culling (default on), and whether the last render used it
   * (1) or not (0).
   */
  void SetDepthPrePass(int mode);
  void SetDepthPrePassOcclusionCulling(int cull);
  int GetUsedDepthPrePass();

  /**
   * The most lighting programs each block mapper keeps compiled (default 32, [0, 4096]; 0
   * keeps every one).
   */
  void SetMaximumNumberOfShaderPrograms(int count);

  /**
   * When vtkOpenMeshNormals computes the surface's normals (ComputeNormalsModes):
   * WhereMissing (default) unless every non-empty piece of the input, on every rank, carries
   * point normals, which are then drawn; Always, replacing the data's; Never: the normals
   * the surface carries are drawn (none: faceted, as ParaView's Surface representation).
   */
  enum ComputeNormalsModes
  {
    Never = 0,
    WhereMissing = 1,
    Always = 2
  };
  void SetComputeNormals(int mode);

  /**
   * The normals' vertex weighting: 0 uniform, 1 area, 2 angle, 3 Max (default), as
   * vtkOpenMeshNormals::SetWeighting; and its feature angle in degrees (default 30, [0, 180]).
   */
  void SetNormalsWeighting(int weighting);
  void SetNormalsFeatureAngle(double degrees);

  /**
   * ParaView's "Normal Array" choice (SelectNormalArray), remembered and applied only while
   * the data's normals are drawn: otherwise the computed normals are the ones drawn. ParaView
   * sets "None" when the input has no normals array, and ParaView 5.11 passes that name on
   * to SetActiveNormals, which would switch the computed normals off again.
   */
  void SetNormalArray(const char* name) override;

  /**
   * On (default): under MPI, make one level of ghost cells and compute each piece's
   * normals with its neighbours' faces, so that pieces meet without a seam. Off: each
   * piece's normals see that piece only (no ghost exchange; a seam where pieces meet).
   * Only matters while normals are computed.
   */
  void SetNormalsAcrossPieces(int across);

  /**
   * The superclass' internal input, seen through the ghost-cell stash while normals are
   * computed across pieces: the geometry filter is connected to what this returns.
   */
  using Superclass::GetInternalOutputPort;
  vtkAlgorithmOutput* GetInternalOutputPort(int port, int connection) override;

protected:
  vtkPhongSurfaceRepresentation();
  ~vtkPhongSurfaceRepresentation() override;

  /**
   * The superclass' pipeline, with the ghost trim, vtkOpenMeshNormals and the ghost removal
   * between the geometry filter and the multiblock maker while normals are computed.
   */
  void SetupDefaults() override;

  /**
   * Whether this process is one of several MPI ranks: then the pieces' normals are made to
   * meet here (ExchangesSeamFaces says how; on the ghost-cell path the input's own ghost
   * cells, when it has some, are made again).
   */
  static bool IsParallel();

  /**
   * Whether the normals of the points where pieces meet come from the seam mesh of
   * vtkPhongSeamFacesExchange (polydata under MPI) rather than from ghost cells made by
   * vtkGhostCellsGenerator. The same on every rank: it depends on the number of ranks and
   * the input's type.
   */
  static bool ExchangesSeamFaces(vtkDataObject* input);

  /**
   * The superclass' RequestData, after deciding whether to compute normals (ComputeNormals;
   * collective under MPI). It forwards the input's whole extent to the internal input's
   * producer only when it gets that producer's port, which it does not while the stash is in
   * between: forward it here first.
   */
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /**
   * Whether every non-empty piece of `input` (a data set, or the leaves of composite data)
   * carries point normals, on every rank (collective when IsParallel).
   */
  static bool HasPointNormals(vtkDataObject* input);

  /**
   * Whether the ghost-cell stash is in the pipeline (normals computed, NormalsAcrossPieces).
   */
  bool StashesGhostCells() const { return this->ComputesNormals && this->NormalsAcrossPieces; }

  /**
   * Feed the multiblock maker through the ghost trim, the normals and the ghost removal
   * (ComputesNormals), then the seam patch (PatchesSeams: polydata under MPI), or
   * straight from the geometry filter.
   */
  void ConnectNormals();

  /**
   * Give the seam mesh's normals the settings of the piece's.
   */
  void ConfigureSeamNormals();

  /**
   * Tell the superclass which normals to draw: none named (the computed ones stay active)
   * while normals are computed, the user's NormalArray otherwise.
   */
  void ApplyNormalArray();

  int ComputeNormals = WhereMissing;
  bool ComputesNormals = true; // what ComputeNormals decided for the current input
  bool NormalsAcrossPieces = true;
  std::string NormalArray;
  vtkNew<vtkGhostCellsGenerator> GhostCells;
  vtkNew<vtkPhongGhostCellsStash> GhostStash;
  vtkNew<vtkPhongGhostCellsStash> GhostTrim;
  vtkNew<vtkOpenMeshNormals> Normals;
  vtkNew<vtkPhongLightingSettings> LightingSettings;
  vtkNew<vtkPhongGhostCellsStash> GhostRemoval;
  bool PatchesSeams = false;
  vtkNew<vtkPhongSeamFacesExchange> SeamFaces;
  vtkNew<vtkOpenMeshNormals> SeamNormals;
  vtkNew<vtkPhongSeamNormalsPatch> SeamPatch;

private:
  vtkPhongSurfaceRepresentation(const vtkPhongSurfaceRepresentation&) = delete;
  void operator=(const vtkPhongSurfaceRepresentation&) = delete;
};

#endif
