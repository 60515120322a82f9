/**
 * @class   vtkPhongGouraudBound
 * @brief   a proven bound on how far per-vertex lighting strays from per-fragment lighting
 * (private)
 *
 * Under an error budget (vtkPhongLightingSettings::ErrorBudget) the planner may light a
 * surface at its vertices and interpolate (VTK's true Gouraud) instead of at every fragment,
 * which on fine meshes costs a fraction of the per-fragment lighting. It does so only where
 * this bound, on the largest difference per pixel and channel between the two, fits the
 * budget. docs/lighting-model.md ("Error budget") has the derivation; in short:
 *
 * For one triangle whose unit vertex normals lie in a cap of angular radius R, and one
 * directional light, the per-vertex value G(b) = sum b_i s(n_i.H) and the per-fragment value
 * F(b) = s(N(b).H), N(b) the normalized interpolated normal, differ by at most (Waldron's
 * identity for the degree-0 homogeneous function s(H.m/|m|))
 *
 *     E(R) = tan^2(R)/2 * (Hs + 2 G1 (1 - cos R cos 2R) / sin R)
 *
 * with Hs = sup |d2 s/d alpha2| + sup |s'(c) c| and G1 = sup s'(c) sin(alpha) over the
 * angles alpha between H and the normals of the cap. Both values lie in [0, sup s], so
 * sup s bounds the difference too (the only bound where a lobe's clamp or the specular gate
 * crosses the triangle). The Phong lobe takes the reflected vector's cap (2R); the diffuse
 * term is the case s(c) = max(c, 0), n = 1, whose kink at the terminator costs sin(R)/2.
 * Bound() also gives the bound without the diffuse term, for the mode that lights the
 * diffuse term per fragment from interpolated dot products (exact: max(n.L, 0) / |n| with
 * n the interpolated normal) and only the specular sums per vertex.
 *
 * Update() bins the triangles once per upload by the direction of their normal cap (a cube
 * map of 6 x 8 x 8 cells), keeping per cell the cone of cap axes, the largest cap radius, the
 * largest triangle radius and the ball around its points; Bound() then costs cells x lights
 * per frame and bounds every triangle of a cell at once (the cell's angles widen by its cone,
 * and in perspective by the view vector's cone over the cell's ball). Only directional lights
 * are bounded; a perspective view adds the view vector's spread over a triangle (first
 * order, with a margin of 1.1 checked by brute force in TestPhongGouraudBound).
 */

#ifndef vtkPhongGouraudBound_h
#define vtkPhongGouraudBound_h

#include "vtkRenderingPhongModule.h" // for export macro (vtkPhongBenchmark times Bound)
#include "vtkType.h"                 // for vtkMTimeType

#include <array>  // for std::array
#include <vector> // for std::vector

class vtkDataArray;
class vtkPoints;
class vtkPolyData;

class VTKRENDERINGPHONG_EXPORT vtkPhongGouraudBound
{
public:
  /// What lights the surface, in the model coordinates of its normals (unit vectors).
  struct Scene
  {
    struct Light
    {
      std::array<double, 3> ToLightMC; ///< L, from the surface towards the light
      double Diffuse = 0.0;            ///< kd*Cd*Ld*I, the largest over channels and sides
      double Specular = 0.0;           ///< ks*Cs*Ls*I*normalization, likewise
      bool operator==(const Light& other) const;
    };
    std::vector<Light> Lights;
    bool Parallel = true;
    std::array<double, 3> ToEyeMC = { { 0.0, 0.0, 1.0 } }; ///< V, parallel projection
    std::array<double, 3> EyeMC = { { 0.0, 0.0, 0.0 } };   ///< the eye, perspective
    double Shininess = 1.0;
    bool Blinn = true;
    bool TwoSided = true;          ///< back faces lit with the reversed normals
    bool SmoothTerminator = false; ///< the lobe times max(N.L, 0) instead of the gate
    bool operator==(const Scene& other) const;
  };

  /**
   * Bin the triangles of `blocks` (their polygons, fan-triangulated as VTK draws them, and
   * point normals) unless done for `buildTime` already. Without point normals, or with
   * normals that are not unit-length usable vectors, the surface is unbounded.
   */
  void Update(const std::vector<vtkPolyData*>& blocks, vtkMTimeType buildTime);

  /// Bounds of the two per-vertex modes; +inf where they cannot be bounded.
  struct Bounds
  {
    double PerVertex;         ///< every light sum per vertex
    double SpecularPerVertex; ///< the specular sums per vertex, the diffuse per fragment
  };

  /**
   * The largest difference per pixel and channel (linear colour) between per-vertex and
   * per-fragment lighting of the binned triangles in `scene`, for both per-vertex modes.
   * The scene of the last call is remembered: a still view costs nothing.
   */
  Bounds Bound(const Scene& scene);

  /**
   * The bound E above for one cap: `spread` its angular radius, [near, far] the range of
   * angles between the lobe's axis and the normals of the cap (radians), `n` the exponent of
   * s(c) = max(c, 0)^n. Where the cap reaches c = 0 with n < 2 the clamp is not smooth: for
   * n = 1 (the diffuse term) its kink adds sin(R)/2, otherwise the bound is +inf (callers
   * take sup s instead). Public for tests.
   */
  static double LobeBound(double spread, double nearAngle, double farAngle, double n);

  /// Triangles binned; 0 when nothing was or the surface is unbounded.
  std::size_t GetNumberOfTriangles() const { return this->Triangles; }

  /// Points of the binned blocks (the vertices per-vertex lighting would light).
  std::size_t GetNumberOfPoints() const { return this->Points; }

  /// Where the light sums go, from the most exact and dearest to the cheapest.
  enum class Mode
  {
    PerFragment,
    SpecularPerVertex,
    PerVertex
  };

  /// The planner's choice last time (its hysteresis).
  Mode Chosen = Mode::PerFragment;

private:
  using Vector = std::array<double, 3>;
  static constexpr double Huge = 1.0e300;
  struct Cell
  {
    Vector Axis = { { 0.0, 0.0, 0.0 } }; ///< the cell's centre direction
    // While Update bins, the squares: of the longest chords to a cap axis and within a cap, of
    // the largest radius (comparing them needs no arcsine); then the angles and the length.
    double Cone = 0.0;   ///< largest angle to a cap axis
    double Spread = 0.0; ///< largest cap radius
    double Radius = 0.0; ///< largest triangle radius
    std::size_t Count = 0;
    Vector Low = { { Huge, Huge, Huge } }, High = { { -Huge, -Huge, -Huge } }; ///< points' box
    Vector Centre = { { 0.0, 0.0, 0.0 } }; ///< of the ball holding its points (from the box)
    double Reach = 0.0;                    ///< that ball's radius
  };
  /// The view vector over the whole surface: a cone, and the eye's least distance.
  struct View
  {
    Vector Centre = { { 0.0, 0.0, 1.0 } };
    double Spread = 0.0;
    double Nearest = 0.0;
    double LobeCut = 0.0; ///< the angle from the lobe's axis past which it is negligible
    double CosHalfSpread = 1.0, SinHalfSpread = 0.0; ///< of Spread / 2
  };
  /// Blinn's halfway vector for one light over the view cone (unused for Phong).
  struct Halfway
  {
    Vector Direction = { { 0.0, 0.0, 1.0 } };
    double Least = 0.0;    ///< |L + V| at its least over the view cone
    bool LobeZero = false; ///< L = -V in parallel projection: the lobe is 0
    bool Unbounded = false;
  };
  static bool MakeView(const Scene& scene, const Cell& cell, View& view);
  static Halfway MakeHalfway(const Scene& scene, const View& view, const Vector& toLight);
  static Bounds CellBound(
    const Cell& cell, const Scene& scene, const View& view, const std::vector<Halfway>& halfways);
  /// The terms of LobeBound that depend on the cap's radius alone, made once per cell.
  struct Cap
  {
    explicit Cap(double spread);
    double Spread, HalfTangent2 = 0.0, Radial = 0.0, Kink = 0.0;
  };
  static double LobeBound(const Cap& cap, double nearAngle, double farAngle, double n);
  static double DiffuseBound(const Cap& normals, double cosNear, double sinFar, bool terminator);
  static double SpecularBound(const Cell& cell, const Scene& scene, const View& view,
    const Vector& d, const Vector& toLight, const Halfway& halfway, double localView,
    bool gateCrosses);
  void AddPolygon(vtkIdType count, const vtkIdType* ids, vtkPoints* points, vtkDataArray* normals);

  std::vector<Cell> Cells;
  std::vector<Vector> CornerNormals, CornerPositions; ///< AddPolygon's, reused
  std::size_t Triangles = 0;
  std::size_t Points = 0;
  bool Unbounded = true;
  Scene LastScene;                    ///< Bound's last scene, and its bounds
  Bounds LastBounds = { -1.0, -1.0 }; ///< negative: none yet since Update
  Bounds Compute(const Scene& scene) const;
  vtkMTimeType BuildTime = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongGouraudBound.h
