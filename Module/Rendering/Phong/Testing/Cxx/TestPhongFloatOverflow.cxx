// Values finite in double but infinite in float (1e308): light intensities and colours,
// material colours and emission, the renderer's ambient light, light positions and
// attenuation (VTK itself clamps the coefficients, specular power and spot exponent). Before they
// were bounded, an infinity met a zero in the shader and the picture held NaN with no message. Each
// case renders a lit sphere into a float target: every pixel must be finite, and the mapper must
// say what it clamped.

#include "vtkPhongReferenceTesting.h"

#include <cmath>
#include <functional>

namespace
{
constexpr double Huge = 1.0e308;

struct OverflowCase
{
  const char* Name;
  const char* Message; ///< a piece of the expected report
  std::function<void(vtkRenderer*, vtkLight*, vtkPhongProperty*, vtkActor*)> Apply;
};

// Pixels that are NaN or infinite in any channel.
vtkIdType CountNonFinite(vtkImageData* image)
{
  vtkDataArray* rgba = image->GetPointData()->GetScalars();
  vtkIdType count = 0;
  for (vtkIdType p = 0; p < rgba->GetNumberOfTuples(); ++p)
  {
    double value[4];
    rgba->GetTuple(p, value);
    count += (std::isfinite(value[0]) && std::isfinite(value[1]) && std::isfinite(value[2]) &&
               std::isfinite(value[3]))
      ? 0
      : 1;
  }
  return count;
}

bool RunCase(const OverflowCase& overflow, vtkPhongTest::Checks& checks)
{
  vtkPhongTest::Scene scene(120, 120);
  scene.Renderer->AutomaticLightCreationOff();
  vtkNew<vtkPhongProperty> material;
  material->SetSpecular(0.5);
  material->SetShininess(30.0);
  vtkActor* actor = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(32), material);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(1.0, 1.0, 2.0);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->PositionalOn();
  light->SetConeAngle(60.0);
  scene.Renderer->AddLight(light);
  scene.LookFromZ(3.0);
  overflow.Apply(scene.Renderer, light, material, actor);

  vtkPhongTest::ErrorCollector messages;
  messages.Observe(actor->GetMapper());
  vtkNew<vtkPhongFloatRenderPass> pass;
  vtkSmartPointer<vtkImageData> image = vtkPhongTest::RenderFloat(scene, pass);
  const vtkIdType nonFinite = CountNonFinite(image);
  const std::string name = overflow.Name;
  checks.Expect(nonFinite == 0, name + ": " + std::to_string(nonFinite) + " NaN or Inf pixels");
  checks.Expect(messages.Contains(overflow.Message),
    name + ": reported ('" + overflow.Message + "' in " + std::to_string(messages.Messages.size()) +
      " messages)");
  return nonFinite == 0;
}
}

int TestPhongFloatOverflow(int, char*[])
{
  const std::vector<OverflowCase> cases = {
    { "light intensity", "diffuse colour times intensity",
      [](vtkRenderer*, vtkLight* light, vtkPhongProperty*, vtkActor*)
      { light->SetIntensity(Huge); } },
    { "light colour", "diffuse colour times intensity",
      [](vtkRenderer*, vtkLight* light, vtkPhongProperty*, vtkActor*)
      { light->SetDiffuseColor(Huge, 1.0, 1.0); } },
    { "light position", "position component",
      [](vtkRenderer*, vtkLight* light, vtkPhongProperty*, vtkActor*)
      { light->SetPosition(Huge, 0.0, 0.0); } },
    { "attenuation", "attenuation coefficient",
      [](vtkRenderer*, vtkLight* light, vtkPhongProperty*, vtkActor*)
      { light->SetAttenuationValues(1.0, 0.0, Huge); } },
    { "renderer ambient", "ambient light component",
      [](vtkRenderer* ren, vtkLight*, vtkPhongProperty* material, vtkActor*)
      {
        ren->SetAmbient(Huge, 0.0, 0.0);
        material->SetAmbient(0.5);
      } },
    { "material colour", "specular colour component",
      [](vtkRenderer*, vtkLight*, vtkPhongProperty* material, vtkActor*)
      { material->SetSpecularColor(Huge, 0.0, 0.0); } },
    { "material diffuse colour", "diffuse colour component",
      [](vtkRenderer*, vtkLight*, vtkPhongProperty* material, vtkActor*)
      { material->SetDiffuseColor(0.0, Huge, 0.0); } },
    { "material ambient colour", "ambient colour component",
      [](vtkRenderer*, vtkLight*, vtkPhongProperty* material, vtkActor*)
      {
        material->SetAmbient(0.5);
        material->SetAmbientColor(Huge, 1.0, 1.0);
      } },
    { "emission", "emission component",
      [](vtkRenderer*, vtkLight*, vtkPhongProperty* material, vtkActor*)
      { material->SetEmission(Huge, 0.0, 0.0); } },
  };
  vtkPhongTest::Checks checks;
  for (const OverflowCase& overflow : cases)
  {
    RunCase(overflow, checks);
  }
  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
