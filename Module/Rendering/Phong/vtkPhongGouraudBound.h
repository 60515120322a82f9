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
 * and in perspective by the view vector's cone over the cell's ball). Directional lights and
 * point lights are bounded, attenuated ones with their attenuation's largest value and change
 * over a triangle (MakeLightView); not spot lights. A perspective view adds
 * the view vector's spread over a triangle, from Waldron's identity for the normal and the
 * view vector interpolated together (ViewSpreadBound), and the turn of the lobe's axis by the
 * skew of the interpolated view vector (MakeLocalView); Phong adds that of the reflected
 * interpolated normal (ReflectionSkew). A point light's direction does over a triangle what
 * the view vector does (MakeLightView: Blinn's H turns with both; Phong's reflected vectors
 * spread further; the diffuse term, LightSpreadBound), and over a cell's ball widens its
 * angles. Under a point light only every sum goes per vertex: the other mode lights the
 * directional lights' diffuse term alone per fragment.
 */

#ifndef vtkPhongGouraudBound_h
#define vtkPhongGouraudBound_h

#include "vtkPhongAttenuation.h"     // for vtkPhongAttenuation
#include "vtkRenderingPhongModule.h" // for export macro (vtkPhongBenchmark times Bound)
#include "vtkType.h"                 // for vtkMTimeType

#include <array>  // for std::array
#include <cmath>  // for HUGE_VAL
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
      /// A point light (no cone) at PositionMC instead of the direction.
      bool Positional = false;
      std::array<double, 3> PositionMC = { { 0.0, 0.0, 0.0 } };
      /// A point light's attenuation of distances in model units (VTK's coefficients take
      /// view units: vtkPhongAttenuation::Scaled); c > 0.
      vtkPhongAttenuation AttenuationMC;
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
   * Once both exceed `limit` (the most a caller could accept) the cells left are skipped:
   * a bound above `limit` may then be less than the largest difference, though still above
   * `limit`. The scene and limit of the last call are remembered: a still view costs nothing.
   */
  Bounds Bound(const Scene& scene, double limit = HUGE_VAL);

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
  /// The terms of LobeBound that depend on the cap's radius alone, made once per cap.
  struct Cap
  {
    explicit Cap(double spread = 0.0);
    Cap(double spread, double sine, double cosine); ///< with the sine and cosine of spread
    void SetTerms(double sine, double cosine);
    double Spread, HalfTangent2 = 0.0, Radial = 0.0, Kink = 0.0;
    double Tangent = 0.0; ///< tan(R): the cap's sum of b_i |n_i - m|^2 over |m|, rooted
    double Cosine = 1.0;  ///< cos(R)
  };
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
    // Made once binning ends, since the bound needs them every frame:
    Cap Normals;                           ///< the cap of the largest radius, Spread
    Cap Reflections;                       ///< Phong's reflected vectors' cap, 2 Spread
    double CosWidth = 1.0, SinWidth = 0.0; ///< of Cone + Spread, the normals' angles around Axis
    double ReflectionSkew = 0.0; ///< ReflectionSkew(Spread) of a directional light (Phong)
  };
  /// The view vector over the whole surface: a cone, and the eye's least distance.
  struct View
  {
    Vector Centre = { { 0.0, 0.0, 1.0 } };
    double Spread = 0.0;
    double Nearest = 0.0;
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
  /// The direction from one triangle of a cell to a point (the eye, a point light): its
  /// spread (the angular radius of the vertices' directions) and its skew (how far a
  /// fragment's direction is from the normalized interpolation of the vertices' unit ones),
  /// each by its tangent (at least the angle); both 0 for a point at infinity.
  struct LocalView
  {
    double Spread = 0.0;
    double Skew = 0.0;
    Cap Directions; ///< the cap of the vertices' unit directions (Spread, the sine and cosine
                    ///< of the radius)
  };
  static LocalView MakeLocalView(const Scene& scene, const Cell& cell, const View& view);
  static LocalView MakeLocalSpread(double radius, double nearest);
  /// One light over one cell: its direction from the cell's centre, the half-angle of the
  /// cone holding it over the cell's ball (0 for a directional light) and over one triangle.
  struct LightView
  {
    Vector ToLight = { { 0.0, 0.0, 1.0 } };
    double Spread = 0.0, CosSpread = 1.0, SinSpread = 0.0;
    LocalView Local;
    /// A point light's attenuation over the cell: its largest value, and how far it can
    /// differ between two points of one triangle (1 and 0 without attenuation).
    double Fade = 1.0, FadeChange = 0.0;
  };
  static bool MakeLightView(const Scene::Light& light, const Cell& cell, LightView& lightView);
  static Halfway MakeHalfway(const Scene& scene, const View& view, const LightView& light);
  /// The lobe's exponent n, and what depends on it alone: made once per bound.
  struct Exponent
  {
    explicit Exponent(double n);
    double N;
    double Cut = 0.0; ///< the angle from the lobe's axis past which it is negligible
    double CosCut = -1.0, SinCut = 0.0; ///< of Cut, where it is at most pi/2
    /// sup of cos^p sin^q at its interior peak (tan^2 = q/p), and that angle's cosine, for
    /// p = n - 2, q = 2 and p = n - 1, q = 1 (0 and 0 where p <= 0: no interior peak).
    double CurvaturePeak = 0.0, SlopePeak = 0.0;
    double CurvaturePeakCos = 0.0, SlopePeakCos = 0.0;
    /// n where it is a whole number up to 2^16, else 0: its powers by squaring (a few
    /// products, within a few ulps) instead of std::pow.
    unsigned int Whole = 0;
    double Power(double x) const; ///< x^n, x in [0, 1]
  };
  /// An angle in [0, pi] by its cosine and sine: the lobe bounds compare and combine angles
  /// by them, so that a light and cell costs no arccosine, sine or cosine.
  struct CosSin
  {
    double Cos = 1.0, Sin = 0.0;
    static CosSin Of(double angle); ///< of min(angle, pi); cos <= 0 from pi/2 on
  };
  /// The near angle of a lobe bound, in [0, pi] (the lobe 0 from pi/2 on), with cos^n.
  struct NearAngle
  {
    NearAngle(const CosSin& angle, const Exponent& exponent);
    double Cos, Sin, CosN;
  };
  /// The suprema of a lobe's derivatives over a range of angles that Waldron's identity
  /// takes (LobeBound): Hs and G1 above, and Hx = sup max(|d2 s/d alpha2|, s'(c)), which
  /// bounds the mixed derivative when both the normal and the lobe's axis move.
  struct LobeTerms
  {
    double Hs = 0.0, G1 = 0.0, Hx = 0.0;
    bool Kink = false; ///< n = 1 and the clamp at c = 0 within the range
  };
  static LobeTerms MakeLobeTerms(
    const NearAngle& nearAngle, const CosSin& farAngle, const Exponent& exponent);
  static double CapBound(const Cap& cap, const LobeTerms& lobe, double n);
  static double ViewSpreadBound(const LobeTerms& lobe, const Cap& normals,
    const LocalView& localView, const LocalView& localLight, bool blinn, double halfwayLeast);
  static double LightSpreadBound(
    const Cap& normals, const LocalView& localLight, double cosNear, double cosFar, double sinFar);
  struct CellScratch
  {
    std::vector<LightView> Lights;
    std::vector<Halfway> Halfways;
    bool DirectionalMade = false; ///< the directional lights' views, the same in every cell
  };
  static bool MakeLightViews(
    const Cell& cell, const Scene& scene, const View& view, CellScratch& scratch, bool& positional);
  static Bounds CellBound(const Cell& cell, const Scene& scene, const Exponent& exponent,
    const View& view, const std::vector<Halfway>& halfways, CellScratch& scratch);
  static double LobeBound(
    const Cap& cap, const NearAngle& nearAngle, const CosSin& farAngle, const Exponent& exponent);
  static CosSin Widen(const CosSin& base, double baseAngle, double extra);
  static void LobeRange(const Vector& from, const Vector& axis, const CosSin& width,
    CosSin& nearAngle, CosSin& farAngle);
  static double DiffuseBound(const Cap& normals, double cosNear, double cosFar, double sinFar);
  static double DiffuseCurvature(double cosNear, double cosFar);
  static double SlopeBeyond(const NearAngle& a, const Exponent& exponent);
  static double ReflectionSkew(double spread, const LocalView& light);
  static double SpecularBound(const Cell& cell, const Scene& scene, const Exponent& exponent,
    const View& view, const Vector& d, const LightView& light, const Halfway& halfway,
    const LocalView& localView, bool gateCrosses);
  void AddPolygon(vtkIdType count, const vtkIdType* ids, vtkPoints* points, vtkDataArray* normals);

  std::vector<Cell> Cells;
  std::vector<Vector> CornerNormals, CornerPositions; ///< AddPolygon's, reused
  std::size_t Triangles = 0;
  std::size_t Points = 0;
  bool Unbounded = true;
  Scene LastScene; ///< Bound's last scene and limit, and its bounds
  double LastLimit = 0.0;
  Bounds LastBounds = { -1.0, -1.0 }; ///< negative: none yet since Update
  Bounds Compute(const Scene& scene, double limit) const;
  vtkMTimeType BuildTime = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongGouraudBound.h
