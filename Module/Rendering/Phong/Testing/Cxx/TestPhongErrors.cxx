// Bad input gets a clear error (or a documented clamp), the render goes on,
// and nothing is NaN:
// - vtkPhongProperty refuses NaN shininess and emission, clamps negative ones;
// - negative or NaN light intensities and colours, NaN material colours and a
//   debug light index with no light are reported once, by the mapper;
// - a shader that fails to compile reports the source and the compiler log,
//   and the primitive falls back to VTK's own lighting; broken shader code of the
//   user's falls back to VTK's shaders (stock VTK 9.1 crashes).

#include "vtkPhongTestUtilities.h"

#include "vtkLogger.h"
#include "vtkOutputWindow.h"
#include "vtkShaderProperty.h"
#include "vtkStringOutputWindow.h"

#include <limits>

namespace
{
// While it lives, what VTK prints (a compiler's log) goes to a string and VTK's logger is
// quiet: the harness fails a test whose output shows an error.
class CapturedOutput
{
public:
  CapturedOutput()
    : Previous(vtkOutputWindow::GetInstance())
    , Verbosity(vtkLogger::GetCurrentVerbosityCutoff())
  {
    vtkOutputWindow::SetInstance(this->Captured);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~CapturedOutput()
  {
    vtkLogger::SetStderrVerbosity(this->Verbosity);
    vtkOutputWindow::SetInstance(this->Previous);
  }
  CapturedOutput(const CapturedOutput&) = delete;
  void operator=(const CapturedOutput&) = delete;
  std::string Text() const { return this->Captured->GetOutput(); }

private:
  vtkNew<vtkStringOutputWindow> Captured;
  vtkSmartPointer<vtkOutputWindow> Previous;
  vtkLogger::Verbosity Verbosity;
};

// The actor's own vertex shader code that does not compile (stock VTK 9.1 dereferences the
// null program and crashes): reported, and the primitive drawn with VTK's shaders, frame after
// frame, the depth pre-pass included.
void CheckBrokenShaderCode(vtkPhongTest::Checks& checks)
{
  vtkPhongTest::Scene scene(64, 64);
  vtkNew<vtkPhongProperty> material;
  vtkActor* actor = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(32), material);
  actor->GetShaderProperty()->SetVertexShaderCode(
    "//VTK::System::Dec\nin vec4 vertexMC;\nvoid main() { gl_Position = vertexMC + typo; }\n");
  vtkPhongTest::ErrorCollector messages;
  messages.Observe(actor->GetMapper());
  scene.LookFromZ(2.5);
  {
    CapturedOutput output;
    for (int frame = 0; frame < 3; ++frame)
    {
      scene.Window->Render();
    }
  }
  checks.Expect(messages.Contains("fail to compile with VTK's own lighting too"),
    "broken shader code of the user's is reported");
  checks.Expect(vtkPhongTest::PixelAt(vtkPhongTest::Snapshot(scene.Window), 32, 32)[0] > 0,
    "the primitive is still drawn, with VTK's shaders");
}
}

int TestPhongErrors(int, char*[])
{
  vtkPhongTest::Checks checks;
  const double nan = std::numeric_limits<double>::quiet_NaN();

  { // vtkPhongProperty's setters
    vtkNew<vtkPhongProperty> material;
    vtkPhongTest::ErrorCollector messages;
    messages.Observe(material);
    material->SetShininess(50.0);
    material->SetShininess(nan);
    checks.Expect(material->GetShininess() == 50.0 && messages.Contains("NaN refused"),
      "NaN shininess is refused with an error");
    material->SetShininess(-3.0);
    checks.Expect(material->GetShininess() == 0.0 && messages.Contains("clamped to 0"),
      "negative shininess is clamped to 0 with a warning");
    material->SetShininess(5.0e6);
    checks.Expect(material->GetShininess() == 1.0e6, "shininess is clamped to 1e6");
    checks.Expect(
      material->GetSpecularPower() == 128.0, "SpecularPower follows, within VTK's range");
    material->SetSpecularPower(64.0);
    checks.Expect(material->GetShininess() == 64.0, "SetSpecularPower sets the shininess");
    material->SetEmission(nan, 0.0, 0.0);
    checks.Expect(material->GetEmission()[0] == 0.0 && messages.Contains("must be finite"),
      "NaN emission is refused");
    material->SetEmission(-1.0, 0.5, 0.0);
    checks.Expect(material->GetEmission()[0] == 0.0 && material->GetEmission()[1] == 0.5,
      "negative emission is clamped to 0");
  }

  vtkPhongTest::Scene scene(64, 64);
  scene.Renderer->AutomaticLightCreationOff();
  const double key[3] = { 0.5, 0.5, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  vtkLight* light = vtkPhongTest::AddLight(scene, key, origin, white, false);
  vtkNew<vtkPhongProperty> material;
  material->SetAmbient(0.2);
  material->SetSpecular(0.5);
  vtkActor* actor = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(32), material);
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper());
  vtkPhongTest::ErrorCollector messages;
  messages.Observe(mapper);
  scene.LookFromZ(2.5);

  auto renderCentre = [&]()
  {
    scene.Window->Render();
    auto image = vtkPhongTest::Snapshot(scene.Window);
    const unsigned char* pixel = vtkPhongTest::PixelAt(image, 32, 32);
    return std::vector<int>(pixel, pixel + 3);
  };
  renderCentre();
  checks.Expect(messages.Messages.empty(), "a good scene reports nothing");

  light->SetIntensity(-2.0);
  renderCentre();
  renderCentre();
  checks.Expect(messages.Messages.size() == 1 && messages.Contains("intensity -2"),
    "a negative intensity is reported once (" + std::to_string(messages.Messages.size()) + ")");
  light->SetIntensity(1.0);

  light->SetSpecularColor(nan, 0.0, 0.0);
  renderCentre();
  checks.Expect(
    messages.Contains("specular colour component nan"), "a NaN light colour is reported");
  light->SetSpecularColor(1.0, 1.0, 1.0);

  material->SetDiffuseColor(nan, 0.5, 0.5);
  const std::vector<int> pixel = renderCentre();
  checks.Expect(
    messages.Contains("diffuse colour component nan"), "a NaN material colour is reported");
  checks.Expect(pixel[1] > 0, "the render goes on with the colour treated as 0");
  material->SetDiffuseColor(0.5, 0.5, 0.5);

  { // vtkLight stores a NaN cone angle as given; as in VTK, a positional light whose cone
    // is not below 90 degrees is a point light, so NaN lights as a point light would.
    light->PositionalOn();
    light->SetConeAngle(180.0);
    const std::vector<int> point = renderCentre();
    light->SetConeAngle(nan);
    checks.Expect(renderCentre() == point, "a NaN cone angle lights as a point light");
    light->SetConeAngle(-std::numeric_limits<double>::infinity());
    renderCentre();
    checks.Expect(messages.Contains("cone angle -inf"), "an infinite cone angle is reported");
    light->SetConeAngle(30.0);
    light->PositionalOff();
  }

  mapper->SetDebugViewToSingleLight();
  mapper->SetDebugLightIndex(5);
  renderCentre();
  checks.Expect(
    messages.Contains("DebugLightIndex 5 names no light"), "a bad light index is reported");
  mapper->SetDebugViewToFinal();
  checks.Expect(vtkPhongTest::NoGLErrors(scene.Window, "bad parameters"), "no GL error");

  { // A user replacement that breaks only the lighting variant: it must be
    // reported with source and log, and the primitive drawn by VTK's code.
    std::string log;
    std::vector<int> fallback;
    {
      CapturedOutput output;
      actor->GetShaderProperty()->AddFragmentShaderReplacement(
        "phongSumLights(vertexVC", false, "phongSumLightsTypo(vertexVC", false);
      fallback = renderCentre();
      log = output.Text();
    }
    checks.Expect(messages.Contains("failed to compile"), "the mapper reports the failed variant");
    checks.Expect(log.find("phongSumLightsTypo") != std::string::npos &&
        log.find("#version") != std::string::npos,
      "the numbered source is printed");
    checks.Expect(log.find("rror") != std::string::npos, "the compiler log is printed");
    checks.Expect(fallback[0] > 0, "the primitive is still drawn (VTK's lighting)");
    checks.Expect(
      std::string(mapper->GetLastShaderSignature()).empty(), "the fallback is VTK's own shader");
  }
  CheckBrokenShaderCode(checks);
  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
