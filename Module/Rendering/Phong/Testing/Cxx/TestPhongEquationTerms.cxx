// Every term of the lighting equation, checked by value. A plane z = 0 facing
// +z fills a parallel view from +z (V = (0, 0, 1)); pixel (32, 32) of the
// 64x64 image shades the point (1/128, 1/128, 0) with N = (0, 0, 1), so each
// expected colour is a closed-form number (docs/lighting-model.md).
// 8-bit output: tolerance 1 level.

#include "vtkPhongTestUtilities.h"

#include "vtkMath.h"

#include <array>

namespace
{
struct TermScene
{
  vtkPhongTest::Scene View{ 64, 64 };
  vtkNew<vtkPhongProperty> Material;
  vtkActor* Actor = nullptr;

  TermScene()
  {
    this->Actor =
      vtkPhongTest::AddActor(this->View, vtkPhongTest::MakePlane(1.0, 4), this->Material);
    this->View.Renderer->AutomaticLightCreationOff();
    vtkCamera* camera = this->View.Renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetParallelScale(0.5);
    camera->SetPosition(0.0, 0.0, 5.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    this->View.Renderer->ResetCameraClippingRange();
    this->Material->SetColor(1.0, 1.0, 1.0);
    this->Material->SetAmbient(0.0);
    this->Material->SetDiffuse(0.0);
    this->Material->SetSpecular(0.0);
  }

  vtkLight* AddLight(const double position[3], const double focalPoint[3], bool positional)
  {
    const double white[3] = { 1.0, 1.0, 1.0 };
    return vtkPhongTest::AddLight(this->View, position, focalPoint, white, positional);
  }

  // The centre pixel as linear RGB in [0, 1].
  std::array<double, 3> Centre()
  {
    this->View.Window->Render();
    auto image = vtkPhongTest::Snapshot(this->View.Window);
    const unsigned char* pixel = vtkPhongTest::PixelAt(image, 32, 32);
    return { pixel[0] / 255.0, pixel[1] / 255.0, pixel[2] / 255.0 };
  }
};

void ExpectColor(vtkPhongTest::Checks& checks, const std::array<double, 3>& got,
  const std::array<double, 3>& expected, const std::string& what)
{
  const char* channel[3] = { " red", " green", " blue" };
  for (int c = 0; c < 3; ++c)
  {
    checks.Near(got[c], std::min(expected[c], 1.0), 1.01 / 255.0, what + channel[c]);
  }
}

// The surface point seen by pixel (32, 32): its centre is half a pixel
// (0.5 / 64 of the view's height of 1) off the middle.
const double shaded[3] = { 1.0 / 128.0, 1.0 / 128.0, 0.0 };
const double fromPlusZ[3] = { 0.0, 0.0, 1.0 };
const double origin[3] = { 0.0, 0.0, 0.0 };
}

int TestPhongEquationTerms(int, char*[])
{
  vtkPhongTest::Checks checks;

  { // kd*Cd*Ld*I*max(N.L, 0) for a directional light
    TermScene scene;
    vtkLight* light = scene.AddLight(fromPlusZ, origin, false);
    light->SetIntensity(0.8);
    light->SetDiffuseColor(1.0, 0.5, 0.25);
    scene.Material->SetDiffuse(1.0);
    scene.Material->SetDiffuseColor(0.5, 0.5, 0.5);
    ExpectColor(checks, scene.Centre(), { 0.4, 0.2, 0.1 }, "diffuse");

    // ka*Ca*Ia: the renderer's ambient light, which stock VTK ignores
    scene.Material->SetAmbient(0.5);
    scene.Material->SetAmbientColor(1.0, 1.0, 1.0);
    scene.View.Renderer->SetAmbient(0.2, 0.4, 0.6);
    ExpectColor(checks, scene.Centre(), { 0.5, 0.4, 0.4 }, "diffuse + renderer ambient");

    // ka*Ca*La*I: the light's ambient colour, which stock VTK ignores
    light->SetAmbientColor(0.5, 0.0, 0.0);
    ExpectColor(checks, scene.Centre(), { 0.7, 0.4, 0.4 }, "diffuse + both ambients");

    // E: emission
    scene.Material->SetEmission(0.0, 0.1, 0.0);
    ExpectColor(checks, scene.Centre(), { 0.7, 0.5, 0.4 }, "diffuse + ambients + emission");
  }

  { // ks*Cs*Ls*I*S: R = V here, so the Phong lobe is 1 whatever n
    TermScene scene;
    vtkLight* light = scene.AddLight(fromPlusZ, origin, false);
    light->SetIntensity(0.8);
    light->SetDiffuseColor(1.0, 1.0, 1.0);
    light->SetSpecularColor(0.0, 0.0, 1.0); // stock VTK would use the diffuse colour
    scene.Material->SetSpecular(1.0);
    scene.Material->SetShininess(50.0);
    ExpectColor(checks, scene.Centre(), { 0.0, 0.0, 0.8 }, "specular with the light's colour");

    // Normalized Blinn-Phong: the lobe times (n + 8) / 8
    scene.Material->SetLightingModelToNormalizedBlinnPhong();
    scene.Material->SetShininess(100.0);
    scene.Material->SetSpecular(0.05);
    ExpectColor(checks, scene.Centre(), { 0.0, 0.0, 0.05 * 13.5 * 0.8 }, "normalized Blinn-Phong");
    scene.Material->SetLightingModelToNormalizedPhong();
    ExpectColor(checks, scene.Centre(), { 0.0, 0.0, 0.05 * 51.0 * 0.8 }, "normalized Phong");
  }

  { // A point light at distance 2 with attenuation (1, 0.5, 0.25): A = 1/3
    TermScene scene;
    const double above[3] = { 0.0, 0.0, 2.0 };
    vtkLight* light = scene.AddLight(above, origin, true);
    light->SetConeAngle(180.0);
    light->SetAttenuationValues(1.0, 0.5, 0.25);
    scene.Material->SetDiffuse(1.0);
    scene.Material->SetDiffuseColor(0.9, 0.9, 0.9);
    ExpectColor(checks, scene.Centre(), { 0.3, 0.3, 0.3 }, "attenuated point light");
  }

  { // A spot at (0, 0, 2) aimed at (0.3, 0, 0): cos(phi) about 0.99
    TermScene scene;
    const double above[3] = { 0.0, 0.0, 2.0 };
    const double aim[3] = { 0.3, 0.0, 0.0 };
    vtkLight* light = scene.AddLight(above, aim, true);
    light->SetConeAngle(20.0);
    light->SetExponent(10.0);
    scene.Material->SetDiffuse(1.0);
    scene.Material->SetDiffuseColor(0.9, 0.9, 0.9);
    double axis[3], toPoint[3];
    vtkMath::Subtract(aim, above, axis);
    vtkMath::Subtract(shaded, above, toPoint);
    const double cosPhi =
      vtkMath::Dot(axis, toPoint) / (vtkMath::Norm(axis) * vtkMath::Norm(toPoint));
    const double spot = std::pow(cosPhi, 10.0);
    ExpectColor(checks, scene.Centre(), { 0.9 * spot, 0.9 * spot, 0.9 * spot }, "spot inside");
    light->SetConeAngle(5.0); // phi = 8.5 degrees: outside the cone
    ExpectColor(checks, scene.Centre(), { 0.0, 0.0, 0.0 }, "spot outside");
  }

  { // No light at all: unlit as stock VTK draws it, C = ka*Ca + kd*Cd (emission unused)
    TermScene scene;
    scene.Material->SetAmbient(0.5);
    scene.Material->SetDiffuse(0.5);
    scene.Material->SetColor(0.8, 0.6, 0.4);
    scene.Material->SetEmission(0.1, 0.0, 0.0);
    ExpectColor(checks, scene.Centre(), { 0.8, 0.6, 0.4 }, "no lights: unlit");
    // LightingWithoutLights: what the model gives without a light, C = E + ka*Ca*Ia.
    vtkPhongPolyDataMapper::SafeDownCast(scene.Actor->GetMapper())->LightingWithoutLightsOn();
    ExpectColor(checks, scene.Centre(), { 0.5, 0.3, 0.2 }, "no lights, LightingWithoutLights");
  }

  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
