// One big-mesh measurement, in a process of its own so that its peak memory is its own:
//
//   vtkPhongBigMeshFrame --mesh sphere|terrain --triangles N --normals yes|no
//                        --mapper stock|phong [--size 800] [--frames 5]
//                        [--prepass auto|on|off] [--closed-culling on|off] [--settle S]
//
// It makes the mesh, notes the resident memory (the data), draws a first frame (timed to
// the GPU's completion), then, after SETTLE seconds of untimed frames (vtkPhong's background
// analyses of a large mesh end meanwhile), FRAMES frames with the camera turned by a degree
// each (the median is reported), and prints one line, `RESULT key=value ...`, with the peak
// resident memory above the data. vtkPhongGrowth.py runs it over sizes and kinds and prints the
// table. One headlight, specular 0.4, an 800 x 800 window, as in issue 29's measurements.

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkOpenMeshNormals.h"
#include "vtkPhongPolyDataMapper.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace
{
struct Options
{
  std::string Mesh = "sphere";
  double Triangles = 1e6;
  bool Normals = true;
  bool Phong = true;
  int Size = 800;
  int Frames = 5;
  double Settle = 0.0; // seconds of frames drawn, not timed, between the first and the steady
  std::string PrePass = "auto"; // vtkPhong's depth pre-pass: auto, on, off
  bool ClosedSurfaceCulling = true;
  bool InterpolatedDots = true; // vtkPhong's InterpolatedDotProducts
  double ErrorBudget = 0.0;     // vtkPhong's ErrorBudget, levels
};

// A /proc/self/status field in MB (VmRSS: resident now, VmHWM: the peak so far).
double StatusMB(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.compare(0, std::strlen(field), field) == 0)
    {
      return std::stod(line.substr(std::strlen(field) + 1)) / 1024.0;
    }
  }
  return 0.0;
}

// A UV sphere of about N triangles: 2 * theta * (phi - 2) + 2 * theta, theta = 2 phi.
vtkSmartPointer<vtkPolyData> Sphere(double triangles)
{
  const int phi = std::max(4, static_cast<int>(std::sqrt(triangles / 4.0)));
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(2 * phi);
  sphere->SetPhiResolution(phi);
  sphere->Update();
  return sphere->GetOutput();
}

// A warped plane: an open surface, every triangle facing up, none culled.
vtkSmartPointer<vtkPolyData> Terrain(double triangles, bool normals)
{
  const int resolution = std::max(2, static_cast<int>(std::sqrt(triangles / 2.0)));
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(resolution, resolution);
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputConnection(plane->GetOutputPort());
  triangulate->Update();
  vtkSmartPointer<vtkPolyData> terrain = triangulate->GetOutput();
  vtkPoints* points = terrain->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    p[2] = 0.08 * std::sin(9.0 * p[0]) * std::cos(7.0 * p[1]) + 0.03 * std::sin(31.0 * p[1]);
    points->SetPoint(i, p);
  }
  if (!normals)
  {
    return terrain;
  }
  vtkNew<vtkPolyDataNormals> withNormals;
  withNormals->SetInputData(terrain);
  withNormals->SplittingOff();
  withNormals->ComputePointNormalsOn();
  withNormals->Update();
  return withNormals->GetOutput();
}

bool Parse(int argc, char* argv[], Options& options)
{
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--mesh")
      options.Mesh = value;
    else if (key == "--triangles")
      options.Triangles = std::stod(value);
    else if (key == "--normals")
      options.Normals = value == "yes";
    else if (key == "--mapper")
      options.Phong = value == "phong";
    else if (key == "--size")
      options.Size = std::stoi(value);
    else if (key == "--frames")
      options.Frames = std::stoi(value);
    else if (key == "--settle")
      options.Settle = std::stod(value);
    else if (key == "--prepass")
      options.PrePass = value;
    else if (key == "--closed-culling")
      options.ClosedSurfaceCulling = value == "on";
    else if (key == "--dots")
      options.InterpolatedDots = value == "on";
    else if (key == "--budget")
      options.ErrorBudget = std::stod(value);
    else
      return false;
  }
  return (argc % 2) == 1 && (options.Mesh == "sphere" || options.Mesh == "terrain");
}

// The GL renderer's name (llvmpipe, a GPU), with spaces made underscores for the RESULT line.
std::string RendererName(vtkRenderWindow* window)
{
  const char* capabilities = window->ReportCapabilities(); // queries the context each call
  const std::string report = capabilities ? capabilities : "";
  const std::string key = "OpenGL renderer string:";
  const size_t at = report.find(key);
  if (at == std::string::npos)
  {
    return "unknown";
  }
  std::string name = report.substr(at + key.size(), report.find('\n', at) - at - key.size());
  name.erase(0, name.find_first_not_of(' '));
  std::replace(name.begin(), name.end(), ' ', '_');
  return name;
}

double Seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}
}

int main(int argc, char* argv[])
{
  Options options;
  if (!Parse(argc, argv, options))
  {
    std::fprintf(stderr,
      "usage: vtkPhongBigMeshFrame --mesh sphere|terrain --triangles N --normals yes|no "
      "--mapper stock|phong [--size 800] [--frames 5] [--prepass auto|on|off] "
      "[--closed-culling on|off] [--dots on|off] [--budget LEVELS] [--settle SECONDS]\n");
    return 2;
  }
  vtkSmartPointer<vtkPolyData> mesh = options.Mesh == "sphere"
    ? Sphere(options.Triangles)
    : Terrain(options.Triangles, options.Normals);
  if (!options.Normals)
  {
    mesh->GetPointData()->SetNormals(nullptr);
  }
  vtkSmartPointer<vtkPolyDataMapper> mapper;
  if (options.Phong)
  {
    vtkNew<vtkPhongPolyDataMapper> phong;
    phong->SetDepthPrePass(options.PrePass == "off"
        ? vtkPhongPolyDataMapper::DepthPrePassOff
        : (options.PrePass == "on" ? vtkPhongPolyDataMapper::DepthPrePassOn
                                   : vtkPhongPolyDataMapper::DepthPrePassAutomatic));
    phong->SetClosedSurfaceCulling(options.ClosedSurfaceCulling);
    phong->SetInterpolatedDotProducts(options.InterpolatedDots);
    phong->SetErrorBudget(options.ErrorBudget);
    mapper = phong.Get();
  }
  else
  {
    mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  }
  mapper->SetInputData(mesh);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetSpecular(0.4);
  actor->GetProperty()->SetSpecularPower(30.0);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> headlight;
  headlight->SetLightTypeToHeadlight();
  renderer->AddLight(headlight);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(options.Size, options.Size);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  if (options.Mesh == "terrain")
  {
    renderer->GetActiveCamera()->Elevation(-50.0);
    renderer->ResetCamera();
  }
  const double dataMB = StatusMB("VmRSS:");

  auto start = std::chrono::steady_clock::now();
  window->Render();
  window->WaitForCompletion();
  const double first = Seconds(start);
  // Frames drawn while vtkPhong's background analyses of a large mesh run, not timed: the
  // steady frame is the one after them (an interactive user sees these within seconds).
  int settleFrames = 0;
  const auto settleStart = std::chrono::steady_clock::now();
  while (Seconds(settleStart) < options.Settle)
  {
    renderer->GetActiveCamera()->Azimuth(1.0);
    window->Render();
    window->WaitForCompletion();
    ++settleFrames;
  }
  std::vector<double> frames;
  for (int i = 0; i < options.Frames; ++i)
  {
    renderer->GetActiveCamera()->Azimuth(1.0);
    start = std::chrono::steady_clock::now();
    window->Render();
    window->WaitForCompletion();
    frames.push_back(Seconds(start));
  }
  std::string each; // every frame, in order: a frame that repeats an analysis shows
  for (double frame : frames)
  {
    each += (each.empty() ? "" : ",") + std::to_string(static_cast<int>(1e3 * frame + 0.5));
  }
  std::sort(frames.begin(), frames.end());
  const double steady = frames.empty() ? 0.0 : frames[frames.size() / 2];
  int culled = -1;
  const char* normalsPath = "-"; // how vtkPhong got its normals
  if (auto* phong = vtkPhongPolyDataMapper::SafeDownCast(mapper))
  {
    culled = phong->GetUsedClosedSurfaceCulling() ? 1 : 0;
    normalsPath = !phong->GetUsedGeneratedNormals()             ? "input"
      : phong->GetNormalsGenerator()->GetComputedPointByPoint() ? "point-by-point"
                                                                : "topology";
  }
  std::printf(
    "RESULT mesh=%s triangles=%lld normals=%s mapper=%s first_s=%.3f steady_ms=%.1f "
    "data_mb=%.0f peak_above_data_mb=%.0f culled=%d normals_path=%s settle_frames=%d frames_ms=%s "
    "renderer=%s\n",
    options.Mesh.c_str(), static_cast<long long>(mesh->GetNumberOfPolys()),
    options.Normals ? "yes" : "no", options.Phong ? "phong" : "stock", first, 1e3 * steady, dataMB,
    StatusMB("VmHWM:") - dataMB, culled, normalsPath, settleFrames, each.c_str(),
    RendererName(window).c_str());
  return 0;
}
