// Drop-in: with VTK's defaults (light ambient colour black, renderer ambient
// white) and the Phong lobe, vtkPhongPolyDataMapper draws what the stock
// vtkOpenGLPolyDataMapper draws, for VTK's default headlight, for sets of
// directional scene lights and for positional and spot lights. The one
// difference, a lone headlight with a highlight (stock VTK switches to a
// Blinn lobe with the viewer at infinity for it), is in docs/compatibility.md.

#include "vtkPhongTestUtilities.h"

#include "vtkOpenGLPolyDataMapper.h"

#include <functional>

namespace
{
vtkSmartPointer<vtkImageData> RenderWith(
  vtkPolyDataMapper* mapper, const std::function<void(vtkRenderer*, vtkProperty*)>& setUp)
{
  vtkPhongTest::Scene scene;
  mapper->SetInputData(vtkPhongTest::MakeSphere(64));
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  scene.Renderer->AddActor(actor);
  setUp(scene.Renderer, actor->GetProperty());
  scene.LookFromZ(2.5);
  scene.Window->Render();
  return vtkPhongTest::Snapshot(scene.Window);
}

void AddDirectional(
  vtkRenderer* renderer, double x, double y, double z, double r, double g, double b)
{
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(x, y, z);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->SetColor(r, g, b);
  renderer->AddLight(light);
}
}

int TestPhongStockCompatibility(int argc, char* argv[])
{
  const std::pair<const char*, std::function<void(vtkRenderer*, vtkProperty*)>> scenes[] = {
    { "VTK defaults, headlight", [](vtkRenderer*, vtkProperty*) {} },
    { "two directional scene lights with specular",
      [](vtkRenderer* renderer, vtkProperty* property)
      {
        property->SetColor(0.9, 0.4, 0.2);
        property->SetAmbient(0.1);
        property->SetSpecular(0.5);
        property->SetSpecularPower(30.0);
        AddDirectional(renderer, 1, 1, 1, 1.0, 0.8, 0.6);
        AddDirectional(renderer, -1, 0.5, 0.3, 0.3, 0.5, 1.0);
      } },
    { "point, spot and camera lights with specular",
      [](vtkRenderer* renderer, vtkProperty* property)
      {
        property->SetColor(0.9, 0.4, 0.2);
        property->SetAmbient(0.1);
        property->SetSpecular(0.5);
        property->SetSpecularPower(30.0);
        vtkNew<vtkLight> point;
        point->SetPosition(1, 1, 1.5);
        point->SetPositional(true);
        point->SetConeAngle(120);
        point->SetAttenuationValues(1, 0.2, 0.1);
        renderer->AddLight(point);
        vtkNew<vtkLight> spot;
        spot->SetPosition(-1, 0.5, 2);
        spot->SetPositional(true);
        spot->SetConeAngle(15);
        spot->SetExponent(3);
        spot->SetColor(0.4, 0.6, 1.0);
        renderer->AddLight(spot);
        vtkNew<vtkLight> camera;
        camera->SetLightTypeToCameraLight();
        camera->SetPosition(0.5, 0.5, 1);
        camera->SetIntensity(0.5);
        renderer->AddLight(camera);
      } },
  };

  vtkPhongTest::Checks checks;
  for (const auto& scene : scenes)
  {
    vtkNew<vtkOpenGLPolyDataMapper> stock;
    vtkNew<vtkPhongPolyDataMapper> phong;
    auto expected = RenderWith(stock, scene.second);
    auto got = RenderWith(phong, scene.second);
    const int difference = vtkPhongTest::MaxDifference(expected, got);
    // Same arithmetic in a different order: one 8-bit level at most.
    checks.Expect(difference <= 1,
      std::string(scene.first) + ": max difference to stock VTK " + std::to_string(difference));
  }

  // The regression picture: the last scene through the module's mapper.
  vtkPhongTest::Scene scene;
  vtkNew<vtkActor> actor;
  vtkNew<vtkPhongPolyDataMapper> mapper;
  mapper->SetInputData(vtkPhongTest::MakeSphere(64));
  actor->SetMapper(mapper);
  scene.Renderer->AddActor(actor);
  scenes[2].second(scene.Renderer, actor->GetProperty());
  scene.LookFromZ(2.5);
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
