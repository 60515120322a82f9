#include "vtkPhongGouraudBound.h"

#include "vtkBoundingBox.h"
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
// First-order terms (the view vector's spread over a triangle) take this margin; the brute
// force of TestPhongGouraudBound found at most 1.003 times the unmargined bound.
constexpr double FirstOrderMargin = 1.1;

double Dot(const Vector& a, const Vector& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double Norm(const Vector& a)
{
  return std::sqrt(Dot(a, a));
}

// The angle between unit vectors, accurate at 0 and pi (unlike acos of the dot product).
double Angle(const Vector& a, const Vector& b)
{
  const Vector difference = { { a[0] - b[0], a[1] - b[1], a[2] - b[2] } };
  const Vector sum = { { a[0] + b[0], a[1] + b[1], a[2] + b[2] } };
  return 2.0 * std::atan2(Norm(difference), Norm(sum));
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

bool Normalize(Vector& a)
{
  const double length = Norm(a);
  if (!(length > 1.0e-12) || !std::isfinite(length))
  {
    return false;
  }
  for (double& component : a)
  {
    component /= length;
  }
  return true;
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

// sup over alpha in [a, b] of cos(alpha)^p sin(alpha)^q, p real, q in {1, 2}: unimodal on
// [0, pi/2] with its peak where tan^2(alpha) = q / p (increasing when p <= 0).
double SupCosSin(double p, int q, double a, double b)
{
  double alpha = b;
  if (p > 0.0)
  {
    alpha = std::min(std::max(std::atan(std::sqrt(q / p)), a), b);
  }
  else if (b >= HalfPi - 1.0e-12 && p < 0.0)
  {
    return Infinite; // cos^p grows without bound at the lobe's edge
  }
  return std::pow(std::cos(alpha), p) * std::pow(std::sin(alpha), q);
}
}

//------------------------------------------------------------------------------
double vtkPhongGouraudBound::LobeBound(double spread, double nearAngle, double farAngle, double n)
{
  if (!(spread > 0.0) || n == 0.0)
  {
    return 0.0; // equal normals, or a lobe that is 1 wherever it is gated on
  }
  const double a = std::max(nearAngle, 0.0), b = std::min(farAngle, HalfPi);
  if (a >= HalfPi)
  {
    return 0.0; // the lobe is 0 over the whole cap
  }
  // Below n = 2 the clamp at c = 0 is no longer smooth enough for Waldron's identity: for
  // n = 1 it is a kink, which adds at most sin(R)/2; otherwise only the largest value bounds.
  const bool kink = n < 2.0 && farAngle >= HalfPi;
  if (spread >= 0.25 * Pi || (kink && n != 1.0))
  {
    return Infinite;
  }
  // d2/dalpha2 cos^n = n(n-1) cos^(n-2) sin^2 - n cos^n; s'(c) c = n cos^n;
  // s'(c) sin = n cos^(n-1) sin.
  const double curvature = n * std::abs(n - 1.0); // 0 for the diffuse term's n = 1
  const double hs = (curvature > 0.0 ? curvature * SupCosSin(n - 2.0, 2, a, b) : 0.0) +
    n * std::pow(std::cos(a), n);
  const double g1 = n * SupCosSin(n - 1.0, 1, a, b);
  const double tangent = std::tan(spread);
  const double radial = (1.0 - std::cos(spread) * std::cos(2.0 * spread)) / std::sin(spread);
  return 0.5 * tangent * tangent * (hs + 2.0 * g1 * radial) + (kink ? 0.5 * std::sin(spread) : 0.0);
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
  vtkBoundingBox box;
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
      this->AddPolygon(count, ids, points, normals, box);
    }
  }
  for (Cell& cell : this->Cells)
  {
    cell.Cone = ChordAngle(cell.Cone);
    cell.Spread = ChordAngle(cell.Spread);
    cell.Radius = std::sqrt(cell.Radius);
  }
  box.GetCenter(this->Sphere.data());
  this->Sphere[3] = box.IsValid() ? 0.5 * box.GetDiagonalLength() : 0.0;
  if (this->Unbounded)
  {
    this->Triangles = 0;
  }
}

//------------------------------------------------------------------------------
// One polygon as one cap: the cap of all its normals contains each triangle's that VTK cuts
// it into, and the ball around its points each triangle's ball. The cell keeps squares while
// binning (of the chords for its cone and spread, of the radius), Update their roots.
void vtkPhongGouraudBound::AddPolygon(vtkIdType count, const vtkIdType* ids, vtkPoints* points,
  vtkDataArray* normals, vtkBoundingBox& box)
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
    box.AddPoint(position[i].data());
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
  }
  ++cell.Count;
  ++this->Triangles;
}

//------------------------------------------------------------------------------
double vtkPhongGouraudBound::Bound(const Scene& scene) const
{
  if (this->Unbounded || this->Triangles == 0)
  {
    return Infinite;
  }
  View view;
  if (!this->MakeView(scene, view))
  {
    return Infinite;
  }
  std::vector<Halfway> halfways;
  for (const Scene::Light& light : scene.Lights)
  {
    halfways.push_back(MakeHalfway(scene, view, light.ToLightMC));
  }
  double largest = 0.0;
  for (const Cell& cell : this->Cells)
  {
    if (cell.Count == 0)
    {
      continue;
    }
    largest = std::max(largest, CellBound(cell, scene, view, halfways, 1.0));
    if (scene.TwoSided)
    {
      largest = std::max(largest, CellBound(cell, scene, view, halfways, -1.0));
    }
  }
  return largest;
}

//------------------------------------------------------------------------------
// Blinn's halfway vector between a light and the view cone's centre, and |L + V| at its least
// over the cone: the same for every cell, so made once per light.
vtkPhongGouraudBound::Halfway vtkPhongGouraudBound::MakeHalfway(
  const Scene& scene, const View& view, const Vector& toLight)
{
  Halfway halfway;
  if (!scene.Blinn)
  {
    return halfway;
  }
  halfway.Least = 2.0 * std::cos(0.5 * std::min(Angle(toLight, view.Centre) + view.Spread, Pi));
  halfway.Direction = { { toLight[0] + view.Centre[0], toLight[1] + view.Centre[1],
    toLight[2] + view.Centre[2] } };
  const bool opposite = !Normalize(halfway.Direction);
  halfway.LobeZero = scene.Parallel && opposite; // L = -V everywhere: the lobe is 0
  // H turns without bound as V does.
  halfway.Unbounded =
    !halfway.LobeZero && (opposite || (!scene.Parallel && !(halfway.Least > 1.0e-3)));
  return halfway;
}

//------------------------------------------------------------------------------
// The view vector over the surface: its direction towards the eye from the bounding sphere's
// centre, the half-angle of the cone holding it everywhere, and the eye's least distance.
bool vtkPhongGouraudBound::MakeView(const Scene& scene, View& view) const
{
  if (scene.Parallel)
  {
    view.Centre = scene.ToEyeMC;
    return Normalize(view.Centre);
  }
  for (int k = 0; k < 3; ++k)
  {
    view.Centre[k] = scene.EyeMC[k] - this->Sphere[k];
  }
  const double distance = Norm(view.Centre);
  const double radius = this->Sphere[3];
  if (!(distance > 1.01 * radius) || !Normalize(view.Centre))
  {
    return false; // the eye inside or at the surface's sphere: V takes every direction
  }
  view.Spread = std::asin(radius / distance);
  view.Nearest = distance - radius;
  return true;
}

//------------------------------------------------------------------------------
// Every triangle of the cell, on one side (1: as is; -1: reversed, two-sided back faces).
double vtkPhongGouraudBound::CellBound(const Cell& cell, const Scene& scene, const View& view,
  const std::vector<Halfway>& halfways, double side)
{
  const Vector d = { { side * cell.Axis[0], side * cell.Axis[1], side * cell.Axis[2] } };
  const double width = cell.Cone + cell.Spread; // normals' angles around d
  // The view vector's spread over one triangle (0 in parallel projection).
  const double localView = scene.Parallel ? 0.0
    : cell.Radius < view.Nearest          ? std::asin(cell.Radius / view.Nearest)
                                          : Infinite;
  double sum = 0.0;
  for (std::size_t i = 0; i < scene.Lights.size(); ++i)
  {
    const Scene::Light& light = scene.Lights[i];
    const double toLight = Angle(d, light.ToLightMC);
    const double nearLight = std::max(toLight - width, 0.0);
    const double farLight = std::min(toLight + width, Pi);
    if (nearLight >= HalfPi)
    {
      continue; // every normal faces away: no diffuse, the specular gate shut
    }
    sum += light.Diffuse * DiffuseBound(cell.Spread, nearLight, farLight);
    if (light.Specular > 0.0)
    {
      sum += light.Specular *
        SpecularBound(cell, scene, view, d, light.ToLightMC, halfways[i], localView, farLight);
    }
  }
  return sum >= 0.0 ? sum : Infinite; // NaN, from a degenerate input, bounds nothing
}

//------------------------------------------------------------------------------
// max(N.L, 0): the lobe bound with n = 1 (the terminator a kink), never more than the
// term's largest value.
double vtkPhongGouraudBound::DiffuseBound(double spread, double nearLight, double farLight)
{
  return std::min(LobeBound(spread, nearLight, farLight, 1.0), std::cos(nearLight));
}

//------------------------------------------------------------------------------
double vtkPhongGouraudBound::SpecularBound(const Cell& cell, const Scene& scene, const View& view,
  const Vector& d, const Vector& toLight, const Halfway& halfway, double localView, double farLight)
{
  // The lobe's axis against the cell's normals: Blinn's H against N, or Phong's reflected
  // vector (which turns twice as far as N) against V.
  double centre, width, spread, scale = 1.0;
  const double n = scene.Shininess;
  if (scene.Blinn)
  {
    if (halfway.LobeZero || halfway.Unbounded)
    {
      return halfway.LobeZero ? 0.0 : Infinite;
    }
    centre = Angle(d, halfway.Direction);
    width = cell.Cone + cell.Spread + view.Spread / halfway.Least;
    spread = cell.Spread + localView / halfway.Least;
  }
  else
  {
    const double c = Dot(d, toLight);
    const Vector r = { { 2.0 * c * d[0] - toLight[0], 2.0 * c * d[1] - toLight[1],
      2.0 * c * d[2] - toLight[2] } };
    centre = Angle(r, view.Centre);
    width = 2.0 * (cell.Cone + cell.Spread) + view.Spread;
    spread = 2.0 * cell.Spread + localView;
  }
  if (!scene.Parallel)
  {
    scale = FirstOrderMargin;
  }
  const double nearLobe = std::max(centre - width, 0.0);
  const double largest = nearLobe >= HalfPi ? 0.0 : std::pow(std::cos(nearLobe), n);
  // The gate (N.L > 1e-4) or the smooth terminator crossing the cell: only the largest value.
  if (scene.SmoothTerminator || farLight >= HalfPi - 1.0e-3)
  {
    return largest;
  }
  return std::min(largest, scale * LobeBound(spread, nearLobe, centre + width, n));
}
