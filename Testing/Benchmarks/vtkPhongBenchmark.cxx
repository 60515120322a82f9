// vtkPhong's benchmark: prints numbers, asserts nothing.
//
//   vtkPhongBenchmark [MESH.off] [--quick]
//
// 1. Shader variants and build time: how many variants the default scene
//    (MESH, or a sphere, on a floor under three lights of different kinds)
//    builds, the time of one variant's build (source generation, compile,
//    link: vtkPhongPolyDataMapper::GetLastShaderBuildTime) and the first-frame
//    latency, for vtkPhongPolyDataMapper and the stock mapper.
// 2. Frame time against the stock vtkOpenGLPolyDataMapper on a sphere at
//    1280x1024, with 1 light (VTK's headlight), 8 directional lights and 8
//    mixed lights (4 directional, 2 point, 2 spot), and the unlit floor (same
//    geometry, lighting off). The mappers take turns in one window, frame
//    batch after frame batch, so both see the same machine state; the table
//    gives medians over the batches and the ratio ours / stock.
//
// On llvmpipe fragment work runs on the CPU, so shader cost shows in these
// times. --quick shrinks everything so ctest can check the program runs.

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPhongOFFReader.h"
#include "vtkPhongPolyDataMapper.h"
#include "vtkPhongProperty.h"
#include "vtkPhongSharedDisplay.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <set>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

vtkSmartPointer<vtkPolyData> Sphere(int resolution)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution);
  sphere->Update();
  return sphere->GetOutput();
}

void AddLight(vtkRenderer* renderer, const double position[3], const double focalPoint[3],
  bool positional, double cone, const double color[3])
{
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(position[0], position[1], position[2]);
  light->SetFocalPoint(focalPoint[0], focalPoint[1], focalPoint[2]);
  light->SetPositional(positional);
  light->SetConeAngle(cone);
  light->SetColor(color[0], color[1], color[2]);
  light->SetIntensity(0.3);
  if (positional)
  {
    light->SetAttenuationValues(1.0, 0.1, 0.05);
  }
  renderer->AddLight(light);
}

// The light sets of the frame-time table.
void SetLights(vtkRenderer* renderer, const std::string& set)
{
  renderer->RemoveAllLights();
  renderer->AutomaticLightCreationOff();
  const double origin[3] = { 0.0, 0.0, 0.0 };
  if (set == "1 headlight")
  {
    vtkNew<vtkLight> headlight;
    headlight->SetLightTypeToHeadlight();
    renderer->AddLight(headlight);
    return;
  }
  for (int i = 0; i < 8; ++i)
  {
    const double angle = 6.283185307 * i / 8.0;
    const double position[3] = { 1.5 * std::cos(angle), 1.5 * std::sin(angle), 1.5 };
    const double color[3] = { 0.6 + 0.4 * std::cos(angle), 0.8, 0.6 + 0.4 * std::sin(angle) };
    const bool positional = set == "8 mixed" && i >= 4;
    const double cone = (set == "8 mixed" && i >= 6) ? 35.0 : 180.0;
    AddLight(renderer, position, origin, positional, positional ? cone : 30.0, color);
  }
}

struct FrameTimer
{
  vtkRenderWindow* Window;
  int FramesPerBatch;

  // Seconds per frame over one batch, the GPU finished after each frame.
  double Batch() const
  {
    const auto start = Clock::now();
    for (int i = 0; i < this->FramesPerBatch; ++i)
    {
      this->Window->Render();
      this->Window->WaitForCompletion();
    }
    return Seconds(start) / this->FramesPerBatch;
  }
};

void ShaderSection(const char* meshFile, bool quick)
{
  std::printf(
    "\n== Shader variants and build time (default scene: %s) ==\n", meshFile ? meshFile : "sphere");
  vtkSmartPointer<vtkPolyData> mesh = Sphere(quick ? 32 : 128);
  if (meshFile)
  {
    vtkNew<vtkPhongOFFReader> reader;
    reader->SetFileName(meshFile);
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputConnection(reader->GetOutputPort());
    normals->SplittingOff();
    normals->Update();
    mesh = normals->GetOutput();
  }
  std::printf("%-34s %12s %12s\n", "", "vtkPhong", "stock");
  double firstFrame[2], steadyFrame[2];
  std::set<std::string> signatures;
  int compiles = 0;
  double buildTime = 0.0;
  double newVariantFrame = 0.0;
  for (int stock = 0; stock < 2; ++stock)
  {
    vtkNew<vtkRenderer> renderer;
    double bounds[6];
    mesh->GetBounds(bounds);
    const double size = std::max(bounds[1] - bounds[0], bounds[3] - bounds[2]);
    const double origin[3] = { 0.0, 0.0, 0.0 };
    const double white[3] = { 1.0, 1.0, 1.0 };
    const double above[3] = { 0.0, 3.0 * size, 3.0 * size };
    const double side[3] = { 2.0 * size, 0.5 * size, size };
    const double back[3] = { 0.0, 2.0 * size, -2.0 * size };
    renderer->AutomaticLightCreationOff();
    AddLight(renderer, above, origin, false, 30.0, white);
    AddLight(renderer, side, origin, true, 180.0, white);
    AddLight(renderer, back, origin, true, 25.0, white);

    std::vector<vtkSmartPointer<vtkPolyDataMapper>> mappers;
    vtkNew<vtkPlaneSource> floor;
    floor->SetOrigin(-size, bounds[2], -size);
    floor->SetPoint1(size, bounds[2], -size);
    floor->SetPoint2(-size, bounds[2], size);
    floor->Update();
    for (vtkPolyData* data : { mesh.GetPointer(), floor->GetOutput() })
    {
      vtkSmartPointer<vtkPolyDataMapper> mapper;
      if (stock)
      {
        mapper = vtkSmartPointer<vtkOpenGLPolyDataMapper>::New();
      }
      else
      {
        mapper = vtkSmartPointer<vtkPhongPolyDataMapper>::New();
      }
      mapper->SetInputData(data);
      vtkNew<vtkPhongProperty> material;
      material->SetSpecular(0.4);
      material->SetAmbient(0.1);
      material->SetLightingModelToBlinnPhong();
      material->SetShininess(80.0);
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->SetProperty(material);
      renderer->AddActor(actor);
      mappers.push_back(mapper);
    }
    vtkNew<vtkRenderWindow> window;
    vtkPhongTest::UseSharedDisplay(window);
    window->SetOffScreenRendering(1);
    window->SetSize(quick ? 320 : 1280, quick ? 256 : 1024);
    window->AddRenderer(renderer);
    renderer->ResetCamera();
    auto start = Clock::now();
    window->Render();
    window->WaitForCompletion();
    firstFrame[stock] = Seconds(start);
    steadyFrame[stock] = Median({ FrameTimer{ window, 3 }.Batch(), FrameTimer{ window, 3 }.Batch(),
      FrameTimer{ window, 3 }.Batch() });
    if (!stock)
    {
      for (const auto& mapper : mappers)
      {
        auto* phong = vtkPhongPolyDataMapper::SafeDownCast(mapper);
        signatures.insert(phong->GetLastShaderSignature());
        compiles += phong->GetShaderCompileCount();
      }
      // A structural change in a warm window: the next frame builds, compiles
      // and (llvmpipe JIT-compiles shaders at draw time) first runs one variant.
      auto* material =
        vtkPhongProperty::SafeDownCast(renderer->GetActors()->GetLastActor()->GetProperty());
      material->SetLightingModelToPhong();
      start = Clock::now();
      window->Render();
      window->WaitForCompletion();
      newVariantFrame = Seconds(start) - steadyFrame[stock];
      buildTime = vtkPhongPolyDataMapper::SafeDownCast(mappers.back())->GetLastShaderBuildTime();
    }
  }
  std::printf("%-34s %12zu %12s\n", "distinct lighting variants", signatures.size(), "-");
  std::printf("%-34s %12d %12s\n", "programs requested (mesh + floor)", compiles, "-");
  std::printf("%-34s %10.1f ms %12s\n", "new variant: GLSL compile and link", 1e3 * buildTime, "-");
  std::printf(
    "%-34s %10.1f ms %12s\n", "new variant: added frame latency", 1e3 * newVariantFrame, "-");
  std::printf("%-34s %10.1f ms %9.1f ms\n", "first frame (build + draw)", 1e3 * firstFrame[0],
    1e3 * firstFrame[1]);
  std::printf(
    "%-34s %10.1f ms %9.1f ms\n", "steady frame", 1e3 * steadyFrame[0], 1e3 * steadyFrame[1]);
}

void FrameSection(bool quick)
{
  const int resolution = quick ? 32 : 256;
  const int width = quick ? 320 : 1280, height = quick ? 256 : 1024;
  const int batches = quick ? 3 : 9, frames = quick ? 2 : 8;
  auto sphere = Sphere(resolution);
  std::printf("\n== Frame time against the stock mapper (sphere, %lld triangles, %dx%d) ==\n",
    static_cast<long long>(sphere->GetNumberOfPolys()), width, height);
  std::printf(
    "%-18s %12s %12s %12s %10s\n", "lights", "unlit floor", "stock", "vtkPhong", "ours/stock");

  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  vtkPhongTest::UseSharedDisplay(window);
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);

  // Three actors on the same sphere: stock lit, ours lit, stock unlit.
  vtkNew<vtkOpenGLPolyDataMapper> stockMapper;
  vtkNew<vtkPhongPolyDataMapper> phongMapper;
  vtkNew<vtkOpenGLPolyDataMapper> unlitMapper;
  vtkPolyDataMapper* mappers[3] = { unlitMapper, stockMapper, phongMapper };
  vtkActor* actors[3];
  for (int i = 0; i < 3; ++i)
  {
    mappers[i]->SetInputData(sphere);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mappers[i]);
    vtkProperty* material = actor->GetProperty();
    material->SetColor(0.8, 0.6, 0.4);
    material->SetAmbient(0.1);
    material->SetDiffuse(0.8);
    material->SetSpecular(0.5);
    material->SetSpecularPower(30.0);
    material->SetLighting(i != 0);
    renderer->AddActor(actor);
    actors[i] = actor;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, 1.6);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewAngle(40.0);
  renderer->ResetCameraClippingRange();

  for (const std::string set : { "1 headlight", "8 directional", "8 mixed" })
  {
    SetLights(renderer, set);
    std::vector<double> times[3];
    auto show = [&](int which)
    {
      for (int i = 0; i < 3; ++i)
      {
        actors[i]->SetVisibility(i == which);
      }
    };
    for (int which = 0; which < 3; ++which) // build every shader before timing
    {
      show(which);
      window->Render();
    }
    const FrameTimer timer{ window, frames };
    for (int batch = 0; batch < batches; ++batch)
    {
      for (int which = 0; which < 3; ++which)
      {
        show(which);
        times[which].push_back(timer.Batch());
      }
    }
    const double unlit = Median(times[0]), stock = Median(times[1]), ours = Median(times[2]);
    std::printf("%-18s %9.2f ms %9.2f ms %9.2f ms %9.2fx\n", set.c_str(), 1e3 * unlit, 1e3 * stock,
      1e3 * ours, ours / stock);
    std::fflush(stdout);
  }
}
}

int main(int argc, char* argv[])
{
  const char* meshFile = nullptr;
  bool quick = false;
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--quick") == 0)
    {
      quick = true;
    }
    else if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0)
    {
      std::printf("usage: %s [MESH.off] [--quick]\n", argv[0]);
      return 0;
    }
    else
    {
      meshFile = argv[i];
    }
  }
  ShaderSection(meshFile, quick);
  FrameSection(quick);
  return 0;
}
