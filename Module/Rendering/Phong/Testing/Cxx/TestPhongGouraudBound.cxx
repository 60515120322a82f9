// vtkPhongGouraudBound against brute force: on tessellations (a sphere, a torus, a sphere whose
// normals were disturbed) and on CGAL's bunny00 and refined_elephant (the first argument is
// their directory; irregular triangles, normals computed by vtkOpenMeshNormals as the mapper
// computes them for files without), under random directional lights and views, the
// largest difference between per-vertex and per-fragment lighting of any triangle, found in
// double over a barycentric grid, must not exceed the bound. Also the lobe bound alone on
// random caps of normals around random halfway vectors, and both modes' bounds on single
// random triangles, degenerate ones among them (100 000 per lobe, Blinn and Phong, under
// directional lights, headlights and point lights, attenuated or not; --triangles N sets the
// count). Prints how tight the bounds are.
#include "vtkPhongGouraudBound.h"
#include "vtkPhongTestTorus.h"
#include "vtkPhongTestUtilities.h"

#include "vtkBoundingBox.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkOpenMeshNormals.h"
#include "vtkPhongOFFReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
using Vector = std::array<double, 3>;
using Scene = vtkPhongGouraudBound::Scene;

double Dot(const Vector& a, const Vector& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vector Unit(Vector a)
{
  const double length = std::sqrt(Dot(a, a));
  return { { a[0] / length, a[1] / length, a[2] / length } };
}

Vector RandomDirection(std::mt19937& random)
{
  std::normal_distribution<double> normal;
  return Unit({ { normal(random), normal(random), normal(random) } });
}

// The model's diffuse and specular light sums at one point p (N, V unit; directional and
// point lights): what per-vertex lighting evaluates at the vertices and per-fragment lighting
// at each fragment.
struct Sums
{
  double Diffuse = 0.0, Specular = 0.0;
};

Sums Shade(const Scene& scene, const Vector& n, const Vector& v, const Vector& p)
{
  Sums sums;
  for (const Scene::Light& light : scene.Lights)
  {
    const Vector toLight = { { light.PositionMC[0] - p[0], light.PositionMC[1] - p[1],
      light.PositionMC[2] - p[2] } };
    const Vector l = light.Positional ? Unit(toLight) : light.ToLightMC;
    const double d = std::sqrt(Dot(toLight, toLight));
    const auto& k = light.AttenuationMC.Coefficients;
    const double fade = light.Positional ? 1.0 / (k[0] + k[1] * d + k[2] * d * d) : 1.0;
    const double nl = Dot(n, l);
    sums.Diffuse += fade * light.Diffuse * std::max(nl, 0.0);
    double c;
    if (scene.Blinn)
    {
      const Vector h = { { l[0] + v[0], l[1] + v[1], l[2] + v[2] } };
      const double length = std::sqrt(Dot(h, h));
      c = length > 0.0 ? Dot(n, h) / length : 0.0;
    }
    else
    {
      const Vector r = { { 2.0 * nl * n[0] - l[0], 2.0 * nl * n[1] - l[1],
        2.0 * nl * n[2] - l[2] } };
      c = Dot(r, v);
    }
    const double lobe = std::pow(std::min(std::max(c, 0.0), 1.0), scene.Shininess);
    const double gate = scene.SmoothTerminator ? std::max(nl, 0.0) : (nl > 1.0e-4 ? 1.0 : 0.0);
    sums.Specular += fade * light.Specular * lobe * gate;
  }
  return sums;
}

Vector ToEye(const Scene& scene, const Vector& p)
{
  return scene.Parallel
    ? scene.ToEyeMC
    : Unit({ { scene.EyeMC[0] - p[0], scene.EyeMC[1] - p[1], scene.EyeMC[2] - p[2] } });
}

// The largest |per-vertex - per-fragment| over every triangle, side and grid point, with
// every sum per vertex and with the specular sums alone (the diffuse sum per fragment).
vtkPhongGouraudBound::Bounds BruteForce(vtkPolyData* mesh, const Scene& scene)
{
  constexpr int Steps = 8;
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  vtkNew<vtkIdList> ids;
  vtkPhongGouraudBound::Bounds largest = { 0.0, 0.0 };
  auto polys = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    polys->GetCurrentCell(ids);
    for (vtkIdType t = 1; t + 1 < ids->GetNumberOfIds(); ++t)
    {
      const vtkIdType corner[3] = { ids->GetId(0), ids->GetId(t), ids->GetId(t + 1) };
      Vector n[3], p[3];
      for (int i = 0; i < 3; ++i)
      {
        normals->GetTuple(corner[i], n[i].data());
        n[i] = Unit(n[i]);
        mesh->GetPoint(corner[i], p[i].data());
      }
      for (double side : { 1.0, -1.0 })
      {
        if (side < 0.0 && !scene.TwoSided)
        {
          continue;
        }
        Sums atVertex[3];
        Vector sided[3];
        for (int i = 0; i < 3; ++i)
        {
          sided[i] = { { side * n[i][0], side * n[i][1], side * n[i][2] } };
          atVertex[i] = Shade(scene, sided[i], ToEye(scene, p[i]), p[i]);
        }
        for (int i = 0; i <= Steps; ++i)
        {
          for (int j = 0; i + j <= Steps; ++j)
          {
            const double b[3] = { double(i) / Steps, double(j) / Steps,
              double(Steps - i - j) / Steps };
            Vector normal{}, position{};
            for (int k = 0; k < 3; ++k)
            {
              for (int c = 0; c < 3; ++c)
              {
                normal[c] += b[k] * sided[k][c];
                position[c] += b[k] * p[k][c];
              }
            }
            if (Dot(normal, normal) < 1.0e-20)
            {
              continue;
            }
            const Sums fragment = Shade(scene, Unit(normal), ToEye(scene, position), position);
            Sums vertex;
            for (int k = 0; k < 3; ++k)
            {
              vertex.Diffuse += b[k] * atVertex[k].Diffuse;
              vertex.Specular += b[k] * atVertex[k].Specular;
            }
            const double specular = vertex.Specular - fragment.Specular;
            largest.PerVertex =
              std::max(largest.PerVertex, std::abs(vertex.Diffuse - fragment.Diffuse + specular));
            largest.SpecularPerVertex = std::max(largest.SpecularPerVertex, std::abs(specular));
          }
        }
      }
    }
  }
  return largest;
}

vtkSmartPointer<vtkPolyData> MakeMesh(int kind, std::mt19937& random)
{
  vtkSmartPointer<vtkPolyData> mesh;
  if (kind == 1)
  {
    mesh = vtkPhongTest::MakeTorus(0.6, 0.25, 48, 24);
  }
  else
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(40);
    sphere->SetPhiResolution(40);
    sphere->Update();
    mesh = sphere->GetOutput();
  }
  if (kind == 2) // normals disturbed by up to about 0.1 rad: wide caps, uneven ones
  {
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->DeepCopy(mesh);
    vtkDataArray* normals = copy->GetPointData()->GetNormals();
    std::uniform_real_distribution<double> jitter(-0.06, 0.06);
    for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
    {
      double* n = normals->GetTuple3(i);
      normals->SetTuple3(i, n[0] + jitter(random), n[1] + jitter(random), n[2] + jitter(random));
    }
    mesh = copy;
  }
  return mesh;
}

// A directional light of a random direction, its diffuse and specular strengths drawn from
// `strength`.
Scene::Light RandomLight(std::mt19937& random, std::uniform_real_distribution<double>& strength)
{
  Scene::Light light;
  light.ToLightMC = RandomDirection(random);
  light.Diffuse = strength(random);
  light.Specular = strength(random);
  return light;
}

// In one case of two, each point light of `scene` attenuated, (c, l, q) drawn from `fades` (a
// generator of their own, so that the scenes' other draws stay those of before): c from 0.05
// to 2, l and q up to 2 / `size` and 2 / size^2, so that the attenuation changes across the
// triangles.
void Attenuate(Scene& scene, std::mt19937& fades, double size)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (Scene::Light& light : scene.Lights)
  {
    if (light.Positional && fades() % 2 == 0)
    {
      light.AttenuationMC.Coefficients = { { 0.05 + 1.95 * unit(fades), 2.0 * unit(fades) / size,
        2.0 * unit(fades) / (size * size) } };
    }
  }
}

// Scene `index` of the sequence; the eye at 2 to 8 times `scale` from `centre`.
Scene RandomScene(std::mt19937& random, int index, const double centre[3], double scale)
{
  const double shininess[] = { 1.0, 2.0, 10.0, 40.0, 200.0, 1.0e3 };
  std::uniform_real_distribution<double> uniform(0.2, 1.0);
  Scene scene;
  scene.Shininess = shininess[index % 6];
  scene.Blinn = (index / 6) % 2 == 0;
  scene.Parallel = (index / 12) % 2 == 0;
  scene.TwoSided = index % 5 != 0;
  scene.SmoothTerminator = index % 7 == 3;
  const int lights = 1 + index % 4;
  for (int i = 0; i < lights; ++i)
  {
    scene.Lights.push_back(RandomLight(random, uniform));
  }
  scene.ToEyeMC = RandomDirection(random);
  const double distance = 2.0 + 6.0 * uniform(random);
  for (int i = 0; i < 3; ++i)
  {
    scene.EyeMC[i] = centre[i] + scale * distance * scene.ToEyeMC[i];
  }
  if (index % 3 == 0) // a headlight: L = V, where the highlight faces the eye
  {
    scene.Lights[0].ToLightMC = scene.ToEyeMC;
  }
  if (index % 4 == 1) // a point light 1.2 to 4 times `scale` from `centre`
  {
    Scene::Light& point = scene.Lights.back();
    point.Positional = true;
    const Vector direction = RandomDirection(random);
    const double reach = scale * (1.2 + 2.8 * uniform(random));
    for (int i = 0; i < 3; ++i)
    {
      point.PositionMC[i] = centre[i] + reach * direction[i];
    }
  }
  return scene;
}

std::string MeshName(int kind, int index)
{
  const char* names[] = { "sphere", "torus", "disturbed sphere" };
  return std::string(names[kind]) + " scene " + std::to_string(index);
}

// A CGAL mesh (no normals in the file) with the point normals the mapper would compute.
vtkSmartPointer<vtkPolyData> ReadWithNormals(const std::string& path)
{
  vtkNew<vtkPhongOFFReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<vtkOpenMeshNormals> normals;
  normals->SetInputConnection(reader->GetOutputPort());
  normals->Update();
  vtkPolyData* output = normals->GetOutput();
  if (output->GetNumberOfPolys() == 0 || !output->GetPointData()->GetNormals())
  {
    std::cerr << "cannot read " << path << " with normals\n";
    return nullptr;
  }
  return output;
}

// One scene on one mesh: brute force against both bounds (counted when the per-vertex bound is
// finite).
bool CheckScene(vtkPolyData* mesh, vtkPhongGouraudBound& bound, const Scene& scene,
  const std::string& name, int& bounded, int& total, double& tightest)
{
  const vtkPhongGouraudBound::Bounds limit = bound.Bound(scene);
  ++total;
  if (!std::isfinite(limit.PerVertex))
  {
    return true;
  }
  ++bounded;
  bool ok = true;
  // Limited between the two modes, as the planner limits it, the bound stops no earlier than
  // the mode within the limit allows: that mode keeps its whole bound.
  const double middle = 0.5 * (limit.SpecularPerVertex + limit.PerVertex);
  const vtkPhongGouraudBound::Bounds limited = bound.Bound(scene, middle);
  if (limit.SpecularPerVertex < middle &&
    (limited.SpecularPerVertex != limit.SpecularPerVertex || !(limited.PerVertex > middle)))
  {
    std::cerr << "limited at " << middle << ": " << name << " specular per vertex "
              << limited.SpecularPerVertex << " against " << limit.SpecularPerVertex << "\n";
    ok = false;
  }
  const vtkPhongGouraudBound::Bounds actual = BruteForce(mesh, scene);
  for (int mode = 0; mode < 2; ++mode)
  {
    const double a = mode == 0 ? actual.PerVertex : actual.SpecularPerVertex;
    const double l = mode == 0 ? limit.PerVertex : limit.SpecularPerVertex;
    tightest = std::max(tightest, a / std::max(l, 1.0e-300));
    if (a > l * (1.0 + 1.0e-9) + 1.0e-12)
    {
      std::cerr << "bound broken (" << (mode == 0 ? "per vertex" : "specular per vertex")
                << "): " << name << " n " << scene.Shininess << (scene.Blinn ? " Blinn" : " Phong")
                << (scene.Parallel ? " parallel" : " perspective") << ": actual " << a
                << " > bound " << l << "\n";
      ok = false;
    }
  }
  return ok;
}

// The lobe bound alone: normals in a random cap of radius R around an axis at a random
// angle from a fixed H; G and F compared over a grid; every case within LobeBound.
bool CheckLobeBound(std::mt19937& random, double& tightest)
{
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double exponents[] = { 1.0, 8.0, 40.0, 128.0, 1.0e3, 1.0e4 };
  bool ok = true;
  for (int trial = 0; trial < 6000; ++trial)
  {
    const double n = exponents[trial % 6];
    const double spread = 0.002 + 0.2 * uniform(random) * uniform(random);
    const Vector h = { { 0.0, 0.0, 1.0 } };
    const double offset = (spread + 3.0 / std::sqrt(n)) * uniform(random);
    const Vector axis = { { std::sin(offset), 0.0, std::cos(offset) } };
    // Three normals in the cap: the axis turned by up to `spread` in random directions.
    Vector normals[3];
    for (auto& normal : normals)
    {
      const double turn = spread * std::sqrt(uniform(random));
      const double around = 6.283185307179586 * uniform(random);
      const Vector u = { { std::cos(offset), 0.0, -std::sin(offset) } }, w = { { 0.0, 1.0, 0.0 } };
      for (int c = 0; c < 3; ++c)
      {
        normal[c] = std::cos(turn) * axis[c] +
          std::sin(turn) * (std::cos(around) * u[c] + std::sin(around) * w[c]);
      }
    }
    auto lobe = [&](const Vector& m) { return std::pow(std::max(Dot(Unit(m), h), 0.0), n); };
    double largest = 0.0;
    for (int i = 0; i <= 12; ++i)
    {
      for (int j = 0; i + j <= 12; ++j)
      {
        const double b[3] = { i / 12.0, j / 12.0, (12 - i - j) / 12.0 };
        Vector m{};
        double vertex = 0.0;
        for (int k = 0; k < 3; ++k)
        {
          vertex += b[k] * lobe(normals[k]);
          for (int c = 0; c < 3; ++c)
          {
            m[c] += b[k] * normals[k][c];
          }
        }
        largest = std::max(largest, std::abs(vertex - lobe(m)));
      }
    }
    const double bound =
      vtkPhongGouraudBound::LobeBound(spread, std::max(offset - spread, 0.0), offset + spread, n);
    const double nearest = std::max(offset - spread, 0.0);
    const double largestLobe = nearest >= 1.5707963267948966 ? 0.0 : std::pow(std::cos(nearest), n);
    const double used = std::min(bound, largestLobe);
    if (largest > used * (1.0 + 1.0e-9) + 1.0e-15)
    {
      std::cerr << "lobe bound broken: n " << n << " spread " << spread << " offset " << offset
                << ": " << largest << " > " << used << "\n";
      ok = false;
    }
    if (used > 1.0e-6)
    {
      tightest = std::max(tightest, largest / used);
    }
  }
  return ok;
}

// A unit vector at angle `turn` from unit `axis`, around it by `around`.
Vector Turned(const Vector& axis, double turn, double around)
{
  const Vector helper =
    std::abs(axis[0]) < 0.9 ? Vector{ { 1.0, 0.0, 0.0 } } : Vector{ { 0.0, 1.0, 0.0 } };
  const Vector u = Unit({ { axis[1] * helper[2] - axis[2] * helper[1],
    axis[2] * helper[0] - axis[0] * helper[2], axis[0] * helper[1] - axis[1] * helper[0] } });
  const Vector w = { { axis[1] * u[2] - axis[2] * u[1], axis[2] * u[0] - axis[0] * u[2],
    axis[0] * u[1] - axis[1] * u[0] } };
  Vector turned;
  for (int c = 0; c < 3; ++c)
  {
    turned[c] = std::cos(turn) * axis[c] +
      std::sin(turn) * (std::cos(around) * u[c] + std::sin(around) * w[c]);
  }
  return Unit(turned);
}

// One random triangle, its shape by `kind`: 0-3 any, 4 its points on a line (no area), 5 two
// points at one place, 6 a sliver (one side 1e-4 of the others), 7 at most 1e-3 across. Its
// normals lie in a cap of random radius (from 1e-4 to 1.2 rad, 0 in one case of eight: all
// three alike) around a random axis, one of them sometimes at the cap's very edge, or in one
// case of four turn with the points.
void RandomTriangle(std::mt19937& random, int kind, vtkPoints* points, vtkDataArray* normals)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double size = std::pow(10.0, -2.0 * unit(random));
  Vector p[3];
  for (auto& point : p)
  {
    for (double& c : point)
    {
      c = size * (2.0 * unit(random) - 1.0);
    }
  }
  const double t = unit(random);
  for (int c = 0; c < 3; ++c)
  {
    p[2][c] = kind == 4 ? p[0][c] + t * (p[1][c] - p[0][c])
      : kind == 5       ? p[0][c]
      : kind == 6       ? p[1][c] + 1.0e-4 * (p[2][c] - p[1][c])
      : kind == 7       ? 1.0e-3 * p[2][c]
                        : p[2][c];
    p[1][c] = kind == 7 ? 1.0e-3 * p[1][c] : p[1][c];
    p[0][c] = kind == 7 ? 1.0e-3 * p[0][c] : p[0][c];
  }
  const Vector axis = RandomDirection(random);
  const double radius =
    random() % 8 == 0 ? 0.0 : std::pow(10.0, -4.0 + 4.08 * unit(random)); // up to 1.2 rad
  // In one case of four the normals turn with the points, as on a curved surface (convex or
  // concave): then, in perspective, the normal and the view vector turn together.
  const bool curved = random() % 4 == 0;
  const double curvature = (random() % 2 ? 1.0 : -1.0) * radius / size;
  for (int i = 0; i < 3; ++i)
  {
    const double turn = i == 0 && random() % 4 == 0 ? radius : radius * std::sqrt(unit(random));
    Vector n = Turned(axis, turn, 6.283185307179586 * unit(random));
    if (curved)
    {
      n = Unit({ { axis[0] + curvature * p[i][0], axis[1] + curvature * p[i][1],
        axis[2] + curvature * p[i][2] } });
    }
    points->SetPoint(i, p[i].data());
    normals->SetTuple(i, n.data());
  }
}

// A random scene for one triangle: 1 to 3 directional lights, one of them in one case of four
// the headlight (L = V) and in one of eight in the plane of the cap's axis (N.L = 0 at the
// terminator), and each in one case of three a point light 1.5 to 20 times the triangle's
// size from its centre; the eye as far, or at infinity.
Scene RandomTriangleScene(
  std::mt19937& random, bool blinn, const Vector& axis, const Vector& centre, double size)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double shininess[] = { 1.0, 2.0, 3.0, 10.0, 40.0, 200.0, 1.0e3, 1.0e4 };
  Scene scene;
  scene.Blinn = blinn;
  scene.Shininess = random() % 4 == 0 ? 1.0 + 999.0 * unit(random) : shininess[random() % 8];
  scene.Parallel = random() % 2 == 0;
  scene.TwoSided = random() % 4 != 0;
  scene.SmoothTerminator = random() % 8 == 0;
  // Towards the triangle's side mostly: a view from behind only lights the back faces.
  scene.ToEyeMC = Turned(axis, 1.5 * unit(random), 6.283185307179586 * unit(random));
  const double distance = (1.5 + 18.5 * unit(random)) * std::max(size, 1.0e-3);
  for (int c = 0; c < 3; ++c)
  {
    scene.EyeMC[c] = distance * scene.ToEyeMC[c];
  }
  const int lights = 1 + static_cast<int>(random() % 3);
  for (int i = 0; i < lights; ++i)
  {
    scene.Lights.push_back(RandomLight(random, unit));
  }
  if (random() % 4 == 0)
  {
    scene.Lights[0].ToLightMC = scene.ToEyeMC;
  }
  else if (random() % 8 == 0)
  {
    scene.Lights[0].ToLightMC = Turned(axis, 1.5707963267948966, 6.283185307179586 * unit(random));
  }
  for (Scene::Light& light : scene.Lights)
  {
    if (random() % 3 == 0)
    {
      light.Positional = true;
      const double reach = (1.5 + 18.5 * unit(random)) * std::max(size, 1.0e-3);
      for (int c = 0; c < 3; ++c)
      {
        light.PositionMC[c] = centre[c] + reach * light.ToLightMC[c];
      }
    }
  }
  return scene;
}

// What a failing random triangle was, to reproduce it.
void PrintTriangle(vtkPolyData* triangle, const Scene& scene)
{
  std::cerr.precision(17);
  for (vtkIdType i = 0; i < 3; ++i)
  {
    const double* p = triangle->GetPoint(i);
    const double* n = triangle->GetPointData()->GetNormals()->GetTuple3(i);
    std::cerr << "  point " << p[0] << " " << p[1] << " " << p[2] << " normal " << n[0] << " "
              << n[1] << " " << n[2] << "\n";
  }
  std::cerr << "  eye " << scene.EyeMC[0] << " " << scene.EyeMC[1] << " " << scene.EyeMC[2]
            << " to eye " << scene.ToEyeMC[0] << " " << scene.ToEyeMC[1] << " " << scene.ToEyeMC[2]
            << (scene.TwoSided ? " two-sided" : " one-sided")
            << (scene.SmoothTerminator ? " smooth terminator" : "") << "\n";
  for (const auto& light : scene.Lights)
  {
    std::cerr << "  light " << light.ToLightMC[0] << " " << light.ToLightMC[1] << " "
              << light.ToLightMC[2] << " diffuse " << light.Diffuse << " specular "
              << light.Specular;
    if (light.Positional)
    {
      std::cerr << " at " << light.PositionMC[0] << " " << light.PositionMC[1] << " "
                << light.PositionMC[2] << " attenuation " << light.AttenuationMC.Coefficients[0]
                << " " << light.AttenuationMC.Coefficients[1] << " "
                << light.AttenuationMC.Coefficients[2];
    }
    std::cerr << "\n";
  }
  std::cerr.precision(6);
}

// Both modes' bounds on `perLobe` single random triangles for each lobe (Blinn, Phong), each
// against brute force, point lights attenuated in one case of two (Attenuate); at least nine
// in ten must be bounded (finite).
bool CheckRandomTriangles(std::mt19937& random, int perLobe, double& tightest)
{
  std::mt19937 fades(20261129);
  vtkNew<vtkPolyData> triangle;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(3);
  vtkNew<vtkDoubleArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(3);
  vtkNew<vtkCellArray> polys;
  const vtkIdType ids[3] = { 0, 1, 2 };
  polys->InsertNextCell(3, ids);
  triangle->SetPoints(points);
  triangle->SetPolys(polys);
  triangle->GetPointData()->SetNormals(normals);
  bool ok = true;
  for (int lobe = 0; lobe < 2; ++lobe)
  {
    int bounded = 0, attenuatedScenes = 0;
    double tightestAttenuated = 0.0;
    for (int trial = 0; trial < perLobe; ++trial)
    {
      RandomTriangle(random, trial % 8, points, normals);
      double bounds[6];
      points->GetBounds(bounds);
      const double size = vtkBoundingBox(bounds).GetDiagonalLength();
      Vector axis;
      normals->GetTuple(0, axis.data());
      const Vector centre = { { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
        0.5 * (bounds[4] + bounds[5]) } };
      Scene scene = RandomTriangleScene(random, lobe == 0, axis, centre, size);
      Attenuate(scene, fades, std::max(size, 1.0e-3));
      vtkPhongGouraudBound bound;
      bound.Update({ triangle.GetPointer() }, 1);
      const vtkPhongGouraudBound::Bounds limit = bound.Bound(scene);
      if (!std::isfinite(limit.PerVertex))
      {
        continue;
      }
      ++bounded;
      const vtkPhongGouraudBound::Bounds actual = BruteForce(triangle, scene);
      const bool attenuated = std::any_of(scene.Lights.begin(), scene.Lights.end(),
        [](const Scene::Light& light) { return !light.AttenuationMC.IsNone(); });
      attenuatedScenes += attenuated ? 1 : 0;
      for (int mode = 0; mode < 2; ++mode)
      {
        const double a = mode == 0 ? actual.PerVertex : actual.SpecularPerVertex;
        const double l = mode == 0 ? limit.PerVertex : limit.SpecularPerVertex;
        tightest = l > 1.0e-9 ? std::max(tightest, a / l) : tightest;
        tightestAttenuated =
          attenuated && l > 1.0e-9 ? std::max(tightestAttenuated, a / l) : tightestAttenuated;
        if (a > l * (1.0 + 1.0e-9) + 1.0e-12)
        {
          std::cerr << "bound broken on random triangle " << trial << " (shape " << trial % 8
                    << ", " << (mode == 0 ? "per vertex" : "specular per vertex") << "): n "
                    << scene.Shininess << (scene.Blinn ? " Blinn" : " Phong")
                    << (scene.Parallel ? " parallel" : " perspective") << ": actual " << a
                    << " > bound " << l << "\n";
          PrintTriangle(triangle, scene);
          ok = false;
        }
      }
    }
    std::cout << (lobe == 0 ? "Blinn" : "Phong") << ": " << bounded << " of " << perLobe
              << " random triangles bounded, " << attenuatedScenes
              << " of them under an attenuated point light (largest actual/bound "
              << tightestAttenuated << ")\n";
    if (bounded < perLobe * 9 / 10)
    {
      std::cerr << "too few random triangles bounded\n";
      ok = false;
    }
  }
  return ok;
}

}

int TestPhongGouraudBound(int argc, char* argv[])
{
  std::mt19937 random(20261127);
  bool ok = true;
  double tightestLobe = 0.0;
  ok = CheckLobeBound(random, tightestLobe) && ok;
  std::cout << "lobe bound: 6000 caps, largest actual/bound " << tightestLobe << "\n";
  // Their own generator: the scenes below stay those of the earlier test.
  std::mt19937 triangles(20261128);
  double tightestTriangle = 0.0;
  ok = CheckRandomTriangles(triangles,
         vtkPhongTest::IntegerOption(argc, argv, "--triangles", 100000), tightestTriangle) &&
    ok;
  std::cout << "random triangles: largest actual/bound " << tightestTriangle << "\n";

  if (argc < 2)
  {
    std::cerr << "TestPhongGouraudBound needs CGAL's mesh directory as its first argument\n";
    return EXIT_FAILURE;
  }
  int bounded = 0, total = 0;
  double tightest = 0.0;
  const double origin[3] = { 0.0, 0.0, 0.0 };
  std::mt19937 fades(20261130);
  for (int kind = 0; kind < 3; ++kind)
  {
    auto mesh = MakeMesh(kind, random);
    vtkPhongGouraudBound bound;
    bound.Update({ mesh.GetPointer() }, 1);
    for (int index = 0; index < 24; ++index)
    {
      Scene scene = RandomScene(random, index, origin, 1.0);
      Attenuate(scene, fades, 1.0);
      ok = CheckScene(mesh, bound, scene, MeshName(kind, index), bounded, total, tightest) && ok;
    }
  }
  std::cout << "generated meshes: " << bounded << " of " << total
            << " scenes bounded, largest actual/bound " << tightest << "\n";
  for (const char* name : { "bunny00.off", "refined_elephant.off" })
  {
    auto mesh = ReadWithNormals(std::string(argv[1]) + "/" + name);
    if (!mesh)
    {
      return EXIT_FAILURE;
    }
    vtkPhongGouraudBound bound;
    bound.Update({ mesh.GetPointer() }, 1);
    double centre[3];
    const vtkBoundingBox box(mesh->GetBounds());
    box.GetCenter(centre);
    int meshBounded = 0, meshTotal = 0;
    double meshTightest = 0.0;
    // Blinn and Phong, parallel and perspective, n from 2 to 200, headlights among them.
    for (int index : { 1, 3, 8, 15, 19, 22 })
    {
      Scene scene = RandomScene(random, index, centre, 0.5 * box.GetDiagonalLength());
      Attenuate(scene, fades, 0.5 * box.GetDiagonalLength());
      ok = CheckScene(mesh, bound, scene, std::string(name) + " scene " + std::to_string(index),
             meshBounded, meshTotal, meshTightest) &&
        ok;
    }
    std::cout << name << ": " << meshBounded << " of " << meshTotal
              << " scenes bounded, largest actual/bound " << meshTightest << "\n";
    bounded += meshBounded;
    total += meshTotal;
  }
  if (bounded < total * 3 / 4)
  {
    std::cerr << "too few scenes bounded: " << bounded << " of " << total << "\n";
    ok = false;
  }
  // The last scene's bounds are remembered: asked again after another scene, the same.
  {
    auto mesh = MakeMesh(0, random);
    vtkPhongGouraudBound bound;
    bound.Update({ mesh.GetPointer() }, 1);
    const Scene first = RandomScene(random, 3, origin, 1.0); // directional: both modes finite
    const Scene second = RandomScene(random, 2, origin, 1.0);
    const auto a = bound.Bound(first);
    const auto b = bound.Bound(second);
    const auto c = bound.Bound(first);
    if (a.PerVertex != c.PerVertex || a.SpecularPerVertex != c.SpecularPerVertex ||
      a.PerVertex == b.PerVertex)
    {
      std::cerr << "remembered bounds: " << a.PerVertex << ", " << b.PerVertex << ", "
                << c.PerVertex << "\n";
      ok = false;
    }
    // Under a limit both modes pass, the bound may stop early but stays above the limit;
    // the limit is part of what is remembered.
    const double low = 0.5 * a.SpecularPerVertex;
    const auto cut = bound.Bound(first, low);
    const auto unlimited = bound.Bound(first);
    if (!(a.SpecularPerVertex > 0.0) || !(cut.SpecularPerVertex > low) || !(cut.PerVertex > low) ||
      unlimited.PerVertex != a.PerVertex)
    {
      std::cerr << "limited bounds: " << cut.SpecularPerVertex << ", " << cut.PerVertex
                << " against " << low << "; " << unlimited.PerVertex << " against " << a.PerVertex
                << "\n";
      ok = false;
    }
  }
  // A surface the bound cannot cover says so.
  vtkNew<vtkPolyData> empty;
  vtkPhongGouraudBound none;
  none.Update({ empty.GetPointer() }, 1);
  if (std::isfinite(none.Bound(Scene()).PerVertex) ||
    std::isfinite(none.Bound(Scene()).SpecularPerVertex))
  {
    std::cerr << "a surface without normals was bounded\n";
    ok = false;
  }
  return ok ? 0 : 1;
}
