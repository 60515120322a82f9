// The generated shader contains only what the scene needs: no specular code
// when ks = 0, no attenuation code without positional lights or for lights with
// VTK's (1, 0, 0), no positional ambient code for lights without ambient
// colour, no spot code without spots and no falloff code for exponent 1, no
// emission without a vtkPhongProperty, per-vertex lighting in the vertex shader
// only, no specular colour arrays while every light's specular colour is its
// diffuse colour, and no template directive left over. The all-features variant
// holds everything and draws the same picture. Directional lights take N.L and L.V from dot
// products interpolated from the vertices where VTK's vertex normal is the shading normal,
// and draw the picture of the per-fragment dot products. Also resolves every template
// section under many flag combinations without an error.

#include "vtkPhongReferenceTesting.h"

#include "vtkMultiBlockDataSet.h"
#include "vtkPhongCompositePolyDataMapper.h"
#include "vtkPhongShaderPlan.h"
#include "vtkPhongShaderPlanner.h"
#include "vtkPhongShaderTemplate.h"
#include "vtkShaderProperty.h"
#include "vtkSphereSource.h"

namespace
{
bool Has(const std::string& source, const char* text)
{
  return source.find(text) != std::string::npos;
}

// INTERPOLATED_DOTS: on for VTK's vertex normals under as many directional lights as the
// varyings carry, with the Phong lobe; off for the Blinn lobe, more lights or shader code of the
// user's (which may change the normal). Where it is on, the float picture is the one of the
// per-fragment dot products (a no-op replacement turns them back on) within float rounding, in
// perspective and parallel projection, with one- and two-sided lighting, on a bowl that shows its
// back faces. (Not bit for bit: the two round differently.)
void CheckInterpolatedDots(vtkPhongTest::Checks& checks)
{
  vtkPhongTest::Scene view(96, 96);
  view.Renderer->AutomaticLightCreationOff();
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double warm[3] = { 1.0, 0.8, 0.6 };
  const double cool[3] = { 0.5, 0.7, 1.0 };
  const double key[3] = { 0.5, 0.8, 1.0 };
  const double rim[3] = { -1.0, -0.2, -0.3 };
  vtkPhongTest::AddLight(view, key, origin, warm, false);
  vtkPhongTest::AddLight(view, rim, origin, cool, false);
  vtkNew<vtkSphereSource> bowl; // open: its inside shows the back faces
  bowl->SetThetaResolution(48);
  bowl->SetPhiResolution(48);
  bowl->SetStartPhi(60.0);
  bowl->Update();
  vtkNew<vtkPhongProperty> shiny;
  shiny->SetColor(0.8, 0.5, 0.3);
  shiny->SetSpecular(0.6);
  shiny->SetShininess(30.0);
  vtkActor* actor = vtkPhongTest::AddActor(view, bowl->GetOutput(), shiny);
  actor->RotateX(-60.0);
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper());
  view.LookFromZ(2.5);
  auto dotsOn = [&]
  {
    view.Window->Render();
    return Has(mapper->GetLastShaderSignature(), "INTERPOLATED_DOTS") &&
      Has(mapper->GetLastVertexShaderSource(), "phongDirectionalNormalDotLVSOutput");
  };
  checks.Expect(dotsOn(), "interpolated dots for 2 directional lights and the Phong lobe");

  vtkNew<vtkPhongFloatRenderPass> floatPass;
  vtkShaderProperty* shaders = actor->GetShaderProperty();
  for (const bool parallel : { false, true })
  {
    for (const bool twoSided : { true, false })
    {
      view.Renderer->GetActiveCamera()->SetParallelProjection(parallel);
      view.Renderer->SetTwoSidedLighting(twoSided);
      const std::string where = std::string(parallel ? "parallel" : "perspective") +
        (twoSided ? ", two-sided" : ", one-sided");
      checks.Expect(dotsOn(), "interpolated dots, " + where);
      auto withDots = vtkPhongTest::RenderFloat(view, floatPass);
      shaders->AddFragmentShaderReplacement(
        "//VTK::Light::Impl", false, "//VTK::Light::Impl", false);
      checks.Expect(!dotsOn(), "no interpolated dots with a replacement of the user's, " + where);
      auto withoutDots = vtkPhongTest::RenderFloat(view, floatPass);
      shaders->ClearAllShaderReplacements();
      // Float rounding only: within a hundredth of an 8-bit level at every pixel.
      const auto error = vtkPhongTest::MeasureAgainst(withDots, withoutDots, 0);
      checks.Expect(error.Valid && error.NaNPixels == 0 && error.MaxAbsolute <= 0.01 / 255.0,
        "interpolated dots draw the picture of per-fragment dots, " + where +
          " (largest difference " + std::to_string(error.MaxAbsolute) + ")");
    }
  }
  view.Renderer->SetPass(nullptr);

  mapper->InterpolatedDotProductsOff();
  checks.Expect(!dotsOn(), "no interpolated dots when the mapper's switch is off");
  mapper->InterpolatedDotProductsOn();
  shiny->SetLightingModelToBlinnPhong();
  checks.Expect(!dotsOn(), "no interpolated dots with the Blinn lobe");
  shiny->SetLightingModelToPhong();
  // As many lights as the context's varyings carry (llvmpipe: 48), not one more.
  view.Window->MakeCurrent();
  const std::size_t maximum = vtkPhongShaderPlanner::MaximumInterpolatedDotLights();
  checks.Expect(maximum >= 12 && maximum <= 64,
    "an OpenGL 3.2 context carries the dots of 12 to 64 lights (" + std::to_string(maximum) + ")");
  for (std::size_t light = 2; light < maximum; ++light)
  {
    vtkPhongTest::AddLight(view, key, origin, warm, false);
  }
  checks.Expect(
    dotsOn(), "interpolated dots for " + std::to_string(maximum) + " directional lights");
  vtkPhongTest::AddLight(view, key, origin, warm, false);
  checks.Expect(!dotsOn(), "no interpolated dots for one light more");
  checks.Expect(vtkPhongTest::NoGLErrors(view.Window, "interpolated dots"), "no GL error");
}
}

int TestPhongShaderSpecialization(int, char*[])
{
  vtkPhongTest::Checks checks;
  vtkPhongTest::Scene scene(64, 64);
  scene.Renderer->AutomaticLightCreationOff();
  const double key[3] = { 0.5, 0.5, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  vtkPhongTest::AddLight(scene, key, origin, white, false);
  vtkNew<vtkProperty> plain; // a plain vtkProperty: VTK's defaults, ks = 0, ka = 0
  vtkActor* actor = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(32), plain);
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper());
  scene.LookFromZ(2.5);
  auto render = [&]()
  {
    scene.Window->Render();
    return std::string(mapper->GetLastFragmentShaderSource());
  };

  std::string fs = render();
  checks.Expect(Has(fs, "phongDirectionalLightDiffuse"), "diffuse code for the directional light");
  checks.Expect(
    !Has(fs, "phongSpecular") && !Has(fs, "specularLight"), "no specular code at ks = 0");
  checks.Expect(!Has(fs, "phongDistanceAttenuation"), "no attenuation without positional lights");
  checks.Expect(!Has(fs, "phongPointLight") && !Has(fs, "phongSpotLight"), "no point or spot code");
  checks.Expect(
    !Has(fs, "phongAmbientLight") && !Has(fs, "phongAmbientTerm"), "no ambient code at ka = 0");
  checks.Expect(!Has(fs, "phongEmission"), "no emission for a plain vtkProperty");
  checks.Expect(!Has(fs, "//PHONG_") && !Has(fs, "@"), "no template directive left");
  checks.Expect(!Has(fs, "dFdx(vertexVC"), "no screen-space normal fallback for clean normals");

  plain->SetSpecular(0.4);
  plain->SetAmbient(0.2);
  fs = render();
  checks.Expect(Has(fs, "phongSpecular(") && Has(fs, "2.0 * NdotL * N - L"), "Phong lobe code");
  checks.Expect(!Has(fs, "halfway"), "no Blinn code with the Phong lobe");
  checks.Expect(Has(fs, "phongAmbientTerm"), "ambient code at ka > 0 (ready-made ka*Ca*Ia)");
  checks.Expect(!Has(fs, "ambientColor *") && !Has(fs, "diffuseColor *"),
    "uniform material colours: VTK's products are not read");

  vtkLight* point = vtkPhongTest::AddLight(scene, key, origin, white, true);
  point->SetConeAngle(180.0);
  fs = render();
  checks.Expect(Has(fs, "phongPointLightPositionVC") && !Has(fs, "phongDistanceAttenuation"),
    "point light code, no attenuation code for (c, l, q) = (1, 0, 0)");
  checks.Expect(!Has(fs, "phongPointLightAmbient"), "no ambient code for a black ambient colour");
  checks.Expect(!Has(fs, "phongSpotLight"), "no spot code without spots");
  point->SetAttenuationValues(1.0, 0.5, 0.0);
  point->SetAmbientColor(0.2, 0.2, 0.2);
  fs = render();
  checks.Expect(Has(fs, "phongDistanceAttenuation(phongPointLightAttenuation"),
    "attenuation code for an attenuated point light");
  checks.Expect(Has(fs, "phongPointLightAmbient"), "ambient code for a light's ambient colour");

  point->SetConeAngle(30.0);
  fs = render();
  checks.Expect(Has(fs, "phongSpotLightCosCutoff") && !Has(fs, "phongPointLightPositionVC"),
    "the light is now a spot: spot code only");
  checks.Expect(!Has(fs, "smoothstep"), "no soft edge code unless asked");
  checks.Expect(!Has(fs, "phongSpotLightExponent"), "no falloff code for exponent 1");
  point->SetExponent(3.0);
  fs = render();
  checks.Expect(Has(fs, "pow(max(cosPhi, 0.0), phongSpotLightExponent"), "falloff code");

  vtkNew<vtkPhongProperty> material;
  material->SetSpecular(0.4);
  material->SetLightingModelToBlinnPhong();
  material->SoftSpotEdgeOn();
  actor->SetProperty(material);
  fs = render();
  checks.Expect(Has(fs, "halfway") && !Has(fs, "2.0 * NdotL * N - L"), "Blinn lobe code only");
  checks.Expect(Has(fs, "smoothstep"), "soft edge code");
  checks.Expect(Has(fs, "phongEmission"), "emission code for a vtkPhongProperty");

  material->SetInterpolationToPerVertexGouraud();
  fs = render();
  const std::string vs = mapper->GetLastVertexShaderSource();
  checks.Expect(Has(vs, "phongSumLights(") && !Has(fs, "phongSumLights("),
    "per-vertex Gouraud lights in the vertex shader only");

  // One NaN normal: the screen-space fallback appears (a scan per change of the array).
  material->SetInterpolationToPhong();
  auto mesh = vtkPhongTest::MakeSphere(32);
  mesh->GetPointData()->GetNormals()->SetTuple3(7, std::nan(""), 0.0, 0.0);
  mapper->SetInputData(mesh);
  fs = render();
  checks.Expect(Has(fs, "dFdx(vertexVC"), "a NaN normal brings the screen-space fallback");

  mapper->SetDebugViewToShadingNormal();
  fs = render();
  checks.Expect(!Has(fs, "phongSumLights") && Has(fs, "0.5 * phongNormalVC + 0.5"),
    "the normal view has no light code");
  mapper->SetDebugViewToFinal();

  // The all-features variant: everything, whatever the scene, and the same picture.
  {
    vtkPhongTest::Scene view(96, 96);
    view.Renderer->AutomaticLightCreationOff();
    vtkPhongTest::AddLight(view, key, origin, white, false);
    vtkNew<vtkProperty> shiny;
    shiny->SetSpecular(0.5);
    shiny->SetSpecularPower(20.0);
    shiny->SetAmbient(0.1);
    vtkActor* ball = vtkPhongTest::AddActor(view, vtkPhongTest::MakeSphere(48), shiny);
    auto* ballMapper = vtkPhongPolyDataMapper::SafeDownCast(ball->GetMapper());
    view.LookFromZ(2.5);
    view.Window->Render();
    const std::string specialized = ballMapper->GetLastFragmentShaderSource();
    auto picture = vtkPhongTest::Snapshot(view.Window);
    ballMapper->ShaderSpecializationOff();
    view.Window->Render();
    const std::string everything = ballMapper->GetLastFragmentShaderSource();
    for (const char* part : { "phongPointLightPositionVC", "phongSpotLightCosCutoff",
           "phongDistanceAttenuation", "phongSpotLightExponent", "smoothstep",
           "phongPointLightAmbient", "phongEmission", "dFdx(vertexVC" })
    {
      checks.Expect(!Has(specialized, part) && Has(everything, part),
        std::string("the all-features variant alone has ") + part);
    }
    checks.Expect(
      std::string(ballMapper->GetLastShaderSignature()).find("all features") != std::string::npos,
      "the all-features signature says so");
    const int difference =
      vtkPhongTest::MaxDifference(picture, vtkPhongTest::Snapshot(view.Window));
    checks.Expect(difference <= 1,
      "the all-features variant draws the same picture (" + std::to_string(difference) +
        " levels)");
  }

  // Specular colours: the specular sums read the diffuse colour arrays while every light's
  // specular colour is its diffuse colour, and arrays of their own once one differs. Both
  // variants draw the same picture, bit for bit, when the values are the same: a second light
  // behind the sphere lights no visible point (N.L < 0 there, every term exactly 0) and
  // switches the variant by its specular colour alone.
  {
    vtkPhongTest::Scene view(96, 96);
    view.Renderer->AutomaticLightCreationOff();
    const double behind[3] = { 0.0, 0.0, -1.0 };
    vtkLight* keyLight = vtkPhongTest::AddLight(view, key, origin, white, false);
    keyLight->SetColor(1.0, 0.9, 0.7);
    vtkLight* backLight = vtkPhongTest::AddLight(view, behind, origin, white, false);
    vtkNew<vtkPhongProperty> shiny;
    shiny->SetColor(0.8, 0.5, 0.3);
    shiny->SetAmbient(0.1);
    shiny->SetSpecular(0.6);
    shiny->SetShininess(20.0);
    vtkActor* ball = vtkPhongTest::AddActor(view, vtkPhongTest::MakeSphere(48), shiny);
    auto* ballMapper = vtkPhongPolyDataMapper::SafeDownCast(ball->GetMapper());
    view.LookFromZ(2.5);
    vtkNew<vtkPhongFloatRenderPass> floatPass;
    auto renderBoth =
      [&](vtkSmartPointer<vtkImageData>& picture, vtkSmartPointer<vtkImageData>& floatPicture)
    {
      view.Renderer->SetPass(nullptr);
      view.Window->Render();
      picture = vtkPhongTest::Snapshot(view.Window);
      floatPicture = vtkPhongTest::RenderFloat(view, floatPass);
      view.Renderer->SetPass(nullptr);
      return std::string(ballMapper->GetLastFragmentShaderSource());
    };
    vtkSmartPointer<vtkImageData> shared, sharedFloat, separate, separateFloat;
    const std::string sharedSource = renderBoth(shared, sharedFloat);
    checks.Expect(!Has(sharedSource, "phongDirectionalLightSpecular") &&
        Has(sharedSource, "phongDirectionalLightDiffuse[i] * specular;"),
      "equal colours: the specular sum reads the diffuse colours, no specular array");
    const int variants = ballMapper->GetNumberOfShaderVariants();
    backLight->SetSpecularColor(0.2, 0.4, 1.0);
    const std::string separateSource = renderBoth(separate, separateFloat);
    checks.Expect(Has(separateSource, "uniform vec3 phongDirectionalLightSpecular[2]") &&
        Has(separateSource, "phongDirectionalLightSpecular[i] * specular;"),
      "a specular colour apart: the specular sum reads its own colours");
    checks.Expect(ballMapper->GetNumberOfShaderVariants() == variants + 1,
      "a specular colour apart is one more variant");
    const int difference = vtkPhongTest::MaxDifference(shared, separate);
    checks.Expect(difference == 0,
      "shared and separate colour arrays: the same 8-bit picture (" + std::to_string(difference) +
        " levels)");
    checks.Expect(vtkPhongTest::ArraysEqual(sharedFloat->GetPointData()->GetScalars(),
                    separateFloat->GetPointData()->GetScalars()),
      "shared and separate colour arrays: the same float picture");
    // The all-features variant keeps the specular arrays, whatever the colours.
    keyLight->SetSpecularColor(1.0, 0.9, 0.7);
    backLight->SetSpecularColor(1.0, 1.0, 1.0);
    ballMapper->ShaderSpecializationOff();
    const std::string everything = renderBoth(separate, separateFloat);
    checks.Expect(Has(everything, "phongDirectionalLightSpecular[i]"),
      "the all-features variant keeps the specular colour arrays");
    ballMapper->ShaderSpecializationOn();

    // The composite mapper plans its blocks the same way.
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetNumberOfBlocks(1);
    blocks->SetBlock(0, vtkPhongTest::MakeSphere(24));
    vtkNew<vtkPhongCompositePolyDataMapper> composite;
    composite->SetInputDataObject(blocks);
    ball->SetMapper(composite);
    view.Window->Render();
    auto signature = [&] { return std::string(composite->GetLastShaderSignature()); };
    checks.Expect(!signature().empty() && !Has(signature(), "SEPARATE_SPECULAR_COLORS"),
      "composite mapper, equal colours: shared colour arrays (" + signature() + ")");
    checks.Expect(Has(signature(), "INTERPOLATED_DOTS"), "composite mapper: interpolated dots");
    composite->InterpolatedDotProductsOff();
    view.Window->Render();
    checks.Expect(!Has(signature(), "INTERPOLATED_DOTS"),
      "composite mapper: no interpolated dots when its switch is off");
    composite->InterpolatedDotProductsOn();
    view.Window->Render();
    backLight->SetSpecularColor(0.2, 0.4, 1.0);
    view.Window->Render();
    checks.Expect(Has(signature(), "SEPARATE_SPECULAR_COLORS"),
      "composite mapper, a specular colour apart: separate arrays");
    const int compositeVariants = composite->GetNumberOfShaderVariants();
    backLight->SetSpecularColor(1.0, 1.0, 1.0);
    view.Window->Render();
    checks.Expect(!Has(signature(), "SEPARATE_SPECULAR_COLORS") &&
        composite->GetNumberOfShaderVariants() == compositeVariants,
      "composite mapper: back to shared arrays, no new variant");
    checks.Expect(vtkPhongTest::NoGLErrors(view.Window, "specular colours"), "no GL error");
  }

  CheckInterpolatedDots(checks);

  // Every section of every template resolves cleanly under flag sets that
  // switch each conditional both ways.
  vtkNew<vtkObject> reporter; // the object the template's errors name
  vtkPhongTest::ErrorCollector errors;
  errors.Observe(reporter);
  const vtkPhongShaderTemplate resolver(reporter);
  using F = vtkPhongFeature;
  const std::vector<std::vector<vtkPhongFeature>> flagSets = {
    {},
    { F::Ambient, F::Diffuse, F::Specular, F::DiffuseOrSpecular, F::Emission, F::PositionalAmbient,
      F::LightSums, F::Directional, F::Point, F::Spot, F::Positional, F::LobePhong,
      F::SmoothTerminator, F::SoftSpotEdge, F::Parallel, F::PerVertex, F::SumsPerVertex,
      F::TwoSided, F::BackMaterial, F::ShadingNormal, F::NormalFallback, F::ViewVector,
      F::DebugNormal, F::PointAttenuation, F::SpotAttenuation, F::Attenuation, F::SpotFalloff,
      F::DebugNormalVC, F::DebugPositionVC, F::SeparateSpecularColors },
    { F::Diffuse, F::LightSums, F::Directional, F::SumsPerFragment, F::ShadingNormal, F::OneSided,
      F::ViewVector, F::LobeBlinn, F::Specular },
  };
  const char* sections[][2] = { { "vtkPhongLightingLib", "Sums" },
    { "vtkPhongLightingLib", "Lights" }, { "vtkPhongFS", "Dec" }, { "vtkPhongFS", "UniformFlow" },
    { "vtkPhongFS", "Impl" }, { "vtkPhongFS", "PostTexture" }, { "vtkPhongVS", "Dec" },
    { "vtkPhongVS", "Impl" }, { "vtkPhongGS", "Dec" }, { "vtkPhongGS", "Impl" } };
  for (const auto& flags : flagSets)
  {
    vtkPhongShaderPlan plan;
    for (vtkPhongFeature feature : flags)
    {
      plan.Features.Set(feature);
    }
    for (const auto& section : sections)
    {
      const std::string code =
        resolver.Resolve(vtkPhongShaderTemplate::Get(section[0]), section[1], plan);
      checks.Expect(!Has(code, "//PHONG_") && !Has(code, "@"),
        std::string(section[0]) + " " + section[1] + ": directives resolved");
    }
  }
  checks.Expect(errors.Messages.empty(), "the templates are well formed");

  // A feature name the module does not know is an error, not a silent no-op.
  resolver.Resolve(
    "//PHONG_SECTION Probe\n//PHONG_IF SPECULR\nx\n//PHONG_ENDIF\n", "Probe", vtkPhongShaderPlan());
  checks.Expect(errors.Messages.size() == 1 && Has(errors.Messages[0], "SPECULR"),
    "a misspelt feature in a template is reported");

  // One-sided lighting un-flips the normal by the side drawn only where VTK flipped it so:
  // VTK 9.7 turns lines' normals towards the viewer by their depth (its exact line, below).
  checks.Expect(!vtkPhongShaderTemplate::FlipsNormalByDepth(
                  "  if (gl_FrontFacing == false) { normalVCVSOutput = -normalVCVSOutput; }\n"),
    "VTK's surfaces flip by the side drawn");
  checks.Expect(vtkPhongShaderTemplate::FlipsNormalByDepth(
                  "  if (normalVCVSOutput.z < 0) { normalVCVSOutput = -normalVCVSOutput; }\n"),
    "VTK 9.7's lines flip by depth: no un-flip by the side drawn");
  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
