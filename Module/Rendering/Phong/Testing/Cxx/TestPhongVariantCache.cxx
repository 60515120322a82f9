// Changing a value (colour, intensity, light position, shininess, camera)
// updates uniforms and never builds a shader; changing the structure (a term
// switched on or off, a new light kind, the lobe, a light's attenuation leaving
// VTK's (1, 0, 0), a light's specular colour leaving its diffuse colour) builds
// exactly one variant, and going back to a structure seen before builds nothing.

#include "vtkPhongTestUtilities.h"

#include <functional>

int TestPhongVariantCache(int, char*[])
{
  vtkPhongTest::Scene scene(64, 64);
  scene.Renderer->AutomaticLightCreationOff();
  const double key[3] = { 0.5, 0.5, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  vtkLight* light = vtkPhongTest::AddLight(scene, key, origin, white, false);
  vtkNew<vtkPhongProperty> material;
  material->SetColor(0.8, 0.5, 0.3);
  material->SetAmbient(0.1);
  material->SetSpecular(0.5);
  material->SetShininess(20.0);
  vtkActor* actor = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(32), material);
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper());
  scene.LookFromZ(2.5);
  scene.Window->Render();

  vtkPhongTest::Checks checks;
  checks.Expect(mapper->GetShaderCompileCount() == 1, "the first frame builds one shader");

  auto centreRed = [&]()
  {
    scene.Window->Render();
    return int(vtkPhongTest::PixelAt(vtkPhongTest::Snapshot(scene.Window), 32, 32)[0]);
  };
  // Each value change must show in the picture (the uniform really changed)
  // without a new shader.
  const std::pair<const char*, std::function<void()>> valueChanges[] = {
    { "material colour", [&] { material->SetDiffuseColor(0.2, 0.5, 0.3); } },
    { "light intensity", [&] { light->SetIntensity(0.5); } },
    // SetColor sets the diffuse and the specular colour: they stay equal, a value change.
    { "light colour", [&] { light->SetColor(0.5, 1.0, 1.0); } },
    { "light position", [&] { light->SetPosition(-0.5, 0.2, 1.0); } },
    { "renderer ambient", [&] { scene.Renderer->SetAmbient(2.0, 0.0, 0.0); } },
    { "shininess", [&] { material->SetShininess(2.0); } },
    { "specular coefficient", [&] { material->SetSpecular(0.9); } },
    { "emission", [&] { material->SetEmission(0.2, 0.0, 0.0); } },
  };
  int before = centreRed();
  for (const auto& change : valueChanges)
  {
    const int compiles = mapper->GetShaderCompileCount();
    change.second();
    const int after = centreRed();
    checks.Expect(after != before, std::string(change.first) + " changes the picture");
    checks.Expect(
      mapper->GetShaderCompileCount() == compiles, std::string(change.first) + " builds no shader");
    before = after;
  }
  const int compiles = mapper->GetShaderCompileCount();
  scene.Renderer->GetActiveCamera()->Azimuth(30.0);
  centreRed();
  checks.Expect(mapper->GetShaderCompileCount() == compiles, "moving the camera builds no shader");

  // Structure changes: one new variant each, and none when coming back.
  vtkLight* point = nullptr;
  const std::pair<const char*, std::function<void()>> structureChanges[] = {
    { "specular off", [&] { material->SetSpecular(0.0); } },
    { "specular on again", [&] { material->SetSpecular(0.5); } },
    { "a point light",
      [&]
      {
        point = vtkPhongTest::AddLight(scene, key, origin, white, true);
        point->SetConeAngle(180.0);
      } },
    { "Blinn-Phong lobe", [&] { material->SetLightingModelToBlinnPhong(); } },
    { "Phong lobe again", [&] { material->SetLightingModelToPhong(); } },
    // A light parameter leaving its neutral value adds a term, as a coefficient leaving 0.
    { "the point light's attenuation leaves (1, 0, 0)",
      [&] { point->SetAttenuationValues(1.0, 0.3, 0.0); } },
    { "another attenuation: a value", [&] { point->SetAttenuationValues(1.0, 0.0, 0.4); } },
    // The specular sums read the diffuse colours until a light's specular colour differs.
    { "a light's specular colour leaving its diffuse colour",
      [&] { light->SetSpecularColor(1.0, 0.5, 0.5); } },
    { "another specular colour: a value", [&] { light->SetSpecularColor(0.2, 0.5, 1.0); } },
    { "the specular colour back to the diffuse colour",
      [&] { light->SetSpecularColor(0.5, 1.0, 1.0); } },
  };
  const int expectedNew[] = { 1, 0, 1, 1, 0, 1, 0, 1, 0, 0 };
  for (int i = 0; i < 10; ++i)
  {
    const int count = mapper->GetShaderCompileCount();
    structureChanges[i].second();
    centreRed();
    const int built = mapper->GetShaderCompileCount() - count;
    checks.Expect(built == expectedNew[i],
      std::string(structureChanges[i].first) + " builds " + std::to_string(expectedNew[i]) +
        " shader(s), built " + std::to_string(built));
  }
  checks.Expect(mapper->GetNumberOfShaderVariants() == 6,
    "six distinct variants: " + std::to_string(mapper->GetNumberOfShaderVariants()));
  checks.Expect(mapper->GetLastShaderBuildTime() > 0.0, "the build time is measured");
  checks.Expect(vtkPhongTest::NoGLErrors(scene.Window, "the variant changes"), "no GL error");
  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
