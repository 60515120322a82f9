// vtkOpenMeshNormals against VTK's normal filters: prints numbers, asserts nothing.
//
//   vtkOpenMeshNormalsBenchmark [MESH.off ...] [--rounds N] [--quick]
//
// Meshes: a sphere of 1M triangles (vtkSphereSource, 708 x 708) and each OFF
// file given (CGAL's refined_elephant.off in ./vtkphong.sh bench), all without
// normals. Contenders, each run once per round with a fresh filter (as a
// pipeline would), rounds interleaved so all see the same machine state;
// medians over the rounds:
// - vtkPolyDataNormals with its defaults (splitting, consistency) and with
//   splitting and consistency off;
// - vtkTriangleMeshPointNormals (no splitting, no checks: the floor);
// - vtkOpenMeshNormals with its defaults (point by point where the mesh allows), with the
//   topology always built (PointByPoint off), and with splitting and consistency off;
// - vtkOpenMeshNormals updating after the points moved (topology reused).
// The goals: defaults at most 0.5x vtkPolyDataNormals' defaults in every
// round, a positions-only update at most 0.1x.
//
// First touch included: before each timed run of a fresh filter the freed
// heap is handed back to the system (malloc_trim), so every such contender
// pays for mapping its arrays' pages as in a fresh process, not only when the
// allocator happens to have none to reuse. (Not for the positions-only
// update: an animation's frames reuse the memory the last frame freed.) Besides the medians, each
// round's ratio of vtkOpenMeshNormals (defaults) to vtkPolyDataNormals (defaults) is printed, and
// the worst of them.

#include "vtkNew.h"
#include "vtkOpenMeshNormals.h"
#include "vtkPhongOFFReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTriangleMeshPointNormals.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <malloc.h>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

struct Contender
{
  std::string Name;
  std::function<void()> Run; // one timed execution
  std::vector<double> Seconds = {};
};

// vtkOpenMeshNormals (defaults) / vtkPolyDataNormals (defaults) in each round
// (the two ran back to back), and the worst round.
void PrintRoundRatios(const std::vector<double>& ours, const std::vector<double>& reference)
{
  std::printf("%-44s", "vtkOpenMeshNormals / VTK defaults per round");
  double worst = 0.0;
  for (size_t round = 0; round < ours.size(); ++round)
  {
    const double ratio = ours[round] / reference[round];
    worst = std::max(worst, ratio);
    std::printf(" %.2f", ratio);
  }
  std::printf("\n%-44s %23.2fx\n", "worst round", worst);
}

void Measure(const std::string& name, vtkPolyData* mesh, int rounds)
{
  std::printf("\n== %s: %lld triangles, %lld points ==\n", name.c_str(),
    static_cast<long long>(mesh->GetNumberOfPolys()),
    static_cast<long long>(mesh->GetNumberOfPoints()));

  auto timed = [](auto&& body)
  {
    const auto start = Clock::now();
    body();
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  // The positions-only contender keeps its filter and moves the points a
  // little before each run (outside the timing).
  vtkNew<vtkOpenMeshNormals> animated;
  animated->SetInputData(mesh);
  animated->Update();
  vtkNew<vtkPoints> original;
  original->DeepCopy(mesh->GetPoints());
  int frame = 0;

  std::vector<Contender> contenders = {
    { "vtkPolyDataNormals (defaults)",
      [&]
      {
        vtkNew<vtkPolyDataNormals> f;
        f->SetInputData(mesh);
        f->Update();
      } },
    { "vtkPolyDataNormals (no split/consistency)",
      [&]
      {
        vtkNew<vtkPolyDataNormals> f;
        f->SetInputData(mesh);
        f->SplittingOff();
        f->ConsistencyOff();
        f->Update();
      } },
    { "vtkTriangleMeshPointNormals",
      [&]
      {
        vtkNew<vtkTriangleMeshPointNormals> f;
        f->SetInputData(mesh);
        f->Update();
      } },
    { "vtkOpenMeshNormals (defaults)",
      [&]
      {
        vtkNew<vtkOpenMeshNormals> f;
        f->SetInputData(mesh);
        f->Update();
      } },
    { "vtkOpenMeshNormals (PointByPoint off)",
      [&]
      {
        vtkNew<vtkOpenMeshNormals> f;
        f->SetInputData(mesh);
        f->PointByPointOff();
        f->Update();
      } },
    { "vtkOpenMeshNormals (no split/consistency)",
      [&]
      {
        vtkNew<vtkOpenMeshNormals> f;
        f->SetInputData(mesh);
        f->SplittingOff();
        f->ConsistencyOff();
        f->Update();
      } },
    { "vtkOpenMeshNormals (positions-only)", [&] { animated->Update(); } },
  };

  for (int round = 0; round < rounds; ++round)
  {
    for (auto& contender : contenders)
    {
      if (contender.Name.find("positions-only") != std::string::npos)
      {
        // Move the points (a small wave) without changing the connectivity.
        vtkPoints* points = mesh->GetPoints();
        const double phase = 0.1 * ++frame;
        for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
        {
          double x[3];
          original->GetPoint(p, x);
          points->SetPoint(p, x[0], x[1], x[2] * (1.0 + 0.05 * std::sin(phase + 3.0 * x[0])));
        }
        points->Modified();
      }
      if (contender.Name.find("positions-only") == std::string::npos)
      {
        malloc_trim(0);
      }
      contender.Seconds.push_back(timed(contender.Run));
    }
  }
  if (!animated->GetTopologyReused())
  {
    std::printf("(warning: the positions-only update rebuilt its topology)\n");
  }
  vtkNew<vtkOpenMeshNormals> defaults;
  defaults->SetInputData(mesh);
  defaults->Update();
  std::printf("defaults computed %s\n",
    defaults->GetComputedPointByPoint() ? "point by point" : "with the topology");
  mesh->GetPoints()->DeepCopy(original);

  const double reference = Median(contenders[0].Seconds);
  std::printf("%-44s %12s %12s\n", "", "median", "/ VTK defaults");
  for (const auto& contender : contenders)
  {
    const double median = Median(contender.Seconds);
    std::printf(
      "%-44s %9.1f ms %11.2fx\n", contender.Name.c_str(), 1e3 * median, median / reference);
  }
  PrintRoundRatios(contenders[3].Seconds, contenders[0].Seconds);
  std::fflush(stdout);
}
}

int main(int argc, char* argv[])
{
  bool quick = false;
  int rounds = 7;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--quick") == 0)
    {
      quick = true;
    }
    else if (std::strcmp(argv[i], "--rounds") == 0 && i + 1 < argc)
    {
      rounds = std::max(1, std::atoi(argv[++i]));
    }
    else if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0)
    {
      std::printf("usage: %s [MESH.off ...] [--rounds N] [--quick]\n", argv[0]);
      return 0;
    }
    else
    {
      files.emplace_back(argv[i]);
    }
  }
  if (quick)
  {
    rounds = 1;
  }

  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(quick ? 40 : 708);
  sphere->SetPhiResolution(quick ? 40 : 708);
  sphere->Update();
  vtkNew<vtkPolyData> sphereMesh;
  sphereMesh->DeepCopy(sphere->GetOutput());
  sphereMesh->GetPointData()->SetNormals(nullptr);
  Measure("sphere", sphereMesh, rounds);

  for (const std::string& file : files)
  {
    vtkNew<vtkPhongOFFReader> reader;
    if (!vtkPhongOFFReader::CanReadFile(file.c_str()))
    {
      std::fprintf(stderr, "skipping %s: not an OFF file\n", file.c_str());
      continue;
    }
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkNew<vtkPolyData> mesh;
    mesh->DeepCopy(reader->GetOutput());
    Measure(file.substr(file.find_last_of('/') + 1), mesh, rounds);
  }
  return 0;
}
