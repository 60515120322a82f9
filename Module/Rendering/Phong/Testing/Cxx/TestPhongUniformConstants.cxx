// Under an error budget, light and material values that come back unchanged go into the
// fragment shader as constants (UNIFORM_CONSTANTS, vtkPhongMapperCore): the same floats as the
// uniforms, so the picture changes only by the rounding a compiler makes its own way. Checked
// here:
// - every float written as a literal reads back as the same float;
// - directional, attenuated point and soft-edged spot lights, and the Phong lobe whose vertex
//   shader reads the directions as uniforms: the picture with constants is the picture with
//   uniforms, to the rounding the compiler makes its own way (at most a level at a few pixels;
//   none on Debian 12);
// - the plan is charged that rounding (vtkPhongErrorBudget::ProgramRoundingError) where the
//   squaring did not charge it already;
// - when they are taken: from the second frame of a still scene; not while scene lights turn
//   with the camera, and after each new set of values only once they held for twice as many
//   frames as the time before, and half as many again once they served four times that;
//   always for camera lights, however the camera turns;
// - the material's values are constants too: the ready-made products, VTK's shininess and
//   opacity, and a back material's uniforms (a shell seen inside); also where every sum is
//   made per vertex, whose fragment shader reads only the material; but not the colours and
//   opacity VTK sets per block of a composite dataset, nor any material value in a renderer
//   of more than four actors (which share the lights' program instead);
// - a change of a light's or the material's value (a colour) shows in the picture;
// - a positional camera light, placed from the camera's frame, lights as in world coordinates;
// - never in the exact mode (budget 0), whose shaders stay those of a mapper without budget.

#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPhongCompositePolyDataMapper.h"
#include "vtkPhongShaderTemplate.h"
#include "vtkPhongTestUtilities.h"
#include "vtkPhongTwoSidedScene.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace
{
// The picture of the last frame, without rendering another.
vtkSmartPointer<vtkImageData> LastFrame(vtkRenderWindow* window)
{
  return vtkPhongTest::Snapshot(window, false);
}

// The constants' picture against the uniforms': the same floats, but a compiler may specialize
// code on a constant (Mesa 25 makes a spot's pow(x, 3) products), which rounds its own way:
// at most a level, at a few pixels (Debian 12's llvmpipe: none).
void ExpectSamePicture(vtkPhongTest::Checks& checks, vtkImageData* uniforms,
  vtkImageData* constants, const std::string& what)
{
  const int largest = vtkPhongTest::MaxDifference(uniforms, constants);
  const int pixels = vtkPhongTest::CountDifferentPixels(uniforms, constants, 0);
  const int allowed = static_cast<int>(uniforms->GetNumberOfPoints() / 200);
  checks.Expect(largest <= 1 && pixels <= allowed,
    what + ": " + std::to_string(pixels) + " pixels differ, by up to " + std::to_string(largest) +
      " levels (at most 1 level at " + std::to_string(allowed) + " pixels)");
}

// Render `count` frames of the window.
void RenderFrames(vtkRenderWindow* window, int count)
{
  for (int frame = 0; frame < count; ++frame)
  {
    window->Render();
  }
}

// The scene's sphere, coarse so that the per-vertex bound stays far above the budget and the
// sums per fragment, where the lights are read; under a budget of 1 level, without the depth
// pre-pass (which compiles a program of its own), seen from z.
vtkPhongPolyDataMapper* AddBudgetedSphere(vtkPhongTest::Scene& scene, vtkProperty* material)
{
  vtkActor* actor = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(24), material);
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper());
  mapper->SetErrorBudget(1.0);
  mapper->SetDepthPrePass(vtkPhongPolyDataMapper::DepthPrePassOff);
  scene.LookFromZ(2.2);
  return mapper;
}

bool HasConstants(vtkPhongPolyDataMapper* mapper)
{
  return std::string(mapper->GetLastShaderSignature()).find("UNIFORM_CONSTANTS") !=
    std::string::npos;
}

// Whether the last fragment shader declares each of `names` as a constant.
bool DeclaresConstants(
  vtkPhongPolyDataMapper* mapper, const std::vector<std::string>& names, std::string& missing)
{
  const std::string source = mapper->GetLastFragmentShaderSource();
  missing.clear();
  for (const std::string& name : names)
  {
    if (source.find("const " + name + " = ") == std::string::npos)
    {
      missing += " " + name;
    }
  }
  return missing.empty();
}

// A fresh mapper's first frame (uniforms) against its second: the second has constants and
// the plan's `feature`, declares `names` as constants, and draws the first's picture.
void ExpectConstantsInSecondFrame(vtkPhongTest::Checks& checks, vtkRenderWindow* window,
  vtkPhongPolyDataMapper* mapper, const std::string& feature, const std::vector<std::string>& names,
  const std::string& what)
{
  window->Render();
  auto uniforms = LastFrame(window);
  window->Render();
  const std::string signature = mapper->GetLastShaderSignature();
  std::string missing;
  checks.Expect(HasConstants(mapper) && signature.find(feature) != std::string::npos,
    what + ": constants and " + feature + " in " + signature);
  checks.Expect(DeclaresConstants(mapper, names, missing), what + ": not constants:" + missing);
  ExpectSamePicture(checks, uniforms, LastFrame(window),
    what + ": the picture with constants against the picture with uniforms");
}

// A shell seen inside, with a back material: VTK's uniforms of both sides become constants,
// and the picture stays the uniforms'.
void CheckBackMaterial(vtkPhongTest::Checks& checks)
{
  vtkPhongTest::Scene scene(160, 160);
  vtkActor* actor = vtkPhongTest::BuildShellScene(scene);
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper());
  mapper->SetErrorBudget(1.0);
  mapper->SetDepthPrePass(vtkPhongPolyDataMapper::DepthPrePassOff);
  ExpectConstantsInSecondFrame(checks, scene.Window, mapper, "BACK_MATERIAL",
    { "vec3 diffuseColorUniform", "vec3 diffuseColorUniformBF", "float specularPowerUniformBF",
      "float opacityUniformBF" },
    "a shell with a back material");
}

// Every sum per vertex (a fine sphere filling a large window, one directional light,
// Blinn-Phong at n = 30, 3 levels: a bound of about 2 levels): the fragment
// shader still reads the material, which becomes constants; the lights stay the vertex
// shader's uniforms.
void CheckPerVertexMode(vtkPhongTest::Checks& checks)
{
  vtkPhongTest::Scene scene(640, 640);
  scene.Renderer->AutomaticLightCreationOff();
  const double key[3] = { 1.0, 1.0, 1.5 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  vtkPhongTest::AddLight(scene, key, origin, white, false);
  vtkNew<vtkPhongProperty> material;
  material->SetColor(0.3, 0.6, 0.9);
  material->SetSpecular(0.5);
  material->SetShininess(30.0);
  material->SetLightingModelToBlinnPhong();
  vtkActor* actor = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(256), material);
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper());
  mapper->SetErrorBudget(3.0);
  mapper->SetDepthPrePass(vtkPhongPolyDataMapper::DepthPrePassOff);
  scene.LookFromZ(1.6);
  ExpectConstantsInSecondFrame(checks, scene.Window, mapper, "SUMS_PER_VERTEX",
    { "vec3 phongMaterialDiffuse", "vec3 phongMaterialSpecular", "float opacityUniform" },
    "every sum per vertex");
}

// The composite mapper's blocks: VTK sets each block's colour and opacity as uniforms as it
// draws it, so those stay uniforms; the lights still become constants. Three spheres of
// three block colours, each keeping its colour in the frames with constants.
void CheckBlockColors(vtkPhongTest::Checks& checks)
{
  vtkPhongTest::Scene scene(300, 120);
  auto sphere = vtkPhongTest::MakeSphere(24, 0.45);
  vtkNew<vtkMultiBlockDataSet> blocks;
  vtkNew<vtkPhongCompositePolyDataMapper> mapper;
  mapper->SetInputDataObject(blocks);
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  mapper->SetCompositeDataDisplayAttributes(attributes);
  const double colours[3][3] = { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } };
  for (unsigned int i = 0; i < 3; ++i)
  {
    blocks->SetBlock(i, vtkPhongTest::Moved(sphere, (i - 1.0) * 1.0, 0.0, 0.0));
    attributes->SetBlockColor(blocks->GetBlock(i), colours[i]);
  }
  mapper->SetErrorBudget(1.0);
  mapper->SetDepthPrePass(vtkPhongCompositePolyDataMapper::DepthPrePassOff);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetSpecular(0.3);
  scene.Renderer->AddActor(actor);
  scene.LookFromZ(4.5);
  bool coloured = true;
  std::string seen;
  for (int frame = 0; frame < 3; ++frame)
  {
    scene.Window->Render();
    auto image = LastFrame(scene.Window);
    for (int i = 0; i < 3; ++i)
    {
      // Each sphere's centre: its own channel well above the other two.
      const unsigned char* pixel = vtkPhongTest::PixelAt(image, 150 + (i - 1) * 50, 60);
      const bool own =
        pixel[i] > 100 && pixel[(i + 1) % 3] < pixel[i] / 2 && pixel[(i + 2) % 3] < pixel[i] / 2;
      coloured = coloured && own;
      seen += " (" + std::to_string(pixel[0]) + "," + std::to_string(pixel[1]) + "," +
        std::to_string(pixel[2]) + ")";
    }
  }
  checks.Expect(coloured, "the blocks keep their colours, frame after frame:" + seen);
  checks.Expect(
    std::string(mapper->GetLastShaderSignature()).find("UNIFORM_CONSTANTS") != std::string::npos,
    "the composite mapper's lights as constants: " + std::string(mapper->GetLastShaderSignature()));
}

// Five actors of five colours: a program of each actor's own would cost five compiles (about
// 60 ms each on llvmpipe; 50 actors stalled a frame 3 s), so the material stays uniforms and
// the lights' constants make one program they share.
void CheckManyActors(vtkPhongTest::Checks& checks)
{
  vtkPhongTest::Scene scene(200, 80);
  std::vector<vtkPhongPolyDataMapper*> mappers;
  auto sphere = vtkPhongTest::MakeSphere(24, 0.4);
  for (int i = 0; i < 5; ++i)
  {
    vtkNew<vtkPhongProperty> material;
    material->SetColor(0.2 * i, 0.5, 1.0 - 0.2 * i);
    material->SetSpecular(0.4);
    vtkActor* actor =
      vtkPhongTest::AddActor(scene, vtkPhongTest::Moved(sphere, i - 2.0, 0.0, 0.0), material);
    mappers.push_back(vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper()));
    mappers.back()->SetErrorBudget(1.0);
    mappers.back()->SetDepthPrePass(vtkPhongPolyDataMapper::DepthPrePassOff);
  }
  scene.LookFromZ(9.0);
  RenderFrames(scene.Window, 2);
  bool shared = true;
  for (vtkPhongPolyDataMapper* mapper : mappers)
  {
    const std::string source = mapper->GetLastFragmentShaderSource();
    shared = shared && HasConstants(mapper) &&
      std::string(mapper->GetLastShaderSignature()) == mappers[0]->GetLastShaderSignature() &&
      source.find("const vec3 phongDirectionalLightToLightVC[") != std::string::npos &&
      source.find("uniform vec3 phongMaterialDiffuse;") != std::string::npos;
  }
  checks.Expect(shared,
    "five actors share one program with the lights as constants and the material as "
    "uniforms: " +
      std::string(mappers[0]->GetLastShaderSignature()));
}

// Random finite floats of every exponent, and the awkward ones.
void CheckLiterals(vtkPhongTest::Checks& checks)
{
  std::mt19937 random(2026);
  int wrong = 0;
  std::string example;
  auto check = [&](float value)
  {
    const std::string literal = vtkPhongShaderTemplate::FloatLiteral(value);
    const float back = std::strtof(literal.c_str(), nullptr);
    const bool glslFloat = literal.find_first_of(".e") != std::string::npos;
    if (std::memcmp(&back, &value, sizeof(float)) != 0 || !glslFloat)
    {
      ++wrong;
      example = literal;
    }
  };
  for (float value : { 0.0f, -0.0f, 1.0f, -1.0f, 3.0f, 1.0e-45f, 3.4028235e38f, 0.1f, 1.0e7f })
  {
    check(value);
  }
  for (int i = 0; i < 100000; ++i)
  {
    std::uint32_t bits = random();
    float value;
    std::memcpy(&value, &bits, sizeof(value));
    if (std::isfinite(value))
    {
      check(value);
    }
  }
  checks.Expect(wrong == 0,
    std::to_string(wrong) + " floats do not read back from their literal (e.g. " + example + ")");
}

// The Phong lobe takes N.L and L.V from dot products the vertex shader makes with the
// directions as uniforms (INTERPOLATED_DOTS), while the fragment shader has them as constants:
// a fresh mapper's first frame (uniforms) against its second (constants).
void CheckPhongLobe(vtkPhongTest::Checks& checks)
{
  vtkPhongTest::Scene scene(160, 160);
  scene.Renderer->AutomaticLightCreationOff();
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double key[3] = { 1.0, 1.0, 1.5 };
  const double fill[3] = { -1.5, 0.5, 1.0 };
  const double warm[3] = { 1.0, 0.8, 0.6 };
  const double cool[3] = { 0.5, 0.7, 1.0 };
  vtkLight* keyLight = vtkPhongTest::AddLight(scene, key, origin, warm, false);
  vtkPhongTest::AddLight(scene, fill, origin, cool, false);
  vtkNew<vtkPhongProperty> material;
  material->SetSpecular(0.6);
  material->SetShininess(40.0);
  material->SetLightingModelToPhong();
  vtkPhongPolyDataMapper* mapper = AddBudgetedSphere(scene, material);
  ExpectConstantsInSecondFrame(checks, scene.Window, mapper, "INTERPOLATED_DOTS",
    { "vec3 phongDirectionalLightDiffuse[2]" }, "the Phong lobe, dots from the vertices");

  // Shininess 40.5 is not squared: the constants add their own charge, 0.01 level and more
  // (a light's new colour: a frame with the uniforms, then one with the constants); a budget
  // below it keeps the uniforms.
  material->SetShininess(40.5);
  scene.Window->Render();
  keyLight->SetIntensity(0.9);
  scene.Window->Render();
  const double uniformsBound = mapper->GetErrorBound();
  const bool uniformsFirst = !HasConstants(mapper);
  for (int frame = 0; frame < 4 && !HasConstants(mapper); ++frame) // (two repeats now)
  {
    scene.Window->Render();
  }
  const double charged = mapper->GetErrorBound();
  checks.Expect(
    uniformsFirst && HasConstants(mapper) && charged >= uniformsBound + 0.01 && charged < 0.05,
    "the constants' charge: the bound went from " + std::to_string(uniformsBound) + " to " +
      std::to_string(charged) + " levels");
  mapper->SetErrorBudget(0.005);
  bool kept = false;
  for (int frame = 0; frame < 4; ++frame)
  {
    scene.Window->Render();
    kept = kept || HasConstants(mapper);
  }
  checks.Expect(!kept, "a budget below the constants' charge keeps the uniforms");
}
}

int TestPhongUniformConstants(int, char*[])
{
  vtkPhongTest::Checks checks;
  CheckLiterals(checks);
  CheckPhongLobe(checks);
  CheckBackMaterial(checks);
  CheckPerVertexMode(checks);
  CheckBlockColors(checks);
  CheckManyActors(checks);

  vtkPhongTest::Scene scene(160, 160);
  scene.Renderer->AutomaticLightCreationOff();
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double warm[3] = { 1.0, 0.8, 0.6 };
  const double cool[3] = { 0.5, 0.7, 1.0 };
  const double green[3] = { 0.4, 1.0, 0.5 };
  const double key[3] = { 1.0, 1.0, 1.5 };
  const double fill[3] = { -1.5, 0.5, 1.0 };
  vtkLight* keyLight = vtkPhongTest::AddLight(scene, key, origin, warm, false);
  vtkPhongTest::AddLight(scene, fill, origin, cool, false);
  const double pointAt[3] = { 0.3, -0.6, 0.9 };
  vtkLight* point = vtkPhongTest::AddLight(scene, pointAt, origin, green, true);
  point->SetConeAngle(180.0);
  point->SetAttenuationValues(1.0, 0.3, 0.2);
  const double spotAt[3] = { -0.4, -0.5, 1.2 };
  vtkLight* spot = vtkPhongTest::AddLight(scene, spotAt, origin, warm, true);
  spot->SetConeAngle(25.0);
  spot->SetExponent(3.0);
  spot->SetAttenuationValues(1.0, 0.1, 0.0);

  vtkNew<vtkPhongProperty> material;
  material->SetColor(0.8, 0.7, 0.6);
  material->SetAmbient(0.1);
  material->SetSpecular(0.6);
  material->SetShininess(40.0);
  material->SetLightingModelToBlinnPhong();
  material->SoftSpotEdgeOn();
  material->SetSpotEdgeWidth(5.0);
  vtkPhongPolyDataMapper* mapper = AddBudgetedSphere(scene, material);

  scene.Window->Render();
  checks.Expect(!HasConstants(mapper), "the first frame reads the uniforms");
  auto withUniforms = LastFrame(scene.Window);
  const int compiles = mapper->GetShaderCompileCount();
  scene.Window->Render();
  checks.Expect(HasConstants(mapper),
    "the second frame of a still scene takes the constants: " +
      std::string(mapper->GetLastShaderSignature()));
  checks.Expect(mapper->GetShaderCompileCount() == compiles + 1,
    "one program for them: " + std::to_string(compiles) + " then " +
      std::to_string(mapper->GetShaderCompileCount()));
  ExpectSamePicture(
    checks, withUniforms, LastFrame(scene.Window), "the constants' picture against the uniforms'");
  RenderFrames(scene.Window, 3);
  checks.Expect(HasConstants(mapper) && mapper->GetShaderCompileCount() == compiles + 1,
    "still frames keep them and build nothing");
  std::string missing;
  checks.Expect(
    DeclaresConstants(mapper,
      { "vec3 phongDirectionalLightToLightVC[2]", "vec3 phongSpotLightAxisVC[1]",
        "float phongSpotLightCosInner[1]", "vec3 phongAmbientTerm", "vec3 phongMaterialDiffuse",
        "vec3 phongMaterialSpecular", "float specularPowerUniform", "float opacityUniform" },
      missing),
    "the light and material values as constants; not:" + missing);

  // A material colour change shows and reads the uniforms until it holds.
  auto still = LastFrame(scene.Window);
  material->SetDiffuseColor(0.2, 0.3, 1.0);
  scene.Window->Render();
  checks.Expect(
    vtkPhongTest::MaxDifference(still, LastFrame(scene.Window)) > 20 && !HasConstants(mapper),
    "a new material colour changes the picture and reads the uniforms");
  material->SetDiffuseColor(0.8, 0.7, 0.6);
  scene.Window->Render();

  // Scene lights turn with the camera: each frame brings other values.
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  for (int frame = 0; frame < 3; ++frame)
  {
    camera->Azimuth(5.0);
    scene.Window->Render();
    checks.Expect(!HasConstants(mapper), "turning scene lights read the uniforms");
  }
  // The second set of values is taken after two repeats, the third after four, the fourth
  // after eight (the next would wait 16); 4 x 16 frames with the fourth halve that, 4 x 8 more
  // halve it again, and the fifth set waits four.
  for (int required : { 2, 4, 8, 4 })
  {
    for (int repeat = 1; repeat < required; ++repeat)
    {
      scene.Window->Render();
      checks.Expect(!HasConstants(mapper),
        "repeat " + std::to_string(repeat) + " of " + std::to_string(required) + " reads uniforms");
    }
    auto uniforms = LastFrame(scene.Window);
    scene.Window->Render();
    checks.Expect(
      HasConstants(mapper), "after " + std::to_string(required) + " repeats, the constants");
    ExpectSamePicture(checks, uniforms, LastFrame(scene.Window),
      "after " + std::to_string(required) + " repeats, the same view");
    RenderFrames(scene.Window, required == 8 ? 96 : 0);
    camera->Azimuth(5.0);
    scene.Window->Render();
  }

  // A colour change shows (the constants are not stale) and goes back to the uniforms.
  auto before = LastFrame(scene.Window);
  keyLight->SetColor(0.2, 0.2, 1.0);
  scene.Window->Render();
  checks.Expect(vtkPhongTest::MaxDifference(before, LastFrame(scene.Window)) > 20,
    "a new light colour changes the picture");
  checks.Expect(!HasConstants(mapper), "a changed light reads the uniforms");

  // Camera lights keep their values in view coordinates, however the camera turns (a mapper
  // of its own: the one above now waits eight repeats).
  vtkPhongTest::Scene cameraScene(160, 160);
  cameraScene.Renderer->AutomaticLightCreationOff();
  vtkPhongTest::AddLight(cameraScene, key, origin, warm, false, VTK_LIGHT_TYPE_CAMERA_LIGHT);
  vtkPhongTest::AddLight(cameraScene, fill, origin, cool, false, VTK_LIGHT_TYPE_CAMERA_LIGHT);
  vtkNew<vtkLight> headlight;
  headlight->SetLightTypeToHeadlight();
  headlight->SetIntensity(0.3);
  cameraScene.Renderer->AddLight(headlight);
  vtkPhongPolyDataMapper* cameraMapper = AddBudgetedSphere(cameraScene, material);
  vtkCamera* turning = cameraScene.Renderer->GetActiveCamera();
  cameraScene.Window->Render();
  bool kept = true;
  for (int frame = 0; frame < 10; ++frame)
  {
    turning->Azimuth(7.0);
    turning->Elevation(3.0);
    turning->OrthogonalizeViewUp();
    turning->Dolly(frame % 2 ? 1.1 : 1 / 1.1);
    cameraScene.Window->Render();
    kept = kept && HasConstants(cameraMapper);
  }
  checks.Expect(kept, "camera lights and the headlight keep the constants as the camera turns");
  checks.Expect(cameraMapper->GetShaderCompileCount() == 2,
    "turning with camera lights builds two programs: " +
      std::to_string(cameraMapper->GetShaderCompileCount()));

  // A positional camera light placed from its own coordinates lights as the same light placed
  // in world coordinates through the camera's light transform.
  cameraScene.Renderer->RemoveAllLights();
  const double spotInCamera[3] = { 0.3, 0.4, 1.2 };
  vtkLight* cameraSpot = vtkPhongTest::AddLight(
    cameraScene, spotInCamera, origin, warm, true, VTK_LIGHT_TYPE_CAMERA_LIGHT);
  cameraSpot->SetConeAngle(30.0);
  cameraSpot->SetAttenuationValues(1.0, 0.5, 0.0);
  cameraScene.Window->Render();
  auto fromCamera = LastFrame(cameraScene.Window);
  vtkMatrix4x4* cameraToWorld = turning->GetCameraLightTransformMatrix();
  double positionWC[4] = { spotInCamera[0], spotInCamera[1], spotInCamera[2], 1.0 };
  double focalWC[4] = { 0.0, 0.0, 0.0, 1.0 };
  cameraToWorld->MultiplyPoint(positionWC, positionWC);
  cameraToWorld->MultiplyPoint(focalWC, focalWC);
  cameraScene.Renderer->RemoveAllLights();
  vtkLight* worldSpot = vtkPhongTest::AddLight(cameraScene, positionWC, focalWC, warm, true);
  worldSpot->SetConeAngle(30.0);
  worldSpot->SetAttenuationValues(1.0, 0.5, 0.0);
  cameraScene.Window->Render();
  const int placed = vtkPhongTest::MaxDifference(fromCamera, LastFrame(cameraScene.Window));
  checks.Expect(placed <= 1,
    "a camera spot lights as its world placement (" + std::to_string(placed) + " levels)");

  // The exact mode never takes them.
  mapper->SetErrorBudget(0.0);
  bool exact = true;
  for (int frame = 0; frame < 4; ++frame)
  {
    scene.Window->Render();
    exact = exact && !HasConstants(mapper);
  }
  checks.Expect(exact, "the exact mode reads the uniforms");
  checks.Expect(vtkPhongTest::NoGLErrors(scene.Window, "the light constants"), "no GL error");
  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
