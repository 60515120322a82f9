// Light culling keeps its bound. Four spheres, each with 16 of the scene's 64 point lights
// (inverse-square attenuation) close in front of it: each sphere is reached by a few lights
// only. Rendered into float targets with the default
// culling bound (0.5 / 255) and with culling off (0), the two pictures differ by at most the
// bound in every channel of every pixel; each mapper evaluates only a few of the 64 lights.
// A spot aimed away from every sphere is culled by its cone.
// Culling with a bound of 1 drops some of each sphere's own lights: it differs by more
// than 0.5 / 255 (so the comparison would see a broken bound), but within 1. A frame rendered
// again, or with a far light moved a little, compiles nothing; a zero bound culls nothing.
// vtkPhongLightCulling::ContributionBound, on which culling rests, is also checked alone on
// 100 000 random boxes per light kind (point, attenuated point, spot, spot with falloff and
// attenuation), degenerate ones among them: at 30 points of each box, the light's largest
// contribution there, evaluated in double as the shader does, never exceeds the bound.

#include "vtkPhongReferenceTesting.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkPhongLightCulling.h"
#include "vtkPhongLightGeometry.h"
#include "vtkPhongTestActors.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
constexpr double DefaultBound = 0.5 / 255.0;

// The largest difference of the RGB channels of two float pictures.
double LargestDifference(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* ra = a->GetPointData()->GetScalars();
  vtkDataArray* rb = b->GetPointData()->GetScalars();
  double largest = 0.0;
  for (vtkIdType p = 0; p < ra->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      largest = std::max(largest, std::abs(ra->GetComponent(p, c) - rb->GetComponent(p, c)));
    }
  }
  return largest;
}

// A random box in view coordinates for ContributionBound: one in eight flat, one in sixteen a
// point.
void RandomBox(std::mt19937& random, double box[6])
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int shape = static_cast<int>(random() % 16);
  for (int i = 0; i < 3; ++i)
  {
    const double centre = 10.0 * unit(random) - 5.0;
    const double half =
      shape == 0 || (shape < 3 && i == 0) ? 0.0 : std::pow(10.0, -3.0 + 3.5 * unit(random));
    box[2 * i] = centre - half;
    box[2 * i + 1] = centre + half;
  }
}

// A point of the box: a corner (k < 8), else a random one.
void PointOfBox(std::mt19937& random, const double box[6], int k, double p[3])
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 3; ++i)
  {
    const double t = k < 8 ? ((k >> i) & 1) : unit(random);
    // Clamped: box[0] + 1 * (box[1] - box[0]) may round past box[1].
    p[i] = std::min(box[2 * i] + t * (box[2 * i + 1] - box[2 * i]), box[2 * i + 1]);
  }
}

// The light's largest contribution at p, per channel, as the shader evaluates it (in double)
// with the normal and view that make N.L, the lobe and the gate 1 (N = L = V): A(d) spot
// sum over terms of weight * colour * intensity.
double ContributionAt(vtkLight* light, bool isSpot, const double position[3], const double axis[3],
  const double p[3], const double weights[3][3])
{
  double toPoint[3] = { p[0] - position[0], p[1] - position[1], p[2] - position[2] };
  const double d = vtkMath::Norm(toPoint);
  double spot = 1.0;
  if (isSpot && d > 0.0) // at d = 0 the shader takes L = N, and N = -axis gives cos_phi = 1
  {
    const double cosPhi = vtkMath::Dot(toPoint, axis) / d;
    const double cosCutoff = std::cos(vtkMath::RadiansFromDegrees(light->GetConeAngle()));
    spot = cosPhi >= cosCutoff ? std::pow(std::max(cosPhi, 0.0), light->GetExponent()) : 0.0;
  }
  const double* k = light->GetAttenuationValues();
  const double attenuation = 1.0 / std::max(k[0] + d * (k[1] + d * k[2]), 1.0e-20);
  const double* colors[3] = { light->GetAmbientColor(), light->GetDiffuseColor(),
    light->GetSpecularColor() };
  double largest = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    double channel = 0.0;
    for (int term = 0; term < 3; ++term)
    {
      channel += weights[term][c] *
        vtkPhongLightGeometry::UploadedColor(colors[term][c], light->GetIntensity());
    }
    largest = std::max(largest, channel);
  }
  return attenuation * spot * largest;
}

// ContributionBound on `count` random boxes per light kind against ContributionAt at 30
// points of each: the corners, the point nearest the light, random ones. The light lies in
// the box in one case of eight and on its boundary in one of eight; a spot is aimed at the
// box's centre in one case of four and at a corner in one of eight (the cone's edge across
// the box), else anywhere.
bool CheckContributionBound(int count)
{
  std::mt19937 random(29);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const char* kinds[] = { "point", "attenuated point", "spot", "spot, falloff and attenuation" };
  vtkNew<vtkLight> light;
  light->SetPositional(true);
  bool ok = true;
  for (int kind = 0; kind < 4; ++kind)
  {
    const bool isSpot = kind >= 2;
    double tightest = 0.0;
    for (int trial = 0; trial < count; ++trial)
    {
      double box[6], position[3], axis[3], weights[3][3];
      RandomBox(random, box);
      const int where = static_cast<int>(random() % 8);
      PointOfBox(random, box, where == 0 ? 8 : static_cast<int>(random() % 8), position);
      for (int i = 0; i < 3 && where > 1; ++i)
      {
        position[i] = where == 1 ? position[i] : 20.0 * unit(random) - 10.0;
      }
      double target[3];
      PointOfBox(random, box, trial % 8 == 0 ? static_cast<int>(random() % 8) : 8, target);
      const bool aimed = trial % 4 == 0 || trial % 8 == 1;
      for (int i = 0; i < 3; ++i)
      {
        const double centre = 0.5 * (box[2 * i] + box[2 * i + 1]);
        axis[i] = aimed ? (trial % 4 == 0 ? centre : target[i]) - position[i] : unit(random) - 0.5;
      }
      if (!(vtkMath::Normalize(axis) > 0.0))
      {
        axis[0] = 1.0;
      }
      light->SetConeAngle(1.0 + 88.9 * unit(random));
      light->SetExponent(kind == 3 ? 20.0 * unit(random) * unit(random) : 1.0);
      const bool attenuated = kind == 1 || kind == 3;
      light->SetAttenuationValues(attenuated ? (trial % 16 == 0 ? 0.0 : 2.0 * unit(random)) : 1.0,
        attenuated ? unit(random) : 0.0, attenuated ? unit(random) : 0.0);
      light->SetIntensity(2.0 * unit(random));
      light->SetAmbientColor(unit(random), unit(random), unit(random));
      light->SetDiffuseColor(unit(random), unit(random), unit(random));
      light->SetSpecularColor(unit(random), unit(random), unit(random));
      for (auto& term : weights)
      {
        for (double& weight : term)
        {
          weight = 2.0 * unit(random);
        }
      }
      const double bound =
        vtkPhongLightCulling::ContributionBound(light, isSpot, position, axis, box, weights);
      for (int k = 0; k < 30; ++k)
      {
        double p[3];
        PointOfBox(random, box, k, p);
        if (k == 8) // the point of the box nearest the light
        {
          for (int i = 0; i < 3; ++i)
          {
            p[i] = std::min(std::max(position[i], box[2 * i]), box[2 * i + 1]);
          }
        }
        const double actual = ContributionAt(light, isSpot, position, axis, p, weights);
        tightest = bound > 0.0 ? std::max(tightest, actual / bound) : tightest;
        if (!(actual <= bound * (1.0 + 1.0e-12)))
        {
          std::cerr << kinds[kind] << ", box " << trial << ": " << actual << " at a point > bound "
                    << bound << "\n";
          ok = false;
          break;
        }
      }
    }
    std::cout << kinds[kind] << ": " << count << " random boxes, largest contribution / bound "
              << tightest << "\n";
  }
  return ok;
}

struct CullingScene
{
  static constexpr double Spacing = 30.0;
  static constexpr double Intensity = 0.03;
  vtkPhongTest::Scene View{ 320, 320 };
  std::vector<vtkPhongPolyDataMapper*> Mappers;
  std::vector<vtkLight*> Lights;

  explicit CullingScene(vtkPhongTest::ActorKind kind = vtkPhongTest::ActorKind::Plain)
  {
    this->View.Renderer->AutomaticLightCreationOff();
    vtkNew<vtkPhongProperty> material;
    material->SetAmbient(0.1);
    material->SetDiffuse(0.8);
    material->SetSpecular(0.4);
    material->SetShininess(20.0);
    const double white[3] = { 1.0, 1.0, 1.0 };
    for (int i = 0; i < 4; ++i)
    {
      // Spheres of radius 1.5 on a 2 x 2 grid, Spacing apart.
      const double center[3] = { (i % 2 - 0.5) * Spacing, (i / 2 - 0.5) * Spacing, 0.0 };
      vtkActor* actor = vtkPhongTest::AddActor(
        this->View, vtkPhongTest::MakeSphere(48, 1.5), material, vtkPhongTest::MakeActor(kind));
      actor->SetPosition(center[0], center[1], center[2]);
      this->Mappers.push_back(vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper()));
      // 16 point lights close in front of each: two rings 0.3 off the surface.
      for (int k = 0; k < 16; ++k)
      {
        const double azimuth = 2.0 * vtkMath::Pi() * (k % 8) / 8.0;
        const double polar = vtkMath::RadiansFromDegrees(k < 8 ? 35.0 : 70.0);
        const double r = 1.8;
        const double position[3] = { center[0] + r * std::sin(polar) * std::cos(azimuth),
          center[1] + r * std::sin(polar) * std::sin(azimuth), r * std::cos(polar) };
        vtkLight* light = vtkPhongTest::AddLight(this->View, position, center, white, true);
        light->SetIntensity(Intensity);
        light->SetAttenuationValues(0.0, 0.0, 1.0);
        this->Lights.push_back(light);
      }
    }
    vtkCamera* camera = this->View.Renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(0.0, 0.0, 2.2 * Spacing);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(30.0);
    this->View.Renderer->ResetCameraClippingRange();
  }

  vtkSmartPointer<vtkImageData> Render(double bound)
  {
    for (vtkPhongPolyDataMapper* mapper : this->Mappers)
    {
      mapper->SetLightCullingBound(bound);
    }
    return vtkPhongTest::RenderFloat(this->View, this->Pass);
  }

  int CompileCount()
  {
    int count = 0;
    for (vtkPhongPolyDataMapper* mapper : this->Mappers)
    {
      count += mapper->GetShaderCompileCount();
    }
    return count;
  }

  vtkNew<vtkPhongFloatRenderPass> Pass;
};
}

int TestPhongLightCulling(int, char*[])
{
  vtkPhongTest::Checks checks;
  checks.Expect(CheckContributionBound(100000), "each light's contribution within its bound");
  CullingScene scene;

  const auto all = scene.Render(0.0);
  for (vtkPhongPolyDataMapper* mapper : scene.Mappers)
  {
    checks.Expect(mapper->GetNumberOfCulledLights() == 0, "bound 0: no light culled");
  }
  checks.Expect(vtkPhongTest::LargestValue(all) > 0.2, "the spheres are lit");

  const auto culled = scene.Render(DefaultBound);
  for (size_t i = 0; i < scene.Mappers.size(); ++i)
  {
    const int evaluated = 64 - scene.Mappers[i]->GetNumberOfCulledLights();
    std::cout << "sphere " << i << ": " << evaluated << " of 64 lights evaluated\n";
    checks.Expect(evaluated >= 1 && evaluated <= 16,
      "sphere " + std::to_string(i) + ": a few lights evaluated (" + std::to_string(evaluated) +
        " of 64)");
  }
  const double difference = LargestDifference(all, culled);
  std::cout << "largest difference, default bound: " << difference << " (bound " << DefaultBound
            << ")\n";
  // Float rounding of the sums that remain: a few ulps of values near 1.
  checks.Expect(difference <= DefaultBound + 1.0e-6,
    "culled within 0.5/255 of unculled (" + std::to_string(difference) + ")");

  // A bound of 1 culls some of each sphere's own lights: the comparison sees that.
  const auto coarse = scene.Render(1.0);
  const double coarseDifference = LargestDifference(all, coarse);
  std::cout << "largest difference, bound 1: " << coarseDifference << "\n";
  checks.Expect(coarseDifference > DefaultBound && coarseDifference <= 1.0 + 1.0e-6,
    "bound 1: differs by more than 0.5/255, within 1 (" + std::to_string(coarseDifference) + ")");

  { // A spot without attenuation in front of sphere 0, pointing away from every sphere:
    // only its cone can cull it, and does, for every sphere.
    const double position[3] = { -0.5 * CullingScene::Spacing, -0.5 * CullingScene::Spacing, 3.0 };
    const double focal[3] = { position[0], position[1], 10.0 };
    const double white[3] = { 1.0, 1.0, 1.0 };
    vtkLight* spot = vtkPhongTest::AddLight(scene.View, position, focal, white, true);
    spot->SetConeAngle(30.0);
    const auto withSpot = scene.Render(0.0);
    const auto withSpotCulled = scene.Render(DefaultBound);
    bool allCulled = true;
    for (vtkPhongPolyDataMapper* mapper : scene.Mappers)
    {
      allCulled = allCulled && mapper->GetNumberOfCulledLights() == 49;
    }
    checks.Expect(allCulled, "a spot aimed away from every sphere is culled by its cone");
    checks.Expect(LargestDifference(withSpot, withSpotCulled) <= DefaultBound + 1.0e-6,
      "with the spot: culled within 0.5/255 of unculled");
    scene.View.Renderer->RemoveLight(spot);
  }

  // Actors that draw through an internal one without bounds (vtkFollower: vedo 2023's meshes;
  // vtkLODActor) cull as a vtkActor does.
  scene.Render(DefaultBound);
  for (auto kind : { vtkPhongTest::ActorKind::Follower, vtkPhongTest::ActorKind::LOD })
  {
    CullingScene wrapped(kind);
    wrapped.Render(DefaultBound);
    for (size_t i = 0; i < scene.Mappers.size(); ++i)
    {
      const int culled = wrapped.Mappers[i]->GetNumberOfCulledLights();
      checks.Expect(culled > 0 && culled == scene.Mappers[i]->GetNumberOfCulledLights(),
        std::string(vtkPhongTest::ActorKindName(kind)) + ", sphere " + std::to_string(i) +
          ": culls as a vtkActor (" + std::to_string(culled) + " lights culled)");
    }
  }

  // The variant cache: the same frame again, and a far light moved a little, compile nothing.
  scene.Render(DefaultBound);
  const int compiled = scene.CompileCount();
  scene.Render(DefaultBound);
  double position[3];
  scene.Lights[5]->GetPosition(position);
  scene.Lights[5]->SetPosition(position[0], position[1] + 0.01, position[2]);
  scene.Render(DefaultBound);
  checks.Expect(scene.CompileCount() == compiled,
    "re-rendering and moving a light a little compile nothing (" +
      std::to_string(scene.CompileCount() - compiled) + " compiles)");
  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
