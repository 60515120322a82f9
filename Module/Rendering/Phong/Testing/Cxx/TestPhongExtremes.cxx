// The numerical-stability suite: every extreme of the lighting contract, and every lobe with
// every light kind, rendered into a float target (vtkPhongFloatRenderPass) and compared with
// the double-precision reference (vtkPhongReference):
//
// - planes are compared with the ray-cast analytic plane: the geometry is exact, so the
//   difference is the whole GPU pipeline's float error (interpolation and shading);
// - curved surfaces are compared through the G-buffer (the same positions and normals shaded
//   in double), which isolates the shading arithmetic, and, for information, with the
//   analytic surface (tessellation error included).
//
// Every case must render no NaN or Inf, add no isolated pixels ("speckles") the reference
// does not have, and stay within its tolerance: the largest and the 99th-percentile relative
// error, |gpu - reference| / max(|reference|, 1e-4 * the reference's largest value). The test
// prints the table docs/results/extremes.md quotes (./vtkphong.sh extremes, or
// ctest -R TestPhongExtremes -V).

#include "vtkPhongReferenceTesting.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
#include "vtkPhongImageIO.h"
#include "vtkPlaneSource.h"

#include <cstdio>
#include <functional>
#include <limits>

namespace
{
constexpr int ImageSize = 160;

enum class Against
{
  AnalyticPlane,
  AnalyticSphere,
  AnalyticTorus,
  GBuffer
};

const char* AgainstName(Against kind)
{
  switch (kind)
  {
    case Against::AnalyticPlane:
      return "analytic plane";
    case Against::AnalyticSphere:
      return "analytic sphere";
    case Against::AnalyticTorus:
      return "analytic torus";
    default:
      return "G-buffer";
  }
}

// One scene of the suite: a surface, its material, lights and camera, everything placed
// relative to Center and scaled by Scale, so the same picture can be made far from the
// origin or very small.
struct Bench
{
  vtkPhongTest::Scene View{ ImageSize, ImageSize };
  vtkNew<vtkPhongProperty> Material;
  vtkActor* Actor = nullptr;
  vtkNew<vtkPhongReference> Reference;
  vtkNew<vtkPhongFloatRenderPass> Pass;
  Against Kind = Against::AnalyticPlane;
  double Center[3] = { 0.0, 0.0, 0.0 };
  double Scale = 1.0;
  vtkSmartPointer<vtkPolyData> Mesh;

  Bench()
  {
    this->View.Renderer->AutomaticLightCreationOff();
    this->View.Renderer->SetAmbient(0.3, 0.3, 0.3);
    this->Material->SetColor(0.8, 0.6, 0.4);
    this->Material->SetAmbient(0.1);
    this->Material->SetDiffuse(0.7);
    this->Material->SetSpecular(0.5);
    this->Material->SetShininess(40.0);
    this->Material->SetInterpolationToPhong();
  }

  // A scene point: Center + Scale * local.
  void Place(const double local[3], double world[3]) const
  {
    for (int i = 0; i < 3; ++i)
    {
      world[i] = this->Center[i] + this->Scale * local[i];
    }
  }

  void AddMesh(vtkPolyData* mesh)
  {
    this->Mesh = mesh;
    this->Actor = vtkPhongTest::AddActor(this->View, mesh, this->Material);
    // Relative precision of the equation itself, down to lights of intensity 1e-6: light
    // culling (an absolute bound, TestPhongLightCulling) would drop those.
    vtkPhongPolyDataMapper::SafeDownCast(this->Actor->GetMapper())->SetLightCullingBound(0.0);
    this->Reference->SetRenderer(this->View.Renderer);
    this->Reference->SetActor(this->Actor);
  }

  // The square of half-size 1 in the local z = 0 plane, facing +z, with double-precision
  // points (float points far from the origin would move the surface itself).
  void Plane(int resolution = 16)
  {
    const double corners[3][3] = { { -1, -1, 0 }, { 1, -1, 0 }, { -1, 1, 0 } };
    double origin[3], point1[3], point2[3];
    this->Place(corners[0], origin);
    this->Place(corners[1], point1);
    this->Place(corners[2], point2);
    vtkNew<vtkPlaneSource> plane;
    plane->SetOrigin(origin);
    plane->SetPoint1(point1);
    plane->SetPoint2(point2);
    plane->SetResolution(resolution, resolution);
    plane->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    plane->Update();
    this->AddMesh(plane->GetOutput());
    this->Reference->SetSurfaceToPlane(origin, point1, point2);
    this->Kind = Against::AnalyticPlane;
  }

  void Sphere(int resolution, Against kind)
  {
    auto sphere = vtkPhongTest::MakeSphere(resolution, 0.8);
    this->AddMesh(sphere);
    this->Reference->SetSurfaceToSphere(0.0, 0.0, 0.0, 0.8);
    this->Kind = kind;
  }

  void Torus(int resolution)
  {
    vtkNew<vtkParametricTorus> torus;
    torus->SetRingRadius(0.6);
    torus->SetCrossSectionRadius(0.25);
    vtkNew<vtkParametricFunctionSource> source;
    source->SetParametricFunction(torus);
    source->SetUResolution(2 * resolution);
    source->SetVResolution(resolution);
    source->Update();
    this->AddMesh(source->GetOutput());
    this->Reference->SetSurfaceToTorus(0.0, 0.0, 0.0, 0.6, 0.25);
    this->Kind = Against::AnalyticTorus;
  }

  void LookFrom(double x, double y, double z)
  {
    const double eye[3] = { x, y, z };
    double position[3];
    this->Place(eye, position);
    vtkCamera* camera = this->View.Renderer->GetActiveCamera();
    camera->SetFocalPoint(this->Center);
    camera->SetPosition(position);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(30.0);
  }

  vtkLight* AddLight(const double local[3], const double localTarget[3], bool positional)
  {
    double position[3], focalPoint[3];
    this->Place(local, position);
    this->Place(localTarget, focalPoint);
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPosition(position);
    light->SetFocalPoint(focalPoint);
    light->SetPositional(positional);
    light->SetConeAngle(180.0);
    this->View.Renderer->AddLight(light);
    return light;
  }

  vtkLight* Directional(double x, double y, double z)
  {
    const double from[3] = { x, y, z };
    const double to[3] = { 0.0, 0.0, 0.0 };
    return this->AddLight(from, to, false);
  }

  // A point light with (c, l, q) attenuation given for Scale 1; distances shrink with the
  // scene, so l and q grow to keep the same picture.
  vtkLight* Point(double x, double y, double z, double c = 1.0, double l = 0.3, double q = 0.1)
  {
    const double at[3] = { x, y, z };
    vtkLight* light = this->AddLight(at, at, true);
    light->SetAttenuationValues(c, l / this->Scale, q / (this->Scale * this->Scale));
    return light;
  }

  vtkLight* Spot(const double from[3], const double to[3], double cone, double exponent)
  {
    vtkLight* light = this->AddLight(from, to, true);
    light->SetConeAngle(cone);
    light->SetExponent(exponent);
    light->SetAttenuationValues(1.0, 0.0, 0.0);
    return light;
  }

  vtkLight* Headlight()
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToHeadlight();
    this->View.Renderer->AddLight(light);
    return light;
  }

  // A directional camera light from the upper right of the view.
  vtkLight* CameraLight()
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToCameraLight();
    light->SetPosition(0.6, 0.5, 1.0);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    this->View.Renderer->AddLight(light);
    return light;
  }

  // The five light kinds of the lobe matrix, in a standard placement.
  vtkLight* LightOfKind(int kind)
  {
    const double spotFrom[3] = { -0.4, 0.3, 1.2 };
    const double spotTo[3] = { 0.1, -0.1, 0.0 };
    switch (kind)
    {
      case 0:
        return this->Headlight();
      case 1:
        return this->CameraLight();
      case 2:
        return this->Directional(1.0, 1.0, 2.0);
      case 3:
        return this->Point(0.3, 0.2, 0.8);
      default:
        return this->Spot(spotFrom, spotTo, 30.0, 5.0);
    }
  }
};

const char* const LightKindNames[] = { "headlight", "camera light", "directional", "point",
  "spot" };
const char* const LobeNames[] = { "Phong", "Blinn-Phong", "normalized Phong",
  "normalized Blinn-Phong" };

// Pixels brighter or darker than all eight neighbours by more than a tenth of the picture's
// range: isolated values a smooth picture does not have.
vtkIdType CountSpeckles(vtkImageData* image, double largest)
{
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const int components = scalars->GetNumberOfComponents();
  const double jump = 0.1 * largest;
  auto value = [&](int x, int y, int c) { return scalars->GetComponent(y * dims[0] + x, c); };
  auto covered = [&](int x, int y) { return components < 4 || value(x, y, 3) > 0.0; };
  vtkIdType speckles = 0;
  for (int y = 1; y + 1 < dims[1]; ++y)
  {
    for (int x = 1; x + 1 < dims[0]; ++x)
    {
      bool interior = true;
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dx = -1; dx <= 1; ++dx)
        {
          interior = interior && covered(x + dx, y + dy);
        }
      }
      if (!interior)
      {
        continue;
      }
      for (int c = 0; c < 3; ++c)
      {
        const double centre = value(x, y, c);
        double low = std::numeric_limits<double>::max();
        double high = -low;
        for (int dy = -1; dy <= 1; ++dy)
        {
          for (int dx = -1; dx <= 1; ++dx)
          {
            if (dx != 0 || dy != 0)
            {
              low = std::min(low, value(x + dx, y + dy, c));
              high = std::max(high, value(x + dx, y + dy, c));
            }
          }
        }
        if (centre > high + jump || centre < low - jump)
        {
          ++speckles;
          break;
        }
      }
    }
  }
  return speckles;
}

struct Case
{
  std::string Name;
  double MaxTolerance; // largest relative error allowed
  double P99Tolerance; // 99th-percentile relative error allowed
  std::function<void(Bench&)> Build;
};

std::string Scientific(double value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.1e", value);
  return text;
}
}

int TestPhongExtremes(int argc, char* argv[])
{
  vtkNew<vtkTesting> testing;
  testing->AddArguments(argc, argv);
  const std::string temporary = testing->GetTempDirectory();

  std::vector<Case> cases;
  // Every lobe with every light kind, at moderate values.
  for (int lobe = 0; lobe < 4; ++lobe)
  {
    for (int kind = 0; kind < 5; ++kind)
    {
      cases.push_back({ std::string(LobeNames[lobe]) + ", " + LightKindNames[kind], 1e-4, 5e-5,
        [lobe, kind](Bench& bench)
        {
          bench.Plane();
          bench.Material->SetLightingModel(lobe);
          bench.LightOfKind(kind);
          bench.LookFrom(0.25, -0.35, 4.5);
        } });
    }
  }

  // The extremes of docs/lighting-model.md.
  cases.push_back({ "n = 0, Phong, R.V <= 0 on part (pow(0, 0))", 1e-6, 1e-6,
    [](Bench& bench)
    {
      bench.Plane();
      bench.Material->SetShininess(0.0);
      bench.Directional(1.0, 0.0, 0.05);
      bench.LookFrom(0.25, -0.35, 4.5);
    } });
  cases.push_back({ "n = 0, Blinn-Phong", 1e-6, 1e-6,
    [](Bench& bench)
    {
      bench.Plane();
      bench.Material->SetShininess(0.0);
      bench.Material->SetLightingModelToBlinnPhong();
      bench.Directional(1.0, 0.0, 0.05);
      bench.LookFrom(0.25, -0.35, 4.5);
    } });
  cases.push_back({ "n = 1e-6, Phong (a step at R.V = 0)", 1e-6, 1e-6,
    [](Bench& bench)
    {
      bench.Plane();
      bench.Material->SetShininess(1.0e-6);
      bench.Directional(1.0, 0.0, 0.05);
      bench.LookFrom(0.25, -0.35, 4.5);
    } });
  // Narrow lobes, within half a level (2e-3) of the double reference: from the difference
  // vector (R - V, N - H), and from interpolated dot products (directional lights) up to
  // n = 1e3: at 1e4 their rounding made 2.0e-3. Before the difference vector the n = 1e6
  // Phong highlight was 19 % off.
  for (const char* exponent : { "1e3", "1e4", "1e5" })
  {
    const double shininess = std::stod(exponent);
    cases.push_back({ std::string("n = ") + exponent + ", Phong, directional", 2e-3, 5e-4,
      [shininess](Bench& bench)
      {
        bench.Plane();
        bench.Material->SetShininess(shininess);
        bench.Directional(0.05, -0.08, 1.0);
        bench.LookFrom(0.25, -0.35, 4.5);
      } });
  }
  cases.push_back({ "n = 1e6, Phong, headlight", 1e-4, 1e-6,
    [](Bench& bench)
    {
      bench.Plane();
      bench.Material->SetShininess(1.0e6);
      bench.Headlight();
      bench.LookFrom(0.25, -0.35, 4.5);
    } });
  cases.push_back({ "n = 1e6, Blinn-Phong, headlight", 1e-4, 1e-6,
    [](Bench& bench)
    {
      bench.Plane();
      bench.Material->SetShininess(1.0e6);
      bench.Material->SetLightingModelToBlinnPhong();
      bench.Headlight();
      bench.LookFrom(0.25, -0.35, 4.5);
    } });
  for (int lobe : { vtkPhongProperty::BlinnPhong, vtkPhongProperty::Phong })
  {
    cases.push_back(
      { std::string("L = -V exactly, ") + LobeNames[lobe] + ", back face, one-sided", 1e-6, 1e-6,
        [lobe](Bench& bench)
        {
          bench.Plane();
          bench.Material->SetLightingModel(lobe);
          bench.Actor->RotateY(180.0); // the back face looks at the camera
          bench.View.Renderer->TwoSidedLightingOff();
          bench.Directional(0.0, 0.0, -1.0);
          bench.LookFrom(0.0, 0.0, 4.5);
          bench.View.Renderer->GetActiveCamera()->ParallelProjectionOn();
          bench.View.Renderer->GetActiveCamera()->SetParallelScale(1.2);
        } });
  }
  // The fallback to the face's own normal at every scale: VTK 9.4 scales its derivative
  // normal so that 1e12 and 1e-12 coordinates neither overflow nor underflow in float.
  for (const double scale : { 1.0, 1.0e12, 1.0e-12 })
  {
    const std::string name = scale == 1.0 ? std::string("zero-length and NaN normals")
                                          : "zero-length and NaN normals, geometry scaled by " +
        std::string(scale > 1.0 ? "1e12" : "1e-12");
    cases.push_back({ name, scale == 1.0 ? 3e-4 : 5e-4, 1e-4,
      [scale](Bench& bench)
      {
        bench.Scale = scale;
        bench.Plane();
        vtkNew<vtkFloatArray> normals;
        normals->SetName("Normals");
        normals->SetNumberOfComponents(3);
        const vtkIdType count = bench.Mesh->GetNumberOfPoints();
        normals->SetNumberOfTuples(count);
        const float nan = std::numeric_limits<float>::quiet_NaN();
        for (vtkIdType i = 0; i < count; ++i)
        {
          const float zero[3] = { 0.f, 0.f, 0.f }, bad[3] = { nan, nan, nan },
                      up[3] = { 0.f, 0.f, 1.f };
          normals->SetTypedTuple(i, i % 5 == 0 ? bad : (i % 3 == 0 ? zero : up));
        }
        bench.Mesh->GetPointData()->SetNormals(normals);
        bench.Point(0.3, 0.2, 0.8);
        bench.Directional(1.0, 1.0, 2.0);
        bench.LookFrom(0.25, -0.35, 4.5);
      } });
  }
  cases.push_back({ "light 1e-6 above the surface, A = 1/d^2", 1.0, 1e-2,
    [](Bench& bench)
    {
      bench.Plane();
      bench.Point(0.123, -0.077, 1.0e-6, 0.0, 0.0, 1.0);
      bench.LookFrom(0.25, -0.35, 4.5);
    } });
  cases.push_back({ "light in the surface's plane, A = 1/d^2 (d = 0 possible)", 1e-2, 1e-4,
    [](Bench& bench)
    {
      bench.Plane();
      vtkLight* light = bench.Point(0.3, -0.2, 0.0, 0.0, 0.0, 1.0);
      light->SetAmbientColor(0.2, 0.2, 0.2);
      bench.LookFrom(0.25, -0.35, 4.5);
    } });
  cases.push_back({ "light in the surface's plane, n = 0 (gate at N.L = 0)", 1e-2, 1e-4,
    [](Bench& bench)
    {
      bench.Plane();
      bench.Material->SetShininess(0.0);
      bench.Point(0.3, -0.2, 0.0, 1.0, 0.0, 0.0);
      bench.LookFrom(0.25, -0.35, 4.5);
    } });
  cases.push_back({ "directional light along the surface, n = 0", 2e-6, 1e-6,
    [](Bench& bench)
    {
      bench.Plane();
      bench.Material->SetShininess(0.0);
      bench.Directional(1.0, 0.3, 0.0);
      bench.LookFrom(0.25, -0.35, 4.5);
    } });
  cases.push_back({ "attenuation (0, 0, 0): denominator 0", 5e-5, 2e-5,
    [](Bench& bench)
    {
      bench.Plane();
      bench.Point(0.2, 0.1, 1.0, 0.0, 0.0, 0.0);
      bench.LookFrom(0.25, -0.35, 4.5);
    } });
  cases.push_back({ "grazing light, N.L = 1e-3", 2e-6, 1e-6,
    [](Bench& bench)
    {
      bench.Plane();
      bench.Directional(1.0, 0.0, 1.0e-3);
      bench.LookFrom(0.25, -0.35, 4.5);
    } });
  cases.push_back({ "grazing view, 3 degrees", 5e-6, 5e-6,
    [](Bench& bench)
    {
      bench.Plane();
      bench.Point(0.3, 0.2, 0.8);
      bench.Directional(1.0, 1.0, 2.0);
      bench.LookFrom(0.0, -4.5, 4.5 * std::tan(vtkMath::RadiansFromDegrees(3.0)));
    } });
  for (double intensity : { 1.0e-6, 1.0e6 })
  {
    cases.push_back({ "light intensity " + Scientific(intensity) + ", no ambient", 5e-5, 1e-5,
      [intensity](Bench& bench)
      {
        bench.Plane();
        bench.View.Renderer->SetAmbient(0.0, 0.0, 0.0);
        bench.Point(0.3, 0.2, 0.8)->SetIntensity(intensity);
        bench.Directional(1.0, 1.0, 2.0)->SetIntensity(intensity);
        bench.LookFrom(0.25, -0.35, 4.5);
      } });
  }
  const double spotFrom[3] = { -0.4, 0.3, 1.2 };
  const double spotTo[3] = { 0.1, -0.1, 0.0 };
  cases.push_back({ "geometry offset by 1e7", 5e-5, 1e-5,
    [&](Bench& bench)
    {
      bench.Center[0] = 1.0e7;
      bench.Center[1] = -1.0e7;
      bench.Center[2] = 1.0e7;
      bench.Plane();
      bench.Point(0.3, 0.2, 0.8);
      bench.Spot(spotFrom, spotTo, 30.0, 5.0);
      bench.Directional(1.0, 1.0, 2.0);
      bench.LookFrom(0.25, -0.35, 4.5);
    } });
  cases.push_back({ "geometry scaled by 1e-7", 5e-5, 1e-5,
    [&](Bench& bench)
    {
      bench.Scale = 1.0e-7;
      bench.Plane();
      bench.Point(0.3, 0.2, 0.8);
      bench.Spot(spotFrom, spotTo, 30.0, 5.0);
      bench.Directional(1.0, 1.0, 2.0);
      bench.LookFrom(0.25, -0.35, 4.5);
    } });

  // Curved surfaces: the shading arithmetic alone (G-buffer), then, for information, the
  // full picture against the exact surface (tessellation and normal interpolation).
  auto threeLights = [&](Bench& bench)
  {
    bench.Material->SetLightingModelToBlinnPhong();
    bench.Material->SetShininess(60.0);
    bench.Directional(1.0, 1.0, 2.0);
    bench.Point(-1.0, 0.5, 1.5);
    bench.Spot(spotFrom, spotTo, 30.0, 5.0);
    bench.LookFrom(0.25, -0.35, 4.5);
  };
  cases.push_back({ "sphere, three lights, shading arithmetic", 5e-5, 1e-5,
    [&](Bench& bench)
    {
      bench.Sphere(128, Against::GBuffer);
      threeLights(bench);
    } });
  cases.push_back({ "sphere 128x128 vs exact sphere (tessellation)", 0.1, 2e-2,
    [&](Bench& bench)
    {
      bench.Sphere(128, Against::AnalyticSphere);
      threeLights(bench);
    } });
  cases.push_back({ "torus 256x128 vs exact torus (tessellation)", 0.1, 2e-2,
    [&](Bench& bench)
    {
      bench.Torus(128);
      threeLights(bench);
    } });

  bool passed = true;
  std::cout << "| case | reference | pixels | max rel. error | p99 rel. error | max abs. error "
               "| NaN/Inf | speckles (GPU/ref.) | tolerance (max / p99) | |\n"
            << "|---|---|---|---|---|---|---|---|---|---|\n";
  int index = 0;
  for (const Case& testCase : cases)
  {
    ++index;
    Bench bench;
    testCase.Build(bench);
    bench.View.Renderer->ResetCameraClippingRange();
    auto gpu = vtkPhongTest::RenderFloat(bench.View, bench.Pass);
    vtkSmartPointer<vtkImageData> reference;
    int erosion = 1; // tessellated and exact silhouettes differ by a pixel
    if (bench.Kind == Against::GBuffer)
    {
      reference = vtkPhongTest::ShadeGBuffer(bench.View, bench.Pass, bench.Reference);
      erosion = 0; // the same pixels on both sides
    }
    else
    {
      reference = vtkSmartPointer<vtkImageData>::New();
      if (!bench.Reference->RenderAnalytic(reference))
      {
        reference = nullptr;
      }
    }
    const std::string stem = temporary + "/TestPhongExtremes-" + std::to_string(index);
    const auto measured = vtkPhongTest::MeasureAgainst(gpu, reference, erosion);
    const vtkIdType gpuSpeckles = CountSpeckles(gpu, measured.Largest);
    const vtkIdType referenceSpeckles = reference ? CountSpeckles(reference, measured.Largest) : 0;
    const bool glClean = vtkPhongTest::NoGLErrors(bench.View.Window, testCase.Name.c_str());
    const bool ok = measured.Valid && measured.NaNPixels == 0 && measured.InfPixels == 0 &&
      measured.MaxRelative <= testCase.MaxTolerance &&
      measured.P99Relative <= testCase.P99Tolerance && gpuSpeckles <= referenceSpeckles && glClean;
    if (!ok)
    {
      // The error map: mid grey where a pixel's error reaches the tolerance, white at twice.
      if (measured.Comparison)
      {
        measured.Comparison->SetThreshold(testCase.MaxTolerance * measured.Largest);
        measured.Comparison->WriteErrorMap((stem + ".error.png").c_str());
      }
      vtkNew<vtkPhongImageIO> io;
      io->WriteImage(gpu, (stem + ".gpu.exr").c_str());
      if (reference)
      {
        io->WriteImage(reference, (stem + ".reference.exr").c_str());
      }
    }
    passed = passed && ok;
    std::cout << "| " << testCase.Name << " | " << AgainstName(bench.Kind) << " | "
              << measured.ComparedPixels << " | " << Scientific(measured.MaxRelative) << " | "
              << Scientific(measured.P99Relative) << " | " << Scientific(measured.MaxAbsolute)
              << " | " << measured.NaNPixels + measured.InfPixels << " | " << gpuSpeckles << "/"
              << referenceSpeckles << " | " << Scientific(testCase.MaxTolerance) << " / "
              << Scientific(testCase.P99Tolerance) << " | " << (ok ? "ok" : "FAILED") << " |\n";
  }
  std::cout.flush();
  return passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
