#include "vtkPhongGouraudBound.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
using Vector = std::array<double, 3>;
constexpr double Pi = 3.14159265358979323846;
constexpr double HalfPi = 0.5 * Pi;
constexpr double Infinite = std::numeric_limits<double>::infinity();
constexpr int CellsPerEdge = 8; // cube-map cells per face edge: 6 * 8 * 8 cells
// A lobe value small enough to bound a cell's lobe by it, without its own bound: 1e-7 of the
// light is far below the float rounding margin (vtkPhongErrorBudget).
constexpr double NegligibleLobe = 1.0e-7;

double Dot(const Vector& a, const Vector& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double Norm(const Vector& a)
{
  return std::sqrt(Dot(a, a));
}

double SquaredDistance(const Vector& a, const Vector& b)
{
  const Vector difference = { { a[0] - b[0], a[1] - b[1], a[2] - b[2] } };
  return Dot(difference, difference);
}

// The angle between unit vectors whose chord has this squared length: the largest angle is
// the longest chord's, so binning compares chords and takes one arcsine per cell at the end.
double ChordAngle(double squaredChord)
{
  return 2.0 * std::asin(std::min(1.0, 0.5 * std::sqrt(squaredChord)));
}

// `a` divided by its length, already known; false (and `a` as it was) for a null vector.
bool NormalizeBy(Vector& a, double length)
{
  if (!(length > 1.0e-12) || !std::isfinite(length))
  {
    return false;
  }
  const double inverse = 1.0 / length;
  for (double& component : a)
  {
    component *= inverse;
  }
  return true;
}

bool Normalize(Vector& a)
{
  return NormalizeBy(a, Norm(a));
}

// The cube-map cell of a unit direction, and that cell's centre direction.
std::size_t CellIndex(const Vector& direction)
{
  int major = 0;
  for (int k = 1; k < 3; ++k)
  {
    major = std::abs(direction[k]) > std::abs(direction[major]) ? k : major;
  }
  const int face = 2 * major + (direction[major] < 0.0 ? 1 : 0);
  const double scale = 1.0 / std::abs(direction[major]);
  auto bin = [&](double coordinate)
  {
    const int i = static_cast<int>(std::floor((coordinate * scale + 1.0) * 0.5 * CellsPerEdge));
    return std::min(std::max(i, 0), CellsPerEdge - 1);
  };
  const int u = bin(direction[(major + 1) % 3]), v = bin(direction[(major + 2) % 3]);
  return static_cast<std::size_t>((face * CellsPerEdge + u) * CellsPerEdge + v);
}

Vector CellCentre(std::size_t index)
{
  const int v = static_cast<int>(index % CellsPerEdge);
  const int u = static_cast<int>((index / CellsPerEdge) % CellsPerEdge);
  const int face = static_cast<int>(index / (CellsPerEdge * CellsPerEdge));
  const int major = face / 2;
  Vector centre;
  centre[major] = (face % 2) ? -1.0 : 1.0;
  centre[(major + 1) % 3] = (u + 0.5) * 2.0 / CellsPerEdge - 1.0;
  centre[(major + 2) % 3] = (v + 0.5) * 2.0 / CellsPerEdge - 1.0;
  Normalize(centre);
  return centre;
}

}

//------------------------------------------------------------------------------
double vtkPhongGouraudBound::LobeBound(double spread, double nearAngle, double farAngle, double n)
{
  const Exponent exponent(n);
  if (nearAngle >= HalfPi)
  {
    return 0.0; // the lobe is 0 over the whole cap
  }
  return LobeBound(Cap(spread), NearAngle(CosSin::Of(std::max(nearAngle, 0.0)), exponent),
    CosSin::Of(farAngle), exponent);
}

//------------------------------------------------------------------------------
// tan(R)^2 / 2, (1 - cos R cos 2R) / sin R = sin R (1 / (1 + cos R) + 2 cos R) (without the
// cancellation of the first form at small R) and sin(R) / 2, from one sine and cosine.
vtkPhongGouraudBound::Cap::Cap(double spread)
  : Spread(spread)
{
  if (spread > 0.0 && spread < 0.25 * Pi) // no sine and cosine for an empty cap
  {
    this->SetTerms(std::sin(spread), std::cos(spread));
  }
}

//------------------------------------------------------------------------------
vtkPhongGouraudBound::Cap::Cap(double spread, double s, double c)
  : Spread(spread)
{
  if (spread > 0.0 && spread < 0.25 * Pi)
  {
    this->SetTerms(s, c);
  }
}

//------------------------------------------------------------------------------
void vtkPhongGouraudBound::Cap::SetTerms(double s, double c)
{
  this->Tangent = s / c;
  this->HalfTangent2 = 0.5 * this->Tangent * this->Tangent;
  this->Radial = s * (1.0 / (1.0 + c) + 2.0 * c);
  this->Kink = 0.5 * s;
  this->Cosine = c;
}

//------------------------------------------------------------------------------
// The peaks of cos^p sin^q (p = n - q) inside [0, pi/2], where tan^2 = q / p: cos^2 = p/(p+q).
vtkPhongGouraudBound::Exponent::Exponent(double n)
  : N(n)
  , Cut(n > 0.0 ? std::acos(std::pow(NegligibleLobe, 1.0 / n)) : Infinite)
  , CosCut(n > 0.0 ? std::cos(Cut) : -1.0)
  , SinCut(n > 0.0 ? std::sin(Cut) : 0.0)
  , Whole(n >= 1.0 && n <= 65536.0 && n == std::floor(n) ? static_cast<unsigned int>(n) : 0)
{
  const auto peak = [n](double q, double& cosine)
  {
    const double p = n - q;
    cosine = p > 0.0 ? std::sqrt(p / (p + q)) : 0.0;
    return p > 0.0 ? std::pow(p / (p + q), 0.5 * p) * std::pow(q / (p + q), 0.5 * q) : 0.0;
  };
  this->CurvaturePeak = peak(2.0, this->CurvaturePeakCos);
  this->SlopePeak = peak(1.0, this->SlopePeakCos);
}

//------------------------------------------------------------------------------
double vtkPhongGouraudBound::Exponent::Power(double x) const
{
  if (this->Whole == 0 && this->N != 0.0)
  {
    return std::pow(x, this->N);
  }
  double power = 1.0;
  for (unsigned int k = this->Whole; k != 0; k >>= 1, x *= x)
  {
    power = (k & 1) ? power * x : power;
  }
  return power;
}

//------------------------------------------------------------------------------
// The cosine is taken as 0 from pi/2 on: HalfPi, a double below pi/2, has a positive one.
vtkPhongGouraudBound::CosSin vtkPhongGouraudBound::CosSin::Of(double angle)
{
  const double clamped = std::min(angle, Pi);
  return { clamped >= HalfPi ? std::min(std::cos(clamped), 0.0) : std::cos(clamped),
    std::max(std::sin(clamped), 0.0) };
}

//------------------------------------------------------------------------------
vtkPhongGouraudBound::NearAngle::NearAngle(const CosSin& angle, const Exponent& exponent)
  : Cos(angle.Cos)
  , Sin(angle.Sin)
  , CosN(angle.Cos <= 0.0 ? 0.0 : exponent.Power(angle.Cos))
{
}

//------------------------------------------------------------------------------
double vtkPhongGouraudBound::LobeBound(
  const Cap& cap, const NearAngle& a, const CosSin& farAngle, const Exponent& exponent)
{
  if (a.Cos <= 0.0)
  {
    return 0.0; // the lobe is 0 over the whole cap
  }
  return CapBound(cap, MakeLobeTerms(a, farAngle, exponent), exponent.N);
}

//------------------------------------------------------------------------------
double vtkPhongGouraudBound::CapBound(const Cap& cap, const LobeTerms& lobe, double n)
{
  if (!(cap.Spread > 0.0) || n == 0.0)
  {
    return 0.0; // equal normals, or a lobe that is 1 wherever it is gated on
  }
  if (cap.Spread >= 0.25 * Pi)
  {
    return Infinite;
  }
  return cap.HalfTangent2 * (lobe.Hs + 2.0 * lobe.G1 * cap.Radial) + (lobe.Kink ? cap.Kink : 0.0);
}

//------------------------------------------------------------------------------
// Below n = 2 the clamp at c = 0 is no longer smooth enough for Waldron's identity: for n = 1
// it is a kink (Kink; LobeBound adds sin(R)/2), otherwise only the largest value bounds
// (every term infinite). `a` below pi/2.
vtkPhongGouraudBound::LobeTerms vtkPhongGouraudBound::MakeLobeTerms(
  const NearAngle& a, const CosSin& farAngle, const Exponent& exponent)
{
  const double n = exponent.N;
  LobeTerms lobe;
  lobe.Kink = n < 2.0 && farAngle.Cos <= 0.0;
  if (lobe.Kink && n != 1.0)
  {
    lobe.Hs = lobe.G1 = lobe.Hx = Infinite;
    return lobe;
  }
  // sup over alpha in [a, b] of cos^p sin^q, p = n - q, q in {1, 2}: unimodal on [0, pi/2],
  // its peak where tan^2 = q / p (increasing when p <= 0, the peak then pi/2): at a past the
  // peak, the peak's value (made once per exponent) around it, at b before it. Angles in
  // [0, pi] compare by their cosines, reversed.
  const double cosB = std::max(farAngle.Cos, 0.0); // b = min(far, pi/2)
  const double sinB = farAngle.Cos <= 0.0 ? 1.0 : farAngle.Sin;
  const auto sup = [&](int q, double peak, double peakCos)
  {
    const double p = n - q;
    const auto toQ = [q](double value) { return q == 2 ? value * value : value; };
    if (p > 0.0 && a.Cos <= peakCos)
    {
      const double cosQ = toQ(a.Cos); // cos^p = cos^n / cos^q, cos(a) > 0 here
      return (cosQ > 1.0e-100 ? a.CosN / cosQ : std::pow(a.Cos, p)) * toQ(a.Sin);
    }
    if (p > 0.0 && cosB < peakCos)
    {
      return peak;
    }
    if (p < 0.0 && cosB <= 1.0e-12)
    {
      return Infinite; // cos^p grows without bound at the lobe's edge
    }
    return std::pow(cosB, p) * toQ(sinB);
  };
  // d2/dalpha2 cos^n = n(n-1) cos^(n-2) sin^2 - n cos^n; s'(c) c = n cos^n;
  // s'(c) sin = n cos^(n-1) sin; s'(c) = n cos^(n-1), largest at a for n >= 1.
  const double curvature = n * std::abs(n - 1.0); // 0 for the diffuse term's n = 1
  const double bend =
    curvature > 0.0 ? curvature * sup(2, exponent.CurvaturePeak, exponent.CurvaturePeakCos) : 0.0;
  lobe.Hs = bend + n * a.CosN;
  lobe.G1 = n * sup(1, exponent.SlopePeak, exponent.SlopePeakCos);
  double slope = Infinite; // sup s'(c), for 0 < n < 1 at the far angle
  if (n >= 1.0)
  {
    slope = n * (a.Cos > 1.0e-100 ? a.CosN / a.Cos : std::pow(a.Cos, n - 1.0));
  }
  else if (cosB > 0.0)
  {
    slope = n * std::pow(cosB, n - 1.0);
  }
  lobe.Hx = bend + std::max(n * a.CosN, slope);
  if (lobe.Kink)
  {
    // n = 1: the unclamped cosine, whose interpolation the kink's bound adds to, curves by
    // |cos| up to the far angle, past pi/2 too.
    lobe.Hs = std::max(lobe.Hs, -farAngle.Cos);
  }
  return lobe;
}

//------------------------------------------------------------------------------
void vtkPhongGouraudBound::Update(const std::vector<vtkPolyData*>& blocks, vtkMTimeType buildTime)
{
  if (buildTime == this->BuildTime && !this->Cells.empty())
  {
    return;
  }
  this->BuildTime = buildTime;
  this->Cells.assign(6 * CellsPerEdge * CellsPerEdge, Cell());
  for (std::size_t i = 0; i < this->Cells.size(); ++i)
  {
    this->Cells[i].Axis = CellCentre(i);
  }
  this->Triangles = 0;
  this->Points = 0;
  this->Unbounded = false;
  this->LastBounds = { -1.0, -1.0 };
  for (vtkPolyData* block : blocks)
  {
    vtkDataArray* normals = block->GetPointData()->GetNormals();
    vtkPoints* points = block->GetPoints();
    if (!normals || normals->GetNumberOfComponents() != 3 || !points ||
      block->GetNumberOfStrips() > 0)
    {
      this->Unbounded = true;
      break;
    }
    this->Points += static_cast<std::size_t>(points->GetNumberOfPoints());
    auto polys = vtk::TakeSmartPointer(block->GetPolys()->NewIterator());
    for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal() && !this->Unbounded;
         polys->GoToNextCell())
    {
      vtkIdType count;
      const vtkIdType* ids;
      polys->GetCurrentCell(count, ids);
      this->AddPolygon(count, ids, points, normals);
    }
  }
  for (Cell& cell : this->Cells)
  {
    cell.Cone = ChordAngle(cell.Cone);
    cell.Spread = ChordAngle(cell.Spread);
    cell.Radius = std::sqrt(cell.Radius);
    Vector diagonal;
    for (int k = 0; k < 3; ++k)
    {
      diagonal[k] = cell.High[k] - cell.Low[k];
      cell.Centre[k] = 0.5 * (cell.Low[k] + cell.High[k]);
    }
    cell.Reach = 0.5 * Norm(diagonal);
    cell.Normals = Cap(cell.Spread);
    cell.Reflections = Cap(2.0 * cell.Spread);
    cell.ReflectionSkew = ReflectionSkew(cell.Spread, LocalView());
    cell.CosWidth = std::cos(cell.Cone + cell.Spread);
    cell.SinWidth = std::sin(cell.Cone + cell.Spread);
  }
  if (this->Unbounded)
  {
    this->Triangles = 0;
  }
}

//------------------------------------------------------------------------------
// One polygon as one cap: the cap of all its normals contains each triangle's that VTK cuts
// it into, and the ball around its points each triangle's ball. The cell keeps squares while
// binning (of the chords for its cone and spread, of the radius), Update their roots.
void vtkPhongGouraudBound::AddPolygon(
  vtkIdType count, const vtkIdType* ids, vtkPoints* points, vtkDataArray* normals)
{
  if (count < 3)
  {
    return;
  }
  // Reused from polygon to polygon: an allocation each would cost more than the rest.
  std::vector<Vector>& unit = this->CornerNormals;
  std::vector<Vector>& position = this->CornerPositions;
  unit.resize(count);
  position.resize(count);
  Vector axis = { { 0.0, 0.0, 0.0 } }, centroid = { { 0.0, 0.0, 0.0 } };
  for (vtkIdType i = 0; i < count; ++i)
  {
    normals->GetTuple(ids[i], unit[i].data());
    points->GetPoint(ids[i], position[i].data());
    if (!Normalize(unit[i]))
    {
      this->Unbounded = true; // lit as N = V per vertex, by the face per fragment
      return;
    }
    for (int k = 0; k < 3; ++k)
    {
      axis[k] += unit[i][k];
      centroid[k] += position[i][k] / count;
    }
  }
  if (!Normalize(axis))
  {
    this->Unbounded = true; // normals that cancel out
    return;
  }
  Cell& cell = this->Cells[CellIndex(axis)];
  cell.Cone = std::max(cell.Cone, SquaredDistance(cell.Axis, axis));
  for (vtkIdType i = 0; i < count; ++i)
  {
    cell.Spread = std::max(cell.Spread, SquaredDistance(axis, unit[i]));
    cell.Radius = std::max(cell.Radius, SquaredDistance(position[i], centroid));
    for (int k = 0; k < 3; ++k)
    {
      cell.Low[k] = std::min(cell.Low[k], position[i][k]);
      cell.High[k] = std::max(cell.High[k], position[i][k]);
    }
  }
  ++cell.Count;
  ++this->Triangles;
}

//------------------------------------------------------------------------------
bool vtkPhongGouraudBound::Scene::Light::operator==(const Light& other) const
{
  return this->ToLightMC == other.ToLightMC && this->Diffuse == other.Diffuse &&
    this->Specular == other.Specular && this->Positional == other.Positional &&
    this->PositionMC == other.PositionMC && this->AttenuationMC == other.AttenuationMC;
}

//------------------------------------------------------------------------------
bool vtkPhongGouraudBound::Scene::operator==(const Scene& other) const
{
  return this->Lights == other.Lights && this->Parallel == other.Parallel &&
    this->ToEyeMC == other.ToEyeMC && this->EyeMC == other.EyeMC &&
    this->Shininess == other.Shininess && this->Blinn == other.Blinn &&
    this->TwoSided == other.TwoSided && this->SmoothTerminator == other.SmoothTerminator;
}

//------------------------------------------------------------------------------
vtkPhongGouraudBound::Bounds vtkPhongGouraudBound::Bound(const Scene& scene, double limit)
{
  if (this->LastBounds.PerVertex < 0.0 || !(scene == this->LastScene) || limit != this->LastLimit)
  {
    this->LastScene = scene;
    this->LastLimit = limit;
    this->LastBounds = this->Compute(scene, limit);
  }
  return this->LastBounds;
}

//------------------------------------------------------------------------------
vtkPhongGouraudBound::Bounds vtkPhongGouraudBound::Compute(const Scene& scene, double limit) const
{
  Bounds largest = { Infinite, Infinite };
  if (this->Unbounded || this->Triangles == 0)
  {
    return largest;
  }
  largest = { 0.0, 0.0 };
  const Exponent exponent(scene.Shininess);
  std::vector<Halfway> halfways(scene.Lights.size());
  CellScratch scratch; // CellBound's, reused from cell to cell
  bool halfwaysMade = false;
  for (const Cell& cell : this->Cells)
  {
    View view;
    if (cell.Count == 0)
    {
      continue;
    }
    if (!MakeView(scene, cell, view))
    {
      return { Infinite, Infinite };
    }
    // In parallel projection the view, and so the halfway vectors, are the same for every cell.
    if (!scene.Parallel || !halfwaysMade)
    {
      halfwaysMade = true;
      for (std::size_t i = 0; i < scene.Lights.size(); ++i)
      {
        if (!scene.Lights[i].Positional) // a point light's, per cell (CellBound)
        {
          LightView directional;
          directional.ToLight = scene.Lights[i].ToLightMC;
          halfways[i] = MakeHalfway(scene, view, directional);
        }
      }
    }
    const Bounds bounds = CellBound(cell, scene, exponent, view, halfways, scratch);
    largest.PerVertex = std::max(largest.PerVertex, bounds.PerVertex);
    largest.SpecularPerVertex = std::max(largest.SpecularPerVertex, bounds.SpecularPerVertex);
    // Both past the limit (PerVertex adds the diffuse terms, but under a point light
    // SpecularPerVertex is infinite from the first cell on).
    if (std::min(largest.PerVertex, largest.SpecularPerVertex) > limit)
    {
      break;
    }
  }
  return largest;
}

//------------------------------------------------------------------------------
// Blinn's halfway vector between a light and the view cone's centre, and |L + V| at its least
// over the cone and the light's (`lightSpread`, its half-angle; 0 for a directional light,
// whose halfway vector in parallel projection is the same for every cell, so made once).
vtkPhongGouraudBound::Halfway vtkPhongGouraudBound::MakeHalfway(
  const Scene& scene, const View& view, const LightView& light)
{
  const Vector& toLight = light.ToLight;
  const double lightSpread = light.Spread;
  Halfway halfway;
  if (!scene.Blinn)
  {
    return halfway;
  }
  // |L + V| = 2 cos(g/2) and |L - V| = 2 sin(g/2) for the angle g between them; at its least
  // over the cones |L + V| = 2 cos((g + spread)/2), 0 once that passes pi.
  double cosHalf = view.CosHalfSpread, sinHalf = view.SinHalfSpread;
  if (lightSpread > 0.0)
  {
    // Half the sum of the two cones' angles, h (the light's a tangent, at least its angle):
    // cos h >= 1 - h^2/2 and sin h <= h bound the least |L + V| below with no root and no
    // division per light and cell (past pi it comes out negative, so 0: unbounded).
    const double h = 0.5 * (view.Spread + lightSpread);
    cosHalf = 1.0 - 0.5 * h * h;
    sinHalf = h;
  }
  halfway.Direction = { { toLight[0] + view.Centre[0], toLight[1] + view.Centre[1],
    toLight[2] + view.Centre[2] } };
  const Vector difference = { { toLight[0] - view.Centre[0], toLight[1] - view.Centre[1],
    toLight[2] - view.Centre[2] } };
  const double sumLength = Norm(halfway.Direction);
  halfway.Least = std::max(sumLength * cosHalf - Norm(difference) * sinHalf, 0.0);
  const bool opposite = !NormalizeBy(halfway.Direction, sumLength);
  const bool fixed = scene.Parallel && lightSpread == 0.0; // L and V the same everywhere
  halfway.LobeZero = fixed && opposite;                    // L = -V everywhere: the lobe is 0
  // H turns without bound as V or L does.
  halfway.Unbounded = !halfway.LobeZero && (opposite || (!fixed && !(halfway.Least > 1.0e-3)));
  return halfway;
}

//------------------------------------------------------------------------------
// The view vector over one cell's triangles: its direction towards the eye from the centre of
// the cell's ball, the half-angle of the cone holding it over the ball, and the eye's least
// distance.
bool vtkPhongGouraudBound::MakeView(const Scene& scene, const Cell& cell, View& view)
{
  if (scene.Parallel)
  {
    view.Centre = scene.ToEyeMC;
    return Normalize(view.Centre);
  }
  for (int k = 0; k < 3; ++k)
  {
    view.Centre[k] = scene.EyeMC[k] - cell.Centre[k];
  }
  const double distance = Norm(view.Centre);
  const double radius = cell.Reach;
  if (!(distance > 1.01 * radius) || !Normalize(view.Centre))
  {
    return false; // the eye inside or at the cell's ball: V takes every direction
  }
  // The half angle's cosine and sine from the angle's, which radius / distance gives.
  const double sinSpread = radius / distance;
  view.Spread = std::asin(sinSpread);
  view.CosHalfSpread = std::sqrt(0.5 * (1.0 + std::sqrt(1.0 - sinSpread * sinSpread)));
  view.SinHalfSpread = sinSpread / (2.0 * view.CosHalfSpread);
  view.Nearest = distance - radius;
  return true;
}

//------------------------------------------------------------------------------
// Every triangle of the cell, on each side (as is; reversed: two-sided back faces). The
// angles between the light and the cell's normals, [toLight - width, toLight + width], go by
// their cosines and sines (no arctangent per light and cell: this runs per frame).
vtkPhongGouraudBound::Bounds vtkPhongGouraudBound::CellBound(const Cell& cell, const Scene& scene,
  const Exponent& exponent, const View& view, const std::vector<Halfway>& halfways,
  CellScratch& scratch)
{
  const LocalView localView = MakeLocalView(scene, cell, view);
  const double cosGateOpen = std::sin(1.0e-3); // cos(pi/2 - 1e-3)
  bool positional = false;
  if (!MakeLightViews(cell, scene, view, scratch, positional))
  {
    return { Infinite, Infinite };
  }
  const std::vector<LightView>& lights = scratch.Lights;
  const std::vector<Halfway>& pointHalfways = scratch.Halfways;
  // Per side (as is; reversed: two-sided back faces), the sums' bounds; each light's angles
  // are made once for both sides (the reversed side's cosine is the negated one).
  const int sides = scene.TwoSided ? 2 : 1;
  const Vector axes[2] = { cell.Axis, { { -cell.Axis[0], -cell.Axis[1], -cell.Axis[2] } } };
  double diffuse[2] = { 0.0, 0.0 }, specular[2] = { 0.0, 0.0 };
  for (std::size_t i = 0; i < scene.Lights.size(); ++i)
  {
    const Scene::Light& light = scene.Lights[i];
    const LightView& toLight = lights[i];
    // The angles between the light and the cell's normals: within Cone + Spread (and the
    // light's cone over the cell) around the axis.
    const double width = cell.Cone + cell.Spread + toLight.Spread;
    const bool wide = width >= HalfPi;
    // cos and sin of the sum, from the cell's and the light's own (no cosine per light).
    const double cosWidth = cell.CosWidth * toLight.CosSpread - cell.SinWidth * toLight.SinSpread;
    const double sinWidth = cell.SinWidth * toLight.CosSpread + cell.CosWidth * toLight.SinSpread;
    const double axisCos = std::min(std::max(Dot(cell.Axis, toLight.ToLight), -1.0), 1.0);
    const double s = std::sqrt(1.0 - axisCos * axisCos);
    for (int side = 0; side < sides; ++side)
    {
      const double c = side == 0 ? axisCos : -axisCos; // cos(toLight) from this side's axis
      if (!wide && c <= -sinWidth)
      {
        continue; // every normal faces away (near angle >= pi/2): no diffuse, the gate shut
      }
      const double cosNear = c >= cosWidth ? 1.0 : c * cosWidth + s * sinWidth;
      // cos(toLight + width), or -1 once the far angle would pass pi.
      const double cosFar =
        wide || c * sinWidth + s * cosWidth < 0.0 ? -1.0 : c * cosWidth - s * sinWidth;
      const double sinFar = cosFar <= 0.0 ? 1.0 : s * cosWidth + c * sinWidth; // of min(far, pi/2)
      double term = DiffuseBound(cell.Normals, cosNear, cosFar, sinFar);
      if (light.Positional)
      {
        term = std::min(
          term + LightSpreadBound(cell.Normals, toLight.Local, cosNear, cosFar, sinFar), cosNear);
      }
      // Attenuated: sum b_i A_i g_i - A g = A (sum b_i g_i - g) + sum b_i (A_i - A) g_i, within
      // Fade times the unattenuated bound plus FadeChange times the largest g_i.
      diffuse[side] +=
        toLight.Fade * light.Diffuse * term + toLight.FadeChange * (light.Diffuse + light.Specular);
      if (light.Specular > 0.0)
      {
        specular[side] += toLight.Fade * light.Specular *
          SpecularBound(cell, scene, exponent, view, axes[side], toLight,
            light.Positional ? pointHalfways[i] : halfways[i], localView, cosFar <= cosGateOpen);
      }
    }
  }
  // NaN, from a degenerate input, bounds nothing.
  const auto bounded = [](double value) { return value >= 0.0 ? value : Infinite; };
  Bounds largest = { 0.0, 0.0 };
  for (int side = 0; side < sides; ++side)
  {
    largest.PerVertex = std::max(largest.PerVertex, bounded(diffuse[side] + specular[side]));
    // That mode lights only the directional lights' diffuse term per fragment.
    largest.SpecularPerVertex =
      std::max(largest.SpecularPerVertex, positional ? Infinite : bounded(specular[side]));
  }
  return largest;
}

//------------------------------------------------------------------------------
// Each light over the cell (into `scratch`); a point light's cone and halfway vector are the
// cell's own. False where a point light is too close to the cell to bound it.
bool vtkPhongGouraudBound::MakeLightViews(
  const Cell& cell, const Scene& scene, const View& view, CellScratch& scratch, bool& positional)
{
  // A directional light's view is the same for every cell: made once.
  const bool first = !scratch.DirectionalMade;
  scratch.Lights.resize(scene.Lights.size());
  scratch.Halfways.resize(scene.Lights.size());
  positional = false;
  for (std::size_t i = 0; i < scene.Lights.size(); ++i)
  {
    if ((first || scene.Lights[i].Positional) &&
      !MakeLightView(scene.Lights[i], cell, scratch.Lights[i]))
    {
      return false;
    }
    if (scene.Lights[i].Positional)
    {
      positional = true;
      scratch.Halfways[i] = MakeHalfway(scene, view, scratch.Lights[i]);
    }
  }
  scratch.DirectionalMade = true;
  return true;
}

//------------------------------------------------------------------------------
// The view vector over one triangle of the cell, in perspective (0 and 0 in parallel
// projection). Its vertices' eye vectors w_i (lengths d_i) lie in a cone of half-angle rho,
// sin(rho) <= r / D, r the triangle's radius and D the eye's least distance (Spread = rho).
// At a fragment the view vector is w(b) = sum b_i w_i normalized, not the normalized
// interpolation u(b) of the unit vectors v_i that the cap model takes: with e_i = d_i / d_min - 1
// in [0, delta], delta <= 2r / D, w(b) / d_min = u + e for e = sum b_i e_i v_i, and
// |u + e| >= cos(rho) (along the cone's axis), |e across u| <= delta sin(2 rho), so the angle
// between them has a sine of at most 2 delta sin(rho) <= 4 r^2 / D^2 (Skew; for r / D < 1/2).
vtkPhongGouraudBound::LocalView vtkPhongGouraudBound::MakeLocalView(
  const Scene& scene, const Cell& cell, const View& view)
{
  return scene.Parallel ? LocalView() : MakeLocalSpread(cell.Radius, view.Nearest);
}

//------------------------------------------------------------------------------
// The same for a point at least `nearest` from a triangle of radius `radius` (a point light).
vtkPhongGouraudBound::LocalView vtkPhongGouraudBound::MakeLocalSpread(double radius, double nearest)
{
  LocalView local;
  const double sine = radius / nearest;
  if (!(sine < 0.5))
  {
    local.Spread = local.Skew = Infinite;
    return local;
  }
  // The angles only widen what they are added to: tangents, at least the angles, spare an
  // arcsine each per light and cell. The spread's is tan(asin sine); the skew's sine y is
  // below 1 here (sine < 0.5), and y / (1 - y^2) >= y / sqrt(1 - y^2) = tan(asin y).
  const double cosine = std::sqrt(1.0 - sine * sine);
  local.Directions = Cap(sine / cosine, sine, cosine);
  local.Spread = local.Directions.Spread;
  const double skewSine = 4.0 * sine * sine;
  local.Skew = skewSine / (1.0 - skewSine * skewSine);
  return local;
}

//------------------------------------------------------------------------------
// A point light over a cell: the direction from the cell's centre towards it, the cone that
// holds that direction over the cell's ball, and its spread and skew over one triangle
// (MakeLocalSpread). False where the light is in or at the ball: L then takes every direction.
bool vtkPhongGouraudBound::MakeLightView(
  const Scene::Light& light, const Cell& cell, LightView& lightView)
{
  if (!light.Positional)
  {
    lightView = LightView();
    lightView.ToLight = light.ToLightMC;
    return true;
  }
  // Every member is set below (no reset: this runs per light and cell).
  for (int k = 0; k < 3; ++k)
  {
    lightView.ToLight[k] = light.PositionMC[k] - cell.Centre[k];
  }
  const double distance = Norm(lightView.ToLight);
  if (!(distance > 1.01 * cell.Reach) || !std::isfinite(distance))
  {
    return false;
  }
  const double inverse = 1.0 / distance; // one division per light and cell, not four
  for (double& component : lightView.ToLight)
  {
    component *= inverse;
  }
  lightView.SinSpread = cell.Reach * inverse;
  lightView.CosSpread = std::sqrt(1.0 - lightView.SinSpread * lightView.SinSpread);
  // The angle only widens angles it is added to: its tangent, at least the angle, spares an
  // arcsine per light and cell (the cosine and sine are the angle's own).
  lightView.Spread = lightView.SinSpread / lightView.CosSpread;
  lightView.Local = MakeLocalSpread(cell.Radius, distance - cell.Reach);
  // The attenuation over the ball: at most its value nearest, and between two points of one
  // triangle (at most 2 Radius apart) its steepest slope times that (mean value theorem).
  lightView.Fade = light.AttenuationMC.At(distance - cell.Reach);
  lightView.FadeChange =
    light.AttenuationMC.SteepestOver(distance - cell.Reach, distance + cell.Reach) * 2.0 *
    cell.Radius;
  return std::isfinite(lightView.Local.Spread) && std::isfinite(lightView.FadeChange);
}

//------------------------------------------------------------------------------
// Phong's lobe reflects the interpolated normal N(b) = m / |m|, m = sum b_i n_i, where the cap
// model interpolates the reflected vectors r_i = r(n_i, l_i) = 2 (n_i.l_i) n_i - l_i. With
// d_i = n_i - N, for one light direction L, sum b_i r_i = r(N) + 4 (|m| - 1)(N.L) N +
// 2 sum b_i (d_i.L) d_i, and sum b_i |d_i|^2 = 2 (1 - |m|) <= 2 (1 - cos R): the two differ by
// at most 8 (1 - cos R). A point light's direction l_i differs from vertex to vertex, in a cap
// of radius sigma (`light`; LocalView() for a directional light): with l_i = lbar + lambda_i
// (lbar = sum b_i l_i), sum b_i r_i - r(N, lbar) adds 2 sum b_i ((N.lambda_i) d_i +
// (d_i.lambda_i) n_i), at most 4 sin(sigma) sqrt(2 (1 - cos R)) (|n_i| = 1, sum b_i
// |lambda_i|^2 <= sin^2 sigma); and r(N, lbar) - r(N, L) = reflect(lbar - L), |lbar - L| <=
// 1 - cos(sigma) + the light vector's skew (MakeLocalSpread). Their sum e bounds the angle
// between the directions by asin(e) while e < 1.
double vtkPhongGouraudBound::ReflectionSkew(double spread, const LocalView& light)
{
  // sin(sigma) and cos(sigma) are the light's cap's own (its Spread is a tangent).
  const double half = std::sin(0.5 * spread);
  const double sinLight = 2.0 * light.Directions.Kink;
  const double e =
    16.0 * half * half + 8.0 * sinLight * half + (1.0 - light.Directions.Cosine) + light.Skew;
  return e < 1.0 ? std::asin(e) : Infinite;
}

//------------------------------------------------------------------------------
// The sup of |d/dalpha max(cos(alpha), 0)^n| for alpha from `a` to pi/2: n cos^(n-1) sin,
// whose one peak is where the cosine is SlopePeakCos (n > 1); for n = 1, sin; unbounded for
// 0 < n < 1.
double vtkPhongGouraudBound::SlopeBeyond(const NearAngle& a, const Exponent& exponent)
{
  const double n = exponent.N;
  if (!(n > 0.0) || a.Cos <= 0.0)
  {
    return 0.0;
  }
  if (n < 1.0)
  {
    return Infinite;
  }
  if (n == 1.0)
  {
    return 1.0;
  }
  return a.Cos >= exponent.SlopePeakCos ? n * exponent.SlopePeak : n * a.CosN / a.Cos * a.Sin;
}

//------------------------------------------------------------------------------
// max(N.L, 0): the lobe bound with n = 1 (the terminator a kink), never more than the
// term's largest value: for n = 1, Hs = DiffuseCurvature, G1 = sin(min(far, pi/2)).
double vtkPhongGouraudBound::DiffuseBound(
  const Cap& normals, double cosNear, double cosFar, double sinFar)
{
  if (!(normals.Spread > 0.0))
  {
    return 0.0;
  }
  if (normals.Spread >= 0.25 * Pi)
  {
    return cosNear;
  }
  const bool terminator = cosFar <= 0.0;
  const double bound =
    normals.HalfTangent2 * (DiffuseCurvature(cosNear, cosFar) + 2.0 * sinFar * normals.Radial) +
    (terminator ? normals.Kink : 0.0);
  return std::min(bound, cosNear);
}

//------------------------------------------------------------------------------
// Hs of the diffuse term: the cosine's curvature |cos|, unclamped where the kink's bound takes
// the clamp, so up to the far angle past pi/2 too (cosFar: of min(far, pi), -1 beyond).
double vtkPhongGouraudBound::DiffuseCurvature(double cosNear, double cosFar)
{
  return std::max(cosNear, -cosFar);
}

//------------------------------------------------------------------------------
// What a point light's spread over a triangle adds to the diffuse term's bound: Waldron's
// identity for the normal and the light's direction l interpolated together is
// ViewSpreadBound's for Phong, whose lobe's axis is the view vector, with the light's
// directions in its place and the n = 1 lobe's terms (Hs DiffuseCurvature, G1 sin of the far
// angle, Hx = 1, the kink at the terminator); then the skew of the interpolated light vector
// at the cosine's slope, sin.
double vtkPhongGouraudBound::LightSpreadBound(
  const Cap& normals, const LocalView& localLight, double cosNear, double cosFar, double sinFar)
{
  if (normals.Spread >= 0.25 * Pi)
  {
    return Infinite;
  }
  LobeTerms cosine;
  cosine.Hs = DiffuseCurvature(cosNear, cosFar);
  cosine.G1 = sinFar;
  cosine.Hx = 1.0;
  cosine.Kink = cosFar <= 0.0;
  return ViewSpreadBound(cosine, normals, localLight, LocalView(), false, 1.0) +
    localLight.Skew * sinFar;
}

//------------------------------------------------------------------------------
double vtkPhongGouraudBound::SpecularBound(const Cell& cell, const Scene& scene,
  const Exponent& exponent, const View& view, const Vector& d, const LightView& light,
  const Halfway& halfway, const LocalView& localView, bool gateCrosses)
{
  const Vector& toLight = light.ToLight;
  // The lobe's axis against the cell's normals: Blinn's H against N, or Phong's reflected
  // vector (which turns twice as far as N) against V.
  // The width: the cell's angles (`base`, `baseAngle`) and the view's and light's (`extra`).
  double width, baseAngle, extra;
  CosSin base = { cell.CosWidth, cell.SinWidth };
  // The lobe's axis, and the direction its angle is measured from.
  Vector axis = halfway.Direction, from = d;
  if (scene.Blinn)
  {
    if (halfway.LobeZero || halfway.Unbounded)
    {
      return halfway.LobeZero ? 0.0 : Infinite;
    }
    baseAngle = cell.Cone + cell.Spread;
    extra = (view.Spread + light.Spread) / halfway.Least;
  }
  else
  {
    const double c = Dot(d, toLight);
    from = { { 2.0 * c * d[0] - toLight[0], 2.0 * c * d[1] - toLight[1],
      2.0 * c * d[2] - toLight[2] } };
    axis = view.Centre;
    baseAngle = 2.0 * (cell.Cone + cell.Spread);
    extra = view.Spread + light.Spread;
    base = { cell.CosWidth * cell.CosWidth - cell.SinWidth * cell.SinWidth,
      2.0 * cell.SinWidth * cell.CosWidth };
  }
  width = baseAngle + extra;
  // Most cells lie beyond the lobe: told by a cosine, before any angle is taken. With
  // Cut <= pi/2, cos(Cut + width) >= cos(Cut) (1 - width^2 / 2) - sin(Cut) width, which needs
  // no cosine per light and cell; a cell it misses is told by the angle below.
  if (exponent.Cut + width < Pi &&
    Dot(from, axis) <= exponent.CosCut * (1.0 - 0.5 * width * width) - exponent.SinCut * width)
  {
    return NegligibleLobe;
  }
  CosSin nearAngle, farAngle;
  LobeRange(from, axis, Widen(base, baseAngle, extra), nearAngle, farAngle);
  // Where the lobe is below 1e-7 of the light over the whole cell (most cells, for all but the
  // widest lobes), that bounds it: no power and no lobe bound.
  if (exponent.N > 0.0 && nearAngle.Cos <= exponent.CosCut)
  {
    return NegligibleLobe;
  }
  const NearAngle a(nearAngle, exponent);
  const double largest = a.CosN;
  // The gate (N.L > 1e-4) or the smooth terminator crossing the cell: only the largest value.
  if (scene.SmoothTerminator || gateCrosses)
  {
    return largest;
  }
  // The view vector's skew (MakeLocalView), and a point light's, turn the lobe's axis by
  // that angle (Phong) or by at most that over |L + V| (Blinn: dH = dV across H / |L + V|);
  // within the cell's angles, the lobe changes by at most its slope there times the turn.
  // Phong's reflection of the interpolated normal turns it further (ReflectionSkew).
  const bool positional = light.Spread > 0.0;
  const double turn = scene.Blinn ? (localView.Skew + light.Local.Skew) / halfway.Least
                                  : localView.Skew +
      (positional ? ReflectionSkew(cell.Spread, light.Local) : cell.ReflectionSkew);
  // A lobe with no slope there (n = 0) is not turned, however far its axis turns.
  const double slope = turn > 0.0 ? SlopeBeyond(a, exponent) : 0.0;
  const double skew = slope > 0.0 ? turn * slope : 0.0;
  // The lobe's axis fixed (the cap of the normals, or of Phong's reflected vectors, which a
  // point light's spread widens), then the spread of the view vector (and for Blinn the
  // light's) over the triangle.
  const Cap reflections =
    !scene.Blinn && positional ? Cap(2.0 * cell.Spread + light.Local.Spread) : Cap();
  const Cap& lobeCap = scene.Blinn ? cell.Normals : (positional ? reflections : cell.Reflections);
  const LobeTerms lobe = MakeLobeTerms(a, farAngle, exponent);
  const LocalView& turningLight = scene.Blinn ? light.Local : LocalView();
  const bool spread = localView.Spread > 0.0 || turningLight.Spread > 0.0;
  const double axisSpread = spread && exponent.N != 0.0
    ? ViewSpreadBound(lobe, lobeCap, localView, turningLight, scene.Blinn, halfway.Least)
    : 0.0;
  return std::min(largest, CapBound(lobeCap, lobe, exponent.N) + axisSpread + skew);
}

//------------------------------------------------------------------------------
// The cosine and sine of an angle at least `baseAngle` + `extra` (at most pi), from
// `base`'s: `extra` taken as asin(extra) >= extra, whose cosine is a root, and added by the
// addition formulas; by std::cos and std::sin only where that could pass pi, or extra > 1/2.
vtkPhongGouraudBound::CosSin vtkPhongGouraudBound::Widen(
  const CosSin& base, double baseAngle, double extra)
{
  // asin(x) <= 1.05 x for x <= 1/2.
  if (extra > 0.5 || !(baseAngle + 1.05 * extra < Pi))
  {
    return CosSin::Of(baseAngle + extra);
  }
  const double cosExtra = std::sqrt(1.0 - extra * extra);
  return { base.Cos * cosExtra - base.Sin * extra,
    std::max(base.Sin * cosExtra + base.Cos * extra, 0.0) };
}

//------------------------------------------------------------------------------
// The angles between the unit vectors `from` and `axis`, less and plus `width` (each in
// [0, pi]; width in [0, pi] too), by their cosines and sines: the angle's cosine is the dot
// product and its sine the cross product's length (accurate at 0, where a root of 1 - cos^2
// is not), and the difference and the sum follow by the addition formulas.
void vtkPhongGouraudBound::LobeRange(
  const Vector& from, const Vector& axis, const CosSin& width, CosSin& nearAngle, CosSin& farAngle)
{
  const double c = std::min(std::max(Dot(from, axis), -1.0), 1.0);
  const Vector cross = { { from[1] * axis[2] - from[2] * axis[1],
    from[2] * axis[0] - from[0] * axis[2], from[0] * axis[1] - from[1] * axis[0] } };
  const double s = std::min(Norm(cross), 1.0);
  nearAngle = c >= width.Cos // the angle within the width
    ? CosSin()
    : CosSin{ std::min(c * width.Cos + s * width.Sin, 1.0),
        std::max(s * width.Cos - c * width.Sin, 0.0) };
  farAngle = c <= -width.Cos // the angle at least pi - width
    ? CosSin{ -1.0, 0.0 }
    : CosSin{ std::max(c * width.Cos - s * width.Sin, -1.0),
        std::max(s * width.Cos + c * width.Sin, 0.0) };
}

//------------------------------------------------------------------------------
// What the view vector's spread over a triangle adds to LobeBound, in perspective. Waldron's
// identity, applied to the normal and the view vector interpolated together (the points
// X_i = (n_i, v_i) of R^6, v_i the vertices' unit view vectors in a cap of radius rho, and
// phi(m, v) = s(c), c the cosine between the lobe's axis and the vector it is measured from),
// gives G - F = 1/2 sum b_i Q_i, Q_i the Hessian of phi at points between X(b) and X_i applied
// to d_i = (a_i, e_i) = X_i - X(b), where sum b_i |a_i|^2 <= sin^2 R and sum b_i |e_i|^2 <=
// sin^2 rho. Its part in a_i alone is LobeBound's. Of the rest (docs/lighting-model.md):
// - the mixed part: with dN and dH the turns the two vectors take, s''(dN.H)(N.dH) + s' dN.dH
//   is at most Hx |dN| |dH|; |dN| <= |a| / cos R, |dH| <= k |e| / cos rho (Blinn: k = 1 / |L + V|
//   at its least; Phong, where V is the lobe's axis: k = 1), so it adds Hx tan R tan rho k;
// - the part in e_i alone: Phong's is LobeBound's for the view vectors' cap; Blinn's H moves
//   by dH and bends by at most (k^2 + 1.1548 k) |e|^2 / cos^2 rho across H (the second
//   derivatives of two normalizations), so it adds tan^2 rho / 2 (Hs k^2 + G1 (k^2 + 1.1548 k)).
// The kink of an n = 1 lobe grows from sin(R) / 2 to sin(R + k rho) / 2.
double vtkPhongGouraudBound::ViewSpreadBound(const LobeTerms& lobe, const Cap& normals,
  const LocalView& localView, const LocalView& localLight, bool blinn, double halfwayLeast)
{
  const Cap& views = localView.Directions;
  const Cap& lights = localLight.Directions;
  if (views.Spread >= 0.25 * Pi || lights.Spread >= 0.25 * Pi || !(halfwayLeast > 0.0 || !blinn))
  {
    return Infinite;
  }
  const double k = blinn ? 1.0 / halfwayLeast : 1.0;
  // Blinn's H = (v + l) / |v + l| turns with both: |dh| <= |e_v| / cos + |e_l| / cos, whose
  // sum over b_i of squares is at most (tan rho_v + tan rho_l)^2.
  const double tangent = views.Tangent + lights.Tangent;
  const double mixed = lobe.Hx * normals.Tangent * tangent * k;
  const double alone = blinn ? 0.5 * tangent * tangent * (lobe.Hs + lobe.G1) * k * k +
      (views.HalfTangent2 + lights.HalfTangent2) * lobe.G1 * 1.1548 * k
                             : views.HalfTangent2 * (lobe.Hs + 2.0 * lobe.G1 * views.Radial);
  double kink = 0.0;
  if (lobe.Kink)
  {
    // sin(min(R + x, pi/2)) - sin(R) <= min(x cos R, 1 - sin R), the sine being concave there
    // (no sine per light and cell).
    const double turn = k * (views.Spread + lights.Spread);
    kink = 0.5 * std::min(turn * normals.Cosine, 1.0 - 2.0 * normals.Kink);
  }
  return mixed + alone + kink;
}
