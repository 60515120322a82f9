// vtkPhong's benchmark: prints numbers, asserts nothing.
//
//   vtkPhongBenchmark [MESH.off] [--quick] [--only SECTION]
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
// 3. Then frame time by interpolation and by mesh, and light culling: 64 point lights
//    over four spheres, culling off and on (--only culling runs that section alone).
//    Depth complexity: 8 nested shells against the outer one, with and without the pre-pass.
//    The same shells as blocks of a multiblock through the composite mappers (ParaView's Phong
//    Surface and Surface).
// 4. --only kinds: every light kind at 1, 8 and 32 lights on the sphere and the meshes given.
// 5. Frame time against the error budget: stock, exact, budgets 0.5, 1 and 3 levels; then
//    the budget's planner (--only planner runs that table alone).
// 6. --only aa: specular anti-aliasing's cost, off against on (n = 1e3, 1 and 8 lights).
//
// On llvmpipe fragment work runs on the CPU, so shader cost shows in these
// times. --quick shrinks everything so ctest can check the program runs.

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkContourFilter.h"
#include "vtkLight.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPhongCompositePolyDataMapper.h"
#include "vtkPhongGouraudBound.h"
#include "vtkPhongOFFReader.h"
#include "vtkPhongPolyDataMapper.h"
#include "vtkPhongProperty.h"
#include "vtkPhongSharedDisplay.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
#include "vtkCompositePolyDataMapper.h"
using vtkStockCompositeMapper = vtkCompositePolyDataMapper; // ParaView's from VTK 9.3 on
#else
#include "vtkCompositePolyDataMapper2.h"
using vtkStockCompositeMapper = vtkCompositePolyDataMapper2;
#endif

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
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

// A mesh file (CGAL's OFF) with point normals computed without splitting, named by its file
// name: both mappers get the same normals.
std::pair<std::string, vtkSmartPointer<vtkPolyData>> MeshWithNormals(const std::string& file)
{
  vtkNew<vtkPhongOFFReader> reader;
  reader->SetFileName(file.c_str());
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(reader->GetOutputPort());
  normals->SplittingOff();
  normals->Update();
  return { file.substr(file.find_last_of('/') + 1), normals->GetOutput() };
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
    mesh = MeshWithNormals(meshFile).second;
  }
  std::printf("%-34s %12s %12s\n", "", "vtkPhong", "stock");
  {
    // The first window of a process pays for the GL context and llvmpipe's start-up:
    // a throwaway frame here keeps that out of whichever mapper would come first.
    vtkNew<vtkRenderer> renderer;
    vtkNew<vtkOpenGLPolyDataMapper> mapper;
    mapper->SetInputData(Sphere(8));
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
    vtkNew<vtkRenderWindow> window;
    vtkPhongTest::UseSharedDisplay(window);
    window->SetOffScreenRendering(1);
    window->SetSize(64, 64);
    window->AddRenderer(renderer);
    window->Render();
    window->WaitForCompletion();
  }
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

// Groups of actors drawn in turn, batch after batch, so every group sees the same machine
// state; every shader is built before timing. The median frame time of each group.
std::vector<double> RunGroups(vtkRenderWindow* window,
  const std::vector<std::vector<vtkActor*>>& groups, int batches, int frames)
{
  auto show = [&](size_t which)
  {
    for (size_t g = 0; g < groups.size(); ++g)
    {
      for (vtkActor* actor : groups[g])
      {
        actor->SetVisibility(g == which);
      }
    }
  };
  std::vector<std::vector<double>> times(groups.size());
  for (size_t which = 0; which < groups.size(); ++which) // build every shader first
  {
    show(which);
    window->Render();
    window->WaitForCompletion();
  }
  const FrameTimer timer{ window, frames };
  for (int batch = 0; batch < batches; ++batch)
  {
    for (size_t which = 0; which < groups.size(); ++which)
    {
      show(which);
      times[which].push_back(timer.Batch());
    }
  }
  std::vector<double> medians;
  for (const auto& series : times)
  {
    medians.push_back(Median(series));
  }
  return medians;
}

// One window, the same geometry drawn by each contender in turn, batch after
// batch, so every contender sees the same machine state. Medians over batches.
struct Contest
{
  vtkRenderWindow* Window;
  vtkRenderer* Renderer;
  int Batches;
  int Frames;
  std::vector<vtkActor*> Actors; // one per contender, hidden but for the one timed

  std::vector<double> Run()
  {
    std::vector<std::vector<vtkActor*>> groups;
    for (vtkActor* actor : this->Actors)
    {
      groups.push_back({ actor });
    }
    return RunGroups(this->Window, groups, this->Batches, this->Frames);
  }
};

enum Contender
{
  Unlit = 0,
  Stock = 1,
  Ours = 2,
  OursAllFeatures = 3
};

// The actors of a contest on one mesh: the unlit floor (stock mapper, lighting off), the
// stock mapper, vtkPhong, and vtkPhong's all-features variant; same material.
std::vector<vtkSmartPointer<vtkActor>> MakeContenders(
  vtkPolyData* mesh, int interpolation, bool perVertexGouraud, vtkRenderer* renderer)
{
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (int which = Unlit; which <= OursAllFeatures; ++which)
  {
    vtkSmartPointer<vtkPolyDataMapper> mapper;
    if (which == Ours || which == OursAllFeatures)
    {
      auto phong = vtkSmartPointer<vtkPhongPolyDataMapper>::New();
      phong->SetShaderSpecialization(which == Ours);
      mapper = phong;
    }
    else
    {
      mapper = vtkSmartPointer<vtkOpenGLPolyDataMapper>::New();
    }
    mapper->SetInputData(mesh);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    // A vtkPhongProperty only where it changes something (per-vertex Gouraud); otherwise
    // the same plain vtkProperty settings for everyone.
    auto material = vtkSmartPointer<vtkPhongProperty>::New();
    material->SetColor(0.8, 0.6, 0.4);
    material->SetSpecularColor(1.0, 1.0, 1.0);
    material->SetAmbient(0.1);
    material->SetDiffuse(0.8);
    material->SetSpecular(0.5);
    material->SetShininess(30.0);
    material->SetInterpolation(interpolation);
    material->SetPerVertexGouraud(perVertexGouraud && which == Ours);
    material->SetLighting(which != Unlit);
    if (which == Ours && perVertexGouraud)
    {
      actor->SetProperty(material);
    }
    else
    {
      vtkNew<vtkProperty> plain;
      plain->DeepCopy(material);
      actor->SetProperty(plain);
    }
    renderer->AddActor(actor);
    actors.push_back(actor);
  }
  return actors;
}

// The light sets: "N KIND" with KIND directional, point, spot or mixed (a quarter each of
// point and spot lights, the rest directional), or "1 headlight" (VTK's default light).
// Lights on a ring above the view, coloured, attenuated, spots of 35 degrees.
void SetLights(vtkRenderer* renderer, const std::string& set)
{
  renderer->RemoveAllLights();
  renderer->AutomaticLightCreationOff();
  if (set == "1 headlight")
  {
    vtkNew<vtkLight> headlight;
    headlight->SetLightTypeToHeadlight();
    renderer->AddLight(headlight);
    return;
  }
  const int count = std::stoi(set);
  const std::string kind = set.substr(set.find(' ') + 1);
  for (int i = 0; i < count; ++i)
  {
    const double angle = 6.283185307 * i / count;
    const double position[3] = { 1.5 * std::cos(angle), 1.5 * std::sin(angle), 1.5 };
    const double origin[3] = { 0.0, 0.0, 0.0 };
    const double color[3] = { 0.6 + 0.4 * std::cos(angle), 0.8, 0.6 + 0.4 * std::sin(angle) };
    const bool spot = kind == "spot" || (kind == "mixed" && 4 * i >= 3 * count);
    const bool point = kind == "point" || (kind == "mixed" && !spot && 2 * i >= count);
    AddLight(renderer, position, origin, spot || point, spot ? 35.0 : 180.0, color);
  }
}

struct View
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  View(int width, int height)
  {
    vtkPhongTest::UseSharedDisplay(this->Window);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetSize(width, height);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
  }

  // The mesh fills most of the view, as the benchmark sphere does.
  void Frame(vtkPolyData* mesh)
  {
    double bounds[6];
    mesh->GetBounds(bounds);
    const double center[3] = { (bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
      (bounds[4] + bounds[5]) / 2 };
    const double size =
      std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(center);
    camera->SetPosition(center[0], center[1], center[2] + 1.6 * size);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(40.0);
    this->Renderer->ResetCameraClippingRange();
  }
};

void PrintRatio(double ours, double other)
{
  std::printf(" %8.2fx", ours / other);
}

// The unlit floor, stock and vtkPhong on one mesh in their own window (the all-features
// contender hidden), the mesh framed; 5 batches of 3 frames (quick: 2 of 1).
struct MeshContest
{
  View Scene;
  std::vector<vtkSmartPointer<vtkActor>> Actors;
  Contest Race;

  MeshContest(vtkPolyData* mesh, int width, int height, bool quick)
    : Scene(width, height)
    , Actors(MakeContenders(mesh, VTK_PHONG, false, Scene.Renderer))
    , Race{ Scene.Window, Scene.Renderer, quick ? 2 : 5, quick ? 1 : 3,
      { Actors[Unlit], Actors[Stock], Actors[Ours] } }
  {
    this->Actors[OursAllFeatures]->VisibilityOff();
    this->Scene.Frame(mesh);
  }
};

// Frame time by light set: the unlit floor, stock, vtkPhong, vtkPhong all-features.
void LightSection(bool quick)
{
  const int width = quick ? 320 : 1280, height = quick ? 256 : 1024;
  auto sphere = Sphere(quick ? 32 : 256);
  std::printf("\n== Frame time by light set (sphere, %lld triangles, %dx%d, Phong"
              " interpolation; ms per frame) ==\n",
    static_cast<long long>(sphere->GetNumberOfPolys()), width, height);
  std::printf("%-15s %9s %9s %9s %9s %9s %9s %9s\n", "lights", "unlit", "stock", "vtkPhong",
    "all-feat.", "ours/stk", "ours/unl", "ours/all");
  View view(width, height);
  auto actors = MakeContenders(sphere, VTK_PHONG, false, view.Renderer);
  view.Frame(sphere);
  Contest contest{ view.Window, view.Renderer, quick ? 2 : 7, quick ? 1 : 4, {} };
  for (const auto& actor : actors)
  {
    contest.Actors.push_back(actor);
  }
  const std::vector<std::string> sets = quick
    ? std::vector<std::string>{ "1 headlight", "8 mixed" }
    : std::vector<std::string>{ "1 headlight", "1 directional", "1 point", "1 spot",
        "2 directional", "2 mixed", "8 directional", "8 point", "8 spot", "8 mixed",
        "32 directional", "32 mixed" };
  for (const std::string& set : sets)
  {
    SetLights(view.Renderer, set);
    const auto t = contest.Run();
    if (set == sets.front())
    {
      // The floor of any lit shader: normals in the vertex buffer, a varying, normalized
      // per fragment, no light arithmetic (vtkPhong's ShadingNormal view).
      auto* phong = vtkPhongPolyDataMapper::SafeDownCast(actors[Ours]->GetMapper());
      phong->SetDebugViewToShadingNormal();
      // Only the two timed actors may draw (Contest shows and hides its own actors only).
      actors[Stock]->VisibilityOff();
      actors[OursAllFeatures]->VisibilityOff();
      Contest normalsOnly{ view.Window, view.Renderer, contest.Batches, contest.Frames,
        { actors[Unlit], actors[Ours] } };
      const auto floor = normalsOnly.Run();
      phong->SetDebugViewToFinal();
      std::printf("%-15s %9.2f %9s %9.2f %9s %9s", "(normals only)", 1e3 * floor[0], "",
        1e3 * floor[1], "", "");
      PrintRatio(floor[1], floor[0]);
      std::printf("\n");
    }
    std::printf("%-15s %9.2f %9.2f %9.2f %9.2f", set.c_str(), 1e3 * t[Unlit], 1e3 * t[Stock],
      1e3 * t[Ours], 1e3 * t[OursAllFeatures]);
    PrintRatio(t[Ours], t[Stock]);
    PrintRatio(t[Ours], t[Unlit]);
    PrintRatio(t[Ours], t[OursAllFeatures]);
    std::printf("\n");
    std::fflush(stdout);
  }
}

// Frame time by interpolation, 8 mixed lights. Stock VTK has no per-vertex Gouraud: its
// "Gouraud" (per fragment) is the comparison for ours.
void InterpolationSection(bool quick)
{
  const int width = quick ? 320 : 1280, height = quick ? 256 : 1024;
  auto sphere = Sphere(quick ? 32 : 256);
  std::printf("\n== Frame time by interpolation (same sphere, 8 mixed lights; ms) ==\n");
  std::printf("%-20s %9s %9s %9s %9s\n", "interpolation", "unlit", "stock", "vtkPhong", "ours/stk");
  const struct
  {
    const char* Name;
    int Interpolation;
    bool PerVertex;
  } modes[] = { { "flat", VTK_FLAT, false }, { "Gouraud (VTK's)", VTK_GOURAUD, false },
    { "per-vertex Gouraud", VTK_GOURAUD, true }, { "Phong", VTK_PHONG, false } };
  for (const auto& mode : modes)
  {
    View view(width, height);
    auto actors = MakeContenders(sphere, mode.Interpolation, mode.PerVertex, view.Renderer);
    actors[OursAllFeatures]->VisibilityOff(); // not timed here
    view.Frame(sphere);
    SetLights(view.Renderer, "8 mixed");
    Contest contest{ view.Window, view.Renderer, quick ? 2 : 7, quick ? 1 : 4,
      { actors[Unlit], actors[Stock], actors[Ours] } };
    const auto t = contest.Run();
    std::printf(
      "%-20s %9.2f %9.2f %9.2f", mode.Name, 1e3 * t[Unlit], 1e3 * t[Stock], 1e3 * t[Ours]);
    PrintRatio(t[Ours], t[Stock]);
    std::printf("\n");
    std::fflush(stdout);
  }
}

// Heap memory in use by the process, in MiB: llvmpipe keeps vertex buffers there, so the
// growth over a first render is what a mapper's buffers and shaders cost.
double HeapInUseMiB()
{
  const struct mallinfo2 info = mallinfo2();
  return static_cast<double>(info.uordblks + info.hblkhd) / (1024.0 * 1024.0);
}

// Frame time and memory by mesh size, 1 light and 8 mixed lights.
void MeshSection(const std::vector<std::string>& meshFiles, bool quick)
{
  const int width = quick ? 320 : 1280, height = quick ? 256 : 1024;
  std::printf("\n== Frame time by mesh (ms) and the memory of a first render (MiB) ==\n");
  std::printf("%-24s %10s %-13s %9s %9s %9s %9s %9s %9s\n", "mesh", "triangles", "lights", "unlit",
    "stock", "vtkPhong", "ours/stk", "stock MiB", "ours MiB");
  std::printf("(MiB: heap growth over the first render of the mesh, each mapper alone)\n");
  std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> meshes;
  for (int resolution :
    quick ? std::vector<int>{ 16, 32 } : std::vector<int>{ 100, 256, 512, 1000, 1414 })
  {
    meshes.emplace_back("sphere " + std::to_string(resolution), Sphere(resolution));
  }
  for (const auto& file : meshFiles)
  {
    meshes.push_back(MeshWithNormals(file));
  }
  for (const auto& mesh : meshes)
  {
    // Memory first, in a fresh window per mapper: what the first render adds.
    double memory[2] = { 0.0, 0.0 };
    for (int which : { Stock, Ours })
    {
      View view(width, height);
      vtkSmartPointer<vtkPolyDataMapper> mapper;
      if (which == Ours)
      {
        mapper = vtkSmartPointer<vtkPhongPolyDataMapper>::New();
      }
      else
      {
        mapper = vtkSmartPointer<vtkOpenGLPolyDataMapper>::New();
      }
      mapper->SetInputData(mesh.second);
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->GetProperty()->SetSpecular(0.5);
      view.Renderer->AddActor(actor);
      view.Frame(mesh.second);
      SetLights(view.Renderer, "8 mixed");
      const double before = HeapInUseMiB();
      view.Window->Render();
      view.Window->WaitForCompletion();
      memory[which == Ours] = HeapInUseMiB() - before;
    }
    MeshContest contest(mesh.second, width, height, quick);
    bool first = true;
    for (const std::string set : { "1 directional", "8 mixed" })
    {
      SetLights(contest.Scene.Renderer, set);
      const auto t = contest.Race.Run();
      std::printf("%-24s %10lld %-13s %9.2f %9.2f %9.2f", first ? mesh.first.c_str() : "",
        static_cast<long long>(mesh.second->GetNumberOfPolys()), set.c_str(), 1e3 * t[Unlit],
        1e3 * t[Stock], 1e3 * t[Ours]);
      PrintRatio(t[Ours], t[Stock]);
      if (first)
      {
        std::printf(" %9.1f %9.1f", memory[0], memory[1]);
      }
      std::printf("\n");
      std::fflush(stdout);
      first = false;
    }
  }
}
}

// The unlit floor with the back faces culled (VTK's own property setting, on a copy of the
// unlit contender's property): the least a frame that culls them can cost. The renderer
// keeps the actor.
vtkActor* AddCulledFloor(vtkPolyData* mesh, vtkProperty* unlit, vtkRenderer* renderer)
{
  vtkNew<vtkOpenGLPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->DeepCopy(unlit);
  actor->GetProperty()->BackfaceCullingOn();
  renderer->AddActor(actor);
  return actor;
}

// Two more contenders of the kinds section: vtkPhong drawing the closed surfaces' back faces
// (the all-features actor, specialized again) and the unlit floor with the back faces culled
// (VTK's own property setting), the least a frame that culls them can cost.
void AddCullingContenders(MeshContest& contest, vtkPolyData* mesh)
{
  auto* unculled =
    vtkPhongPolyDataMapper::SafeDownCast(contest.Actors[OursAllFeatures]->GetMapper());
  unculled->SetShaderSpecialization(true);
  unculled->SetClosedSurfaceCulling(false);
  contest.Race.Actors.push_back(contest.Actors[OursAllFeatures]);
  contest.Race.Actors.push_back(
    AddCulledFloor(mesh, contest.Actors[Unlit]->GetProperty(), contest.Scene.Renderer));
}

// The sphere of 130k triangles (quick: 2k) and the meshes given, with their normals.
std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> SphereAndMeshes(
  const std::vector<std::string>& meshFiles, bool quick)
{
  std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> meshes;
  meshes.emplace_back("sphere 256", Sphere(quick ? 32 : 256));
  for (const auto& file : meshFiles)
  {
    meshes.push_back(MeshWithNormals(file));
  }
  return meshes;
}

// Every light kind at 1, 8 and 32 lights (and VTK's headlight) on the sphere and on each mesh
// given: the unlit floor (also with back faces culled), stock, vtkPhong (also drawing the
// back faces), ratios to stock and to the floor.
void KindSection(const std::vector<std::string>& meshFiles, bool quick)
{
  const int width = quick ? 320 : 1280, height = quick ? 256 : 1024;
  std::printf(
    "\n== Frame time by light kind and count (%dx%d, Phong interpolation; ms) ==\n", width, height);
  std::printf("%-22s %-15s %9s %9s %9s %9s %9s %9s %9s %9s %9s\n", "mesh", "lights", "unlit",
    "unl cull", "stock", "vtkPhong", "no cull", "ours/stk", "nocl/stk", "ucul/stk", "ours/unl");
  const auto meshes = SphereAndMeshes(meshFiles, quick);
  std::vector<std::string> sets = { "1 headlight" };
  for (const char* kind : { "directional", "point", "spot", "mixed" })
  {
    for (int count : quick ? std::vector<int>{ 1 } : std::vector<int>{ 1, 8, 32 })
    {
      sets.push_back(std::to_string(count) + " " + kind);
    }
  }
  for (const auto& mesh : meshes)
  {
    MeshContest contest(mesh.second, width, height, quick);
    AddCullingContenders(contest, mesh.second);
    for (const std::string& set : sets)
    {
      SetLights(contest.Scene.Renderer, set);
      const auto t = contest.Race.Run();
      std::printf("%-22s %-15s %9.2f %9.2f %9.2f %9.2f %9.2f",
        set == sets.front() ? mesh.first.c_str() : "", set.c_str(), 1e3 * t[Unlit], 1e3 * t[4],
        1e3 * t[Stock], 1e3 * t[Ours], 1e3 * t[3]);
      PrintRatio(t[Ours], t[Stock]);
      PrintRatio(t[3], t[Stock]);
      PrintRatio(t[4], t[Stock]);
      PrintRatio(t[Ours], t[Unlit]);
      std::printf("\n");
      std::fflush(stdout);
    }
  }
}

// The depth-complexity contest: the unlit floor, stock, and vtkPhong without the pre-pass,
// with it on (every triangle in its depth pass, then occlusion culled) and automatic.
struct ShellContenders
{
  ShellContenders(vtkPolyData* mesh, vtkRenderer* renderer)
  {
    auto stock = MakeContenders(mesh, VTK_PHONG, false, renderer);
    this->Actors = { stock[Unlit], stock[Stock] };
    using Mapper = vtkPhongPolyDataMapper;
    const int modes[4] = { Mapper::DepthPrePassOff, Mapper::DepthPrePassOn, Mapper::DepthPrePassOn,
      Mapper::DepthPrePassAutomatic };
    for (int k = 0; k < 4; ++k)
    {
      vtkNew<Mapper> mapper;
      mapper->SetInputData(mesh);
      mapper->SetDepthPrePass(modes[k]);
      mapper->SetDepthPrePassOcclusionCulling(k != 1);
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->SetProperty(stock[Ours]->GetProperty());
      actor->VisibilityOff();
      renderer->AddActor(actor);
      this->Actors.push_back(actor);
      this->Mappers.push_back(mapper);
    }
    for (const auto& actor : stock)
    {
      if (actor != stock[Unlit] && actor != stock[Stock])
      {
        renderer->RemoveActor(actor);
      }
    }
    // vtkPhong culls the back faces of the closed shells: its floor culls them too.
    this->Actors.push_back(AddCulledFloor(mesh, stock[Unlit]->GetProperty(), renderer));
  }
  std::vector<vtkSmartPointer<vtkActor>> Actors;
  std::vector<vtkSmartPointer<vtkPhongPolyDataMapper>> Mappers;
};

// The field the shells are contours of: vtkRTAnalyticSource, 81^3 samples.
vtkSmartPointer<vtkRTAnalyticSource> ShellField()
{
  auto source = vtkSmartPointer<vtkRTAnalyticSource>::New();
  source->SetWholeExtent(-40, 40, -40, 40, -40, 40);
  return source;
}

// Shell `shell` (0: the outermost) of the nested closed shells: contour 200 + 9 * shell of
// the field, with normals, and with the contour value as scalars or without scalars.
vtkSmartPointer<vtkPolyData> Shell(vtkRTAnalyticSource* source, int shell, bool scalars)
{
  vtkNew<vtkContourFilter> contour;
  contour->SetInputConnection(source->GetOutputPort());
  contour->SetValue(0, 200.0 + 9.0 * shell);
  contour->ComputeNormalsOn();
  contour->SetComputeScalars(scalars);
  contour->Update();
  return contour->GetOutput();
}

// The nested closed shells (contours 200, 209, ..., 263) appended inner shell first or outer
// shell first, or the outer shell alone.
vtkSmartPointer<vtkPolyData> Shells(int count, bool innerFirst)
{
  auto source = ShellField();
  vtkNew<vtkAppendPolyData> append;
  for (int i = 0; i < count; ++i)
  {
    append->AddInputData(Shell(source, innerFirst ? count - 1 - i : i, true));
  }
  append->Update();
  return append->GetOutput();
}

// Depth complexity: the lighting's share of the frame (frame minus the same geometry's unlit
// floor, with the back faces culled where vtkPhong culls them) for 8 nested shells in either order
// against the outer shell alone, under 1 directional and 8 mixed lights: stock, vtkPhong without
// the pre-pass, with it on (its depth pass drawing every triangle, then only those seen in the last
// frame) and automatic (whether Automatic used it, and the depth complexity it measured).
void ShellSection(bool quick)
{
  const int width = quick ? 320 : 1280, height = quick ? 256 : 1024;
  std::printf("\n== Depth complexity: 8 nested shells (%dx%d; ms) ==\n", width, height);
  std::printf("%-18s %-13s %6s %6s %6s %6s %6s %6s %6s %7s %7s %7s %7s %7s %9s\n", "geometry",
    "lights", "unlit", "unl bf", "stock", "ours", "pre", "culled", "auto", "stk lit", "our lit",
    "pre lit", "cul lit", "aut lit", "depth");
  const char* names[] = { "outer shell alone", "8, inner first", "8, outer first" };
  for (const char* set : { "1 directional", "8 mixed" })
  {
    double outer[5] = { 0.0, 0.0, 0.0, 0.0, 0.0 };
    for (int which = 0; which < 3; ++which)
    {
      auto mesh = which == 0 ? Shells(1, false) : Shells(8, which == 1);
      View view(width, height);
      ShellContenders contenders(mesh, view.Renderer);
      view.Frame(Shells(1, false));
      SetLights(view.Renderer, set);
      Contest contest{ view.Window, view.Renderer, quick ? 2 : 5, quick ? 1 : 3, {} };
      for (const auto& actor : contenders.Actors)
      {
        contest.Actors.push_back(actor);
      }
      const auto t = contest.Run();
      // Stock's lighting above its floor; vtkPhong's above the floor with back faces culled
      // where it culled them.
      const bool culled = contenders.Mappers.back()->GetUsedClosedSurfaceCulling();
      double lit[5];
      for (int k = 0; k < 5; ++k)
      {
        lit[k] = t[k + 1] - (k > 0 && culled ? t[6] : t[0]);
      }
      vtkPhongPolyDataMapper* automatic = contenders.Mappers.back();
      std::printf("%-18s %-13s %6.1f %6.1f %6.1f %6.1f %6.1f %6.1f %6.1f %7.1f %7.1f %7.1f %7.1f "
                  "%7.1f %4.2f %3.0f%%%s%s\n",
        names[which], set, 1e3 * t[0], 1e3 * t[6], 1e3 * t[1], 1e3 * t[2], 1e3 * t[3], 1e3 * t[4],
        1e3 * t[5], 1e3 * lit[0], 1e3 * lit[1], 1e3 * lit[2], 1e3 * lit[3], 1e3 * lit[4],
        automatic->GetDepthComplexity(),
        100.0 * contenders.Mappers[2]->GetDepthPassTriangles() / mesh->GetNumberOfPolys(),
        automatic->GetUsedDepthPrePass() ? "+" : "", culled ? " bf" : "");
      if (which == 0)
      {
        std::copy(lit, lit + 5, outer);
      }
      else
      {
        std::printf("%-32s %48s %6.2fx %6.2fx %6.2fx %6.2fx %6.2fx\n", "  lit / outer's lit", "",
          lit[0] / outer[0], lit[1] / outer[1], lit[2] / outer[2], lit[3] / outer[3],
          lit[4] / outer[4]);
      }
      std::fflush(stdout);
    }
  }
  std::printf("(depth: fragments a plain draw shades per visible one, as Automatic measured, and"
              " the share of the triangles the culled depth pass drew; +: Automatic used the"
              " pre-pass in the last frame; bf: vtkPhong culled the closed shells' back faces,"
              " and its lit times are above the unlit floor that culls them, unl bf)\n");
}

// The shells as the blocks of a multiblock, one contour each, as ParaView draws a group of
// contours (one block mapper holds them all).
vtkSmartPointer<vtkMultiBlockDataSet> ShellBlocks(int count, bool innerFirst)
{
  auto source = ShellField();
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  for (int i = 0; i < count; ++i)
  {
    blocks->SetBlock(i, Shell(source, innerFirst ? count - 1 - i : i, false));
  }
  return blocks;
}

// Depth complexity through the composite mappers, under 8 mixed lights: the stock composite
// mapper unlit (the floor) and lit, vtkPhong's without the pre-pass and automatic (it culls
// the closed shells' back faces: its lighting is above the floor that culls them).
void CompositeShellSection(bool quick)
{
  const int width = quick ? 320 : 1280, height = quick ? 256 : 1024;
  std::printf("\n== Depth complexity, composite mappers: 8 shells as 8 blocks (%dx%d, 8 mixed "
              "lights; ms) ==\n",
    width, height);
  std::printf("%-18s %6s %6s %6s %6s %6s %7s %7s %7s\n", "geometry", "unlit", "unl bf", "stock",
    "no pre", "auto", "stk lit", "nop lit", "aut lit");
  const char* names[] = { "outer shell alone", "8, inner first", "8, outer first" };
  double outer[3] = { 0.0, 0.0, 0.0 };
  for (int which = 0; which < 3; ++which)
  {
    auto blocks = which == 0 ? ShellBlocks(1, false) : ShellBlocks(8, which == 1);
    View view(width, height);
    std::vector<vtkSmartPointer<vtkActor>> actors;
    std::vector<vtkPhongCompositePolyDataMapper*> ours;
    for (int k = 0; k < 5; ++k) // unlit, unlit culled, stock, ours off, ours automatic
    {
      vtkSmartPointer<vtkStockCompositeMapper> mapper;
      if (k < 3)
      {
        mapper = vtkSmartPointer<vtkStockCompositeMapper>::New();
      }
      else
      {
        auto phong = vtkSmartPointer<vtkPhongCompositePolyDataMapper>::New();
        phong->SetDepthPrePass(k == 3 ? vtkPhongPolyDataMapper::DepthPrePassOff
                                      : vtkPhongPolyDataMapper::DepthPrePassAutomatic);
        ours.push_back(phong);
        mapper = phong;
      }
      mapper->SetInputDataObject(blocks);
      auto actor = vtkSmartPointer<vtkActor>::New();
      actor->SetMapper(mapper);
      actor->GetProperty()->SetColor(0.8, 0.6, 0.4);
      actor->GetProperty()->SetSpecular(0.5);
      actor->GetProperty()->SetSpecularPower(30.0);
      actor->GetProperty()->SetInterpolationToPhong();
      actor->GetProperty()->SetLighting(k > 1);
      actor->GetProperty()->SetBackfaceCulling(k == 1);
      view.Renderer->AddActor(actor);
      actors.push_back(actor);
    }
    view.Frame(Shells(1, false));
    SetLights(view.Renderer, "8 mixed");
    Contest contest{ view.Window, view.Renderer, quick ? 2 : 5, quick ? 1 : 3, {} };
    for (const auto& actor : actors)
    {
      contest.Actors.push_back(actor);
    }
    const auto t = contest.Run();
    const bool culled = ours.back()->GetUsedClosedSurfaceCulling();
    const double lit[3] = { t[2] - t[0], t[3] - t[culled ? 1 : 0], t[4] - t[culled ? 1 : 0] };
    std::printf("%-18s %6.1f %6.1f %6.1f %6.1f %6.1f %7.1f %7.1f %7.1f%s%s\n", names[which],
      1e3 * t[0], 1e3 * t[1], 1e3 * t[2], 1e3 * t[3], 1e3 * t[4], 1e3 * lit[0], 1e3 * lit[1],
      1e3 * lit[2], ours.back()->GetUsedDepthPrePass() ? " +" : "", culled ? " bf" : "");
    if (which == 0)
    {
      std::copy(lit, lit + 3, outer);
    }
    else
    {
      std::printf("%-18s %34s %6.2fx %6.2fx %6.2fx\n", "  lit / outer's lit", "", lit[0] / outer[0],
        lit[1] / outer[1], lit[2] / outer[2]);
    }
    std::fflush(stdout);
  }
  std::printf("(stock: %s; +: Automatic used the pre-pass in the last frame; bf: vtkPhong culled "
              "the back faces, and its lit times are above the floor that culls them, unl bf)\n",
    vtkSmartPointer<vtkStockCompositeMapper>::New()->GetClassName());
}

// Light culling: four spheres on a 2 x 2 grid, each with 16 of 64 point lights close in
// front of it (inverse-square attenuation; the scene of TestPhongLightCulling). vtkPhong
// with culling off (bound 0) and on (the default 0.5/255, 16 lights per sphere), the stock
// mapper and the unlit floor.
void CullingSection(bool quick)
{
  const int width = quick ? 320 : 1280, height = quick ? 256 : 1024;
  std::printf(
    "\n== Light culling (4 spheres, 64 point lights, 16 near each; %dx%d; ms) ==\n", width, height);
  View view(width, height);
  view.Renderer->AutomaticLightCreationOff();
  const double spacing = 30.0;
  const char* names[] = { "unlit", "stock", "vtkPhong, culling off", "vtkPhong, culling on" };
  std::vector<std::vector<vtkActor*>> groups(4);
  std::vector<vtkPhongPolyDataMapper*> culled;
  for (int i = 0; i < 4; ++i)
  {
    const double center[3] = { (i % 2 - 0.5) * spacing, (i / 2 - 0.5) * spacing, 0.0 };
    vtkNew<vtkSphereSource> source;
    source->SetRadius(1.5);
    source->SetThetaResolution(quick ? 32 : 256);
    source->SetPhiResolution(quick ? 32 : 256);
    source->Update();
    for (int which = 0; which < 4; ++which)
    {
      vtkSmartPointer<vtkPolyDataMapper> mapper;
      if (which >= 2)
      {
        auto phong = vtkSmartPointer<vtkPhongPolyDataMapper>::New();
        phong->SetLightCullingBound(which == 3 ? 0.5 / 255.0 : 0.0);
        if (which == 3)
        {
          culled.push_back(phong);
        }
        mapper = phong;
      }
      else
      {
        mapper = vtkSmartPointer<vtkOpenGLPolyDataMapper>::New();
      }
      mapper->SetInputData(source->GetOutput());
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->SetPosition(center[0], center[1], center[2]);
      actor->GetProperty()->SetInterpolationToPhong();
      actor->GetProperty()->SetSpecular(0.4);
      actor->GetProperty()->SetSpecularPower(20.0);
      actor->GetProperty()->SetLighting(which != 0);
      view.Renderer->AddActor(actor);
      groups[which].push_back(actor);
    }
    for (int k = 0; k < 16; ++k)
    {
      const double azimuth = 6.283185307 * (k % 8) / 8.0;
      const double polar = (k < 8 ? 35.0 : 70.0) * 3.14159265358979 / 180.0;
      vtkNew<vtkLight> light;
      light->SetLightTypeToSceneLight();
      light->SetPosition(center[0] + 1.8 * std::sin(polar) * std::cos(azimuth),
        center[1] + 1.8 * std::sin(polar) * std::sin(azimuth), 1.8 * std::cos(polar));
      light->SetFocalPoint(center);
      light->PositionalOn();
      light->SetConeAngle(180.0);
      light->SetIntensity(0.03);
      light->SetAttenuationValues(0.0, 0.0, 1.0);
      view.Renderer->AddLight(light);
    }
  }
  vtkCamera* camera = view.Renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.0, 0.0, 2.2 * spacing);
  camera->SetViewAngle(30.0);
  view.Renderer->ResetCameraClippingRange();
  const auto t = RunGroups(view.Window, groups, quick ? 2 : 7, quick ? 1 : 4);
  int evaluated = 0;
  for (vtkPhongPolyDataMapper* mapper : culled)
  {
    evaluated += 64 - mapper->GetNumberOfCulledLights();
  }
  std::printf("%-24s %9s %9s %9s\n", "", "ms", "/ stock", "/ off");
  for (size_t which = 0; which < 4; ++which)
  {
    std::printf("%-24s %9.2f %8.2fx %8.2fx\n", names[which], 1e3 * t[which], t[which] / t[1],
      t[which] / t[2]);
  }
  std::printf("(culling on: %d lights evaluated over the 4 spheres, of 256)\n", evaluated);
  std::fflush(stdout);
}

// The error budget's planner: binning the triangles once per upload, and the bound per frame
// (vtkPhongGouraudBound) under 1 and 8 directional lights, two-sided, Blinn 30, perspective,
// with the eye turning (every frame computes) or still (remembered). Limited as the planner
// limits it under a budget of 1 level, the bound stops once no mode fits; "whole" is the bound
// without a limit, what it costs where a mode fits. Medians of batches of frames.
void PlannerCost(
  const std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>>& meshes, bool quick)
{
  std::printf("\n== The error budget's planner (ms) ==\n");
  std::printf("%-22s %10s %12s %12s %12s %12s %12s\n", "mesh", "binning", "1 light", "8 lights",
    "8, whole", "8, still", "8 point, wh.");
  const int batches = quick ? 1 : 11, calls = quick ? 5 : 20;
  for (const auto& mesh : meshes)
  {
    vtkPhongGouraudBound bound;
    auto start = Clock::now();
    bound.Update({ mesh.second.GetPointer() }, 1);
    const double binning = Seconds(start);
    std::vector<double> perCall;
    double bounds[6];
    mesh.second->GetBounds(bounds);
    const double size =
      std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1.0e-12 });
    for (int which = 0; which < 5; ++which)
    {
      vtkPhongGouraudBound::Scene scene;
      scene.Parallel = false;
      scene.Shininess = 30.0;
      const int lights = which == 0 ? 1 : 8;
      for (int i = 0; i < lights; ++i)
      {
        const double angle = 6.283185307 * i / lights;
        vtkPhongGouraudBound::Scene::Light light;
        light.ToLightMC = { { std::cos(angle) / std::sqrt(2.0), std::sin(angle) / std::sqrt(2.0),
          1.0 / std::sqrt(2.0) } };
        light.Diffuse = 0.24;
        light.Specular = 0.15;
        light.Positional = which == 4; // at twice the mesh's size, in the same directions
        for (int k = 0; k < 3; ++k)
        {
          light.PositionMC[k] =
            0.5 * (bounds[2 * k] + bounds[2 * k + 1]) + 2.0 * size * light.ToLightMC[k];
        }
        scene.Lights.push_back(light);
      }
      const double limit = which == 2 || which == 4 ? HUGE_VAL : 1.0 / 255.0;
      std::vector<double> series;
      for (int batch = 0, call = 0; batch < batches; ++batch)
      {
        start = Clock::now();
        for (int i = 0; i < calls; ++i, ++call)
        {
          const double turn = which == 3 ? 0.0 : 0.01 * call; // radians about y
          scene.EyeMC = { { 5.0 * std::sin(turn), 0.0, 5.0 * std::cos(turn) } };
          bound.Bound(scene, limit);
        }
        series.push_back(Seconds(start) / calls);
      }
      perCall.push_back(Median(series));
    }
    std::printf("%-22s %10.1f %12.3f %12.3f %12.3f %12.4f %12.3f\n", mesh.first.c_str(),
      1e3 * binning, 1e3 * perCall[0], 1e3 * perCall[1], 1e3 * perCall[2], 1e3 * perCall[3],
      1e3 * perCall[4]);
  }
  std::printf("(binning: once per upload; the others per frame and actor, the eye turning or "
              "still; limited at 1 level but \"whole\"; point lights at twice the mesh's size)\n");
}

// The mode a vtkPhong mapper's last plan chose under its error budget, in a word, and "+c"
// where its fragment shader took the light and material values as constants.
std::string BudgetMode(vtkPhongPolyDataMapper* mapper)
{
  const bool constants =
    std::string(mapper->GetLastShaderSignature()).find("UNIFORM_CONSTANTS") != std::string::npos;
  const char* mode = "fragment";
  switch (mapper->GetBudgetMode())
  {
    case vtkPhongPolyDataMapper::BudgetPerVertex:
      mode = "vertex";
      break;
    case vtkPhongPolyDataMapper::BudgetSpecularPerVertex:
      mode = "specular";
      break;
    default:
      break;
  }
  return std::string(mode) + (constants ? "+c" : "");
}

// What the error budget buys (vtkPhongPolyDataMapper::SetErrorBudget): stock, exact vtkPhong
// and vtkPhong under budgets of 0.5, 1 and 3 levels on the sphere and each mesh given, under
// the kinds section's light sets of 1 and 8 lights; the materials of that section, Blinn-Phong
// for vtkPhong. Each budget's column: ms, the mode it chose (fragment: every sum per fragment,
// the lobe by squaring where that fits; specular: the specular sums per vertex; vertex:
// every sum; +c: the light and material values as constants) and its bound in levels.
void BudgetSection(const std::vector<std::string>& meshFiles, bool quick)
{
  const int width = quick ? 320 : 1280, height = quick ? 256 : 1024;
  const double budgets[] = { 0.5, 1.0, 3.0 };
  std::printf("\n== Frame time against the error budget (%dx%d; ms) ==\n", width, height);
  std::printf("%-22s %-15s %8s %8s", "mesh", "lights", "stock", "exact");
  for (double budget : budgets)
  {
    std::printf(" %24s", ("budget " + std::to_string(budget).substr(0, 3)).c_str());
  }
  std::printf(" %8s %8s %8s %8s\n", "1/stock", "1/exact", "0.5/exa", "3/stock");
  const auto meshes = SphereAndMeshes(meshFiles, quick);
  const std::vector<std::string> sets = quick
    ? std::vector<std::string>{ "8 directional" }
    : std::vector<std::string>{ "1 directional", "8 directional", "8 point", "8 spot", "8 mixed" };
  for (const auto& mesh : meshes)
  {
    View view(width, height);
    auto actors = MakeContenders(mesh.second, VTK_PHONG, false, view.Renderer);
    actors[Unlit]->VisibilityOff();
    actors[OursAllFeatures]->VisibilityOff();
    vtkNew<vtkPhongProperty> blinn;
    blinn->DeepCopy(actors[Ours]->GetProperty());
    blinn->SetLightingModelToBlinnPhong();
    actors[Ours]->SetProperty(blinn);
    Contest contest{ view.Window, view.Renderer, quick ? 2 : 5, quick ? 1 : 3,
      { actors[Stock], actors[Ours] } };
    std::vector<vtkPhongPolyDataMapper*> budgeted;
    for (double budget : budgets)
    {
      auto mapper = vtkSmartPointer<vtkPhongPolyDataMapper>::New();
      mapper->SetInputData(mesh.second);
      mapper->SetErrorBudget(budget);
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->SetProperty(blinn);
      view.Renderer->AddActor(actor);
      contest.Actors.push_back(actor);
      budgeted.push_back(mapper);
    }
    view.Frame(mesh.second);
    for (const std::string& set : sets)
    {
      SetLights(view.Renderer, set);
      const auto t = contest.Run();
      std::printf("%-22s %-15s %8.2f %8.2f", set == sets.front() ? mesh.first.c_str() : "",
        set.c_str(), 1e3 * t[0], 1e3 * t[1]);
      for (std::size_t b = 0; b < budgeted.size(); ++b)
      {
        std::printf(" %8.2f %-10s %4.2f", 1e3 * t[2 + b], BudgetMode(budgeted[b]).c_str(),
          std::min(budgeted[b]->GetErrorBound(), 9.99));
      }
      PrintRatio(t[3], t[0]);
      PrintRatio(t[3], t[1]);
      PrintRatio(t[2], t[1]);
      PrintRatio(t[4], t[0]);
      std::printf("\n");
      std::fflush(stdout);
    }
  }
  std::printf("(each budget: ms, mode, bound in levels; fragment = every sum per fragment, "
              "the lobe by squaring where its rounding fits, specular = the specular sums per "
              "vertex and the diffuse per fragment, vertex = every sum per vertex, +c = the light "
              "and material values as constants in the fragment shader; ratios: "
              "budget 1 to stock and to exact, 0.5 to exact, 3 to stock)\n");
  PlannerCost(meshes, quick);
}

// Specular anti-aliasing's cost: vtkPhong with and without it on the sphere and the meshes
// given (narrow Blinn lobe, n = 1e3), 1 and 8 directional lights, one window, interleaved.
void AntiAliasingSection(const std::vector<std::string>& meshFiles, bool quick)
{
  const int width = quick ? 320 : 1280, height = quick ? 256 : 1024;
  std::printf("\n== Specular anti-aliasing (%dx%d; ms) ==\n", width, height);
  std::printf("%-22s %-15s %8s %8s %8s\n", "mesh", "lights", "off", "on", "on/off");
  const auto meshes = SphereAndMeshes(meshFiles, quick);
  for (const auto& mesh : meshes)
  {
    View view(width, height);
    vtkNew<vtkPhongProperty> blinn;
    blinn->SetColor(0.8, 0.6, 0.4);
    blinn->SetSpecularColor(1.0, 1.0, 1.0);
    blinn->SetDiffuse(0.8);
    blinn->SetSpecular(0.5);
    blinn->SetShininess(1.0e3);
    blinn->SetLightingModelToBlinnPhong();
    blinn->SetInterpolationToPhong();
    Contest contest{ view.Window, view.Renderer, quick ? 2 : 7, quick ? 1 : 3, {} };
    for (const bool filtered : { false, true })
    {
      vtkNew<vtkPhongPolyDataMapper> mapper;
      mapper->SetInputData(mesh.second);
      mapper->SetSpecularAntiAliasing(filtered);
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->SetProperty(blinn);
      view.Renderer->AddActor(actor);
      contest.Actors.push_back(actor);
    }
    view.Frame(mesh.second);
    for (const std::string set : { "1 directional", "8 directional" })
    {
      SetLights(view.Renderer, set);
      const auto t = contest.Run();
      std::printf("%-22s %-15s %8.2f %8.2f",
        set == std::string("1 directional") ? mesh.first.c_str() : "", set.c_str(), 1e3 * t[0],
        1e3 * t[1]);
      PrintRatio(t[1], t[0]);
      std::printf("\n");
      std::fflush(stdout);
    }
  }
}

int main(int argc, char* argv[])
{
  std::vector<std::string> meshFiles;
  bool quick = false;
  std::string only; // one section: shaders, lights, interpolation, meshes, culling, ...
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--quick") == 0)
    {
      quick = true;
    }
    else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc)
    {
      only = argv[++i];
    }
    else if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0)
    {
      std::printf("usage: %s [MESH.off ...] [--quick] [--only shaders|lights|interpolation|"
                  "meshes|culling|shells|kinds|budget|planner|aa]\n",
        argv[0]);
      return 0;
    }
    else
    {
      meshFiles.emplace_back(argv[i]);
    }
  }
  auto wanted = [&](const char* section) { return only.empty() || only == section; };
  if (wanted("shaders"))
  {
    ShaderSection(meshFiles.empty() ? nullptr : meshFiles.front().c_str(), quick);
  }
  if (wanted("lights"))
  {
    LightSection(quick);
  }
  if (wanted("interpolation"))
  {
    InterpolationSection(quick);
  }
  if (wanted("meshes"))
  {
    MeshSection(meshFiles, quick);
  }
  if (wanted("culling"))
  {
    CullingSection(quick);
  }
  if (wanted("shells"))
  {
    ShellSection(quick);
    CompositeShellSection(quick);
  }
  if (only == "kinds" || (only.empty() && quick))
  {
    KindSection(meshFiles, quick); // about 10 minutes in full: not in the default run
  }
  if (wanted("budget"))
  {
    BudgetSection(meshFiles, quick);
  }
  if (only == "planner")
  {
    PlannerCost(SphereAndMeshes(meshFiles, quick), quick);
  }
  if (wanted("aa"))
  {
    AntiAliasingSection(meshFiles, quick);
  }
  return 0;
}
