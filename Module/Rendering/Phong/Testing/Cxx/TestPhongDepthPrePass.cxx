// The depth pre-pass changes no pixel. Nested closed shells (contours of vtkRTAnalyticSource)
// under 8 lights, drawn with the pre-pass off and on: the 8-bit and the float pictures are
// identical, also with a translucent actor in front under depth peeling (whose mapper never
// uses the pre-pass); with edges shown it is not used. Picking (vtkHardwareSelector) finds the same
// cells either way. Automatic probes the pre-pass and keeps it where the lighting it saves
// outweighs the depth pass (nested shells under 8 lights), not where nothing is hidden (a sphere),
// and does not probe where it could not pay even with nothing visible (CGAL's bunny); it
// decides again when a sphere's back faces start being culled.
// Occlusion culling leaves the hidden shells out of the depth pass, and a view that turns at
// once to what it left out is still exact, also with points at NaN.

#include "vtkPhongReferenceTesting.h"

#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkContourFilter.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPhongCompositePolyDataMapper.h"
#include "vtkPhongOFFReader.h"
#include "vtkRTAnalyticSource.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkUnsignedCharArray.h"

#include "vtkPhongDepthPrePass.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace
{
vtkSmartPointer<vtkPolyData> NestedShells()
{
  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(-20, 20, -20, 20, -20, 20);
  vtkNew<vtkContourFilter> contour;
  contour->SetInputConnection(source->GetOutputPort());
  for (int i = 0; i < 4; ++i)
  {
    contour->SetValue(i, 260.0 - 15.0 * i); // inner shells first in the value list
  }
  contour->ComputeNormalsOn();
  contour->Update();
  return contour->GetOutput();
}

struct PrePassScene
{
  vtkPhongTest::Scene View{ 200, 200 };
  vtkPhongPolyDataMapper* Shells = nullptr;
  vtkActor* ShellActor = nullptr;
  vtkPhongPolyDataMapper* Glass = nullptr;
  vtkActor* GlassActor = nullptr;

  PrePassScene()
  {
    vtkNew<vtkPhongProperty> material;
    material->SetSpecular(0.4);
    material->SetShininess(20.0);
    this->ShellActor = vtkPhongTest::AddActor(this->View, NestedShells(), material);
    this->Shells = vtkPhongPolyDataMapper::SafeDownCast(this->ShellActor->GetMapper());
    auto glass = vtkPhongTest::MakeSphere(24, 6.0);
    glass->GetPointData()->SetNormals(nullptr);
    this->GlassActor = vtkPhongTest::AddActor(this->View, glass);
    this->GlassActor->GetProperty()->SetOpacity(0.4);
    this->GlassActor->SetPosition(4.0, 0.0, 14.0);
    this->GlassActor->VisibilityOff();
    this->Glass = vtkPhongPolyDataMapper::SafeDownCast(this->GlassActor->GetMapper());
    this->SetLights(8);
    this->View.LookFromZ(80.0);
  }

  void SetLights(int count)
  {
    vtkRenderer* renderer = this->View.Renderer;
    renderer->RemoveAllLights();
    for (int i = 0; i < count; ++i)
    {
      const double angle = 6.283185307 * i / count;
      const double position[3] = { 40.0 * std::cos(angle), 40.0 * std::sin(angle), 40.0 };
      const double focal[3] = { 0.0, 0.0, 0.0 };
      const double color[3] = { 0.6 + 0.4 * std::cos(angle), 0.8, 0.6 + 0.4 * std::sin(angle) };
      vtkLight* light = vtkPhongTest::AddLight(this->View, position, focal, color, i % 2 == 1);
      light->SetIntensity(0.3);
    }
  }

  void SetMode(int mode)
  {
    this->Shells->SetDepthPrePass(mode);
    this->Glass->SetDepthPrePass(mode);
  }

  vtkSmartPointer<vtkImageData> Render8Bit(int mode)
  {
    this->SetMode(mode);
    this->View.Renderer->SetPass(nullptr);
    this->View.Window->Render();
    return vtkPhongTest::Snapshot(this->View.Window);
  }

  vtkSmartPointer<vtkImageData> RenderFloat(int mode)
  {
    this->SetMode(mode);
    auto image = vtkPhongTest::RenderFloat(this->View, this->Pass);
    this->View.Renderer->SetPass(nullptr);
    return image;
  }

  std::set<vtkIdType> PickCells(int mode)
  {
    this->SetMode(mode);
    this->View.Window->Render();
    vtkNew<vtkHardwareSelector> selector;
    selector->SetRenderer(this->View.Renderer);
    selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
    selector->SetArea(90, 90, 110, 110);
    std::set<vtkIdType> cells;
    vtkSmartPointer<vtkSelection> selection = vtk::TakeSmartPointer(selector->Select());
    for (unsigned int n = 0; selection && n < selection->GetNumberOfNodes(); ++n)
    {
      auto* ids = vtkIdTypeArray::SafeDownCast(selection->GetNode(n)->GetSelectionList());
      for (vtkIdType i = 0; ids && i < ids->GetNumberOfTuples(); ++i)
      {
        cells.insert(ids->GetValue(i));
      }
    }
    return cells;
  }

  vtkNew<vtkPhongFloatRenderPass> Pass;
};

bool FloatEqual(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* ra = a->GetPointData()->GetScalars();
  vtkDataArray* rb = b->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < ra->GetNumberOfValues(); ++i)
  {
    if (ra->GetVariantValue(i) != rb->GetVariantValue(i))
    {
      return false;
    }
  }
  return ra->GetNumberOfValues() == rb->GetNumberOfValues();
}

// Cell colours are fetched by primitive id from an offset VTK advances as it draws: the lit
// draw after the depth pass must start from the same offset, or it fetches nothing and
// discards every fragment.
void CheckCellColours(PrePassScene& scene, vtkPhongTest::Checks& checks)
{
  auto banded = vtkPhongTest::MakeBandedSphere(12.0);
  scene.ShellActor->VisibilityOff();
  vtkActor* ball = vtkPhongTest::AddActor(scene.View, banded);
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(ball->GetMapper());
  mapper->SetDepthPrePass(vtkPhongPolyDataMapper::DepthPrePassOff);
  scene.View.Window->Render();
  const auto off = vtkPhongTest::Snapshot(scene.View.Window);
  mapper->SetDepthPrePass(vtkPhongPolyDataMapper::DepthPrePassOn);
  scene.View.Window->Render();
  const auto on = vtkPhongTest::Snapshot(scene.View.Window);
  scene.View.Renderer->RemoveActor(ball);
  scene.ShellActor->VisibilityOn();
  const auto black = vtkPhongTest::Snapshot(scene.View.Window);
  black->GetPointData()->GetScalars()->Fill(0.0);
  checks.Expect(vtkPhongTest::CountDifferentPixels(off, black, 8) > 1000 &&
      vtkPhongTest::CountDifferentPixels(off, on, 0) == 0,
    "cell colours: drawn, and identical with the pre-pass (" +
      std::to_string(vtkPhongTest::CountDifferentPixels(off, on, 0)) + " pixels differ)");
}

// Data nobody here made: CGAL's bunny, without normals (the mapper computes them), its
// triangles overlapping in depth, under 8 directional lights: identical with and without the
// pre-pass. Automatic does not even probe it: the depth pass of its 75 408 triangles costs
// more than shading its fragments could save were none of them visible.
void CheckCGALMesh(const char* path, vtkPhongTest::Checks& checks)
{
  vtkNew<vtkPhongOFFReader> reader;
  reader->SetFileName(path);
  reader->Update();
  vtkPhongTest::Scene view(400, 400);
  view.Renderer->AutomaticLightCreationOff();
  const double origin[3] = { 0.0, 0.0, 0.0 };
  for (int i = 0; i < 8; ++i)
  {
    const double angle = 6.283185307 * i / 8;
    const double position[3] = { std::cos(angle), std::sin(angle), 1.0 };
    const double color[3] = { 0.6 + 0.4 * std::cos(angle), 0.8, 0.6 + 0.4 * std::sin(angle) };
    vtkPhongTest::AddLight(view, position, origin, color, false)->SetIntensity(0.3);
  }
  vtkNew<vtkPhongProperty> material;
  material->SetSpecular(0.4);
  material->SetShininess(20.0);
  vtkActor* bunny = vtkPhongTest::AddActor(view, reader->GetOutput(), material);
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(bunny->GetMapper());
  view.Renderer->ResetCamera();
  auto render = [&](int mode)
  {
    mapper->SetDepthPrePass(mode);
    for (int frame = 0; frame < 4; ++frame) // occlusion culling needs counts from a frame
    {
      view.Window->Render();
    }
    return vtkPhongTest::Snapshot(view.Window);
  };
  const auto off = render(vtkPhongPolyDataMapper::DepthPrePassOff);
  const auto on = render(vtkPhongPolyDataMapper::DepthPrePassOn);
  const auto black = vtkPhongTest::Snapshot(view.Window);
  black->GetPointData()->GetScalars()->Fill(0.0);
  const double triangles = static_cast<double>(reader->GetOutput()->GetNumberOfPolys());
  std::cout << "bunny: the depth pass draws " << mapper->GetDepthPassTriangles() << " of "
            << triangles << " triangles\n";
  checks.Expect(vtkPhongTest::CountDifferentPixels(off, black, 8) > 10000 &&
      vtkPhongTest::CountDifferentPixels(off, on, 0) == 0,
    "CGAL's bunny: drawn, and identical with the pre-pass (" +
      std::to_string(vtkPhongTest::CountDifferentPixels(off, on, 0)) + " pixels differ)");
  checks.Expect(mapper->GetDepthPassTriangles() < 0.9 * triangles,
    "CGAL's bunny: the depth pass leaves out the clusters its front hides");
  std::vector<bool> used;
  mapper->SetDepthPrePass(vtkPhongPolyDataMapper::DepthPrePassAutomatic);
  for (int frame = 0; frame < 3; ++frame)
  {
    view.Window->Render();
    used.push_back(mapper->GetUsedDepthPrePass());
  }
  checks.Expect(!used[0] && !used[1] && !used[2] && mapper->GetDepthComplexity() == 0.0,
    "CGAL's bunny, automatic: no probe where the pre-pass could not pay");
}

// A mesh of more than 256k triangles has its clusters arranged on a thread of their own: the
// depth pass draws every triangle until they are in, then leaves out those its front hides,
// and the picture stays the one drawn without the pre-pass.
void CheckLargeMesh(vtkPhongTest::Checks& checks)
{
  vtkPhongTest::Scene view(240, 240);
  vtkActor* actor = vtkPhongTest::AddActor(view, vtkPhongTest::MakeSphere(400)); // 318 400
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper());
  mapper->SetClosedSurfaceCulling(false); // the depth pass then has back clusters to leave out
  view.Renderer->ResetCamera();
  mapper->SetDepthPrePass(vtkPhongPolyDataMapper::DepthPrePassOff);
  view.Window->Render();
  const auto off = vtkPhongTest::Snapshot(view.Window);
  mapper->SetDepthPrePass(vtkPhongPolyDataMapper::DepthPrePassOn);
  const double triangles = 318400.0;
  bool culled = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!culled && std::chrono::steady_clock::now() < deadline)
  {
    view.Window->Render();
    culled = mapper->GetDepthPassTriangles() < 0.9 * triangles;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const int differing =
    vtkPhongTest::CountDifferentPixels(off, vtkPhongTest::Snapshot(view.Window), 0);
  checks.Expect(culled && differing == 0,
    "large mesh: clusters arranged in the background, then used (" +
      std::to_string(mapper->GetDepthPassTriangles()) +
      " of 318400 triangles in the depth "
      "pass), the picture unchanged (" +
      std::to_string(differing) + " pixels differ)");
}

// Two spheres of cells on the view axis in one polydata, the far one hidden behind the near
// one, of 20000 triangles each (several occlusion-culling clusters).
vtkSmartPointer<vtkPolyData> SpheresInLine()
{
  vtkNew<vtkAppendPolyData> append;
  for (int k = 0; k < 2; ++k)
  {
    auto sphere = vtkPhongTest::MakeSphere(100, k == 0 ? 10.0 : 6.0);
    append->AddInputData(vtkPhongTest::Moved(sphere, 0.0, 0.0, k == 0 ? 12.0 : -12.0));
  }
  append->Update();
  return append->GetOutput();
}

// Occlusion culling of the depth pass (vtkPhongVisibleClusters): once the counts are in, the
// depth pass of the nested shells leaves out the inner ones, and the pictures stay those
// without the pre-pass. Two spheres in line, viewed from behind the near one, then at once
// from the other end: the far sphere's clusters, hidden from the first view, are not in the
// depth pass of the first frame of the second view, and that frame is still exact.
void CheckOcclusionCulling(PrePassScene& scene, vtkPhongTest::Checks& checks)
{
  using Mapper = vtkPhongPolyDataMapper;
  const double shellTriangles = static_cast<double>(NestedShells()->GetNumberOfPolys());
  const auto off = scene.Render8Bit(Mapper::DepthPrePassOff);
  const auto floatOff = scene.RenderFloat(Mapper::DepthPrePassOff);
  for (int frame = 0; frame < 3; ++frame)
  {
    scene.Render8Bit(Mapper::DepthPrePassOn);
  }
  const auto on = scene.Render8Bit(Mapper::DepthPrePassOn);
  const double culled = scene.Shells->GetDepthPassTriangles();
  std::cout << "shells: the depth pass draws " << culled << " of " << shellTriangles
            << " triangles\n";
  checks.Expect(culled > 0.0 && culled < 0.6 * shellTriangles,
    "culled: the depth pass leaves out the hidden shells");
  checks.Expect(vtkPhongTest::CountDifferentPixels(off, on, 0) == 0 &&
      FloatEqual(floatOff, scene.RenderFloat(Mapper::DepthPrePassOn)),
    "culled: identical to no pre-pass, 8-bit and float");
  scene.Shells->DepthPrePassOcclusionCullingOff();
  scene.Render8Bit(Mapper::DepthPrePassOn);
  checks.Expect(scene.Shells->GetDepthPassTriangles() == shellTriangles,
    "occlusion culling off: the depth pass draws every triangle");
  scene.Shells->DepthPrePassOcclusionCullingOn();

  scene.ShellActor->VisibilityOff();
  auto spheres = SpheresInLine();
  vtkActor* line = vtkPhongTest::AddActor(scene.View, spheres);
  auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(line->GetMapper());
  auto render = [&](int mode)
  {
    mapper->SetDepthPrePass(mode);
    scene.View.Window->Render();
    return vtkPhongTest::Snapshot(scene.View.Window);
  };
  for (int frame = 0; frame < 4; ++frame)
  {
    render(Mapper::DepthPrePassOn);
  }
  const double seenFromFront = mapper->GetDepthPassTriangles();
  vtkCamera* camera = scene.View.Renderer->GetActiveCamera();
  camera->Azimuth(180.0);
  scene.View.Renderer->ResetCameraClippingRange();
  const auto turnedOn = render(Mapper::DepthPrePassOn);
  const auto turnedOff = render(Mapper::DepthPrePassOff);
  const double triangles = static_cast<double>(spheres->GetNumberOfPolys());
  std::cout << "spheres in line: the depth pass drew " << seenFromFront << " of " << triangles
            << " triangles\n";
  checks.Expect(seenFromFront < 0.6 * triangles, "spheres in line: the far one is left out");
  checks.Expect(vtkPhongTest::CountDifferentPixels(turnedOn, turnedOff, 0) == 0,
    "turned around at once: the first frame is identical to no pre-pass (" +
      std::to_string(vtkPhongTest::CountDifferentPixels(turnedOn, turnedOff, 0)) +
      " pixels differ)");
  camera->Azimuth(180.0);
  scene.View.Renderer->ResetCameraClippingRange();

  // Points at NaN (their triangles draw nothing; the clusters' bounds and order skip them).
  vtkNew<vtkPolyData> broken;
  broken->DeepCopy(spheres);
  for (vtkIdType id = 0; id < broken->GetNumberOfPoints(); id += 97)
  {
    broken->GetPoints()->SetPoint(id, std::nan(""), 0.0, std::nan(""));
  }
  mapper->SetInputData(broken);
  const auto brokenOff = render(Mapper::DepthPrePassOff);
  for (int frame = 0; frame < 3; ++frame)
  {
    render(Mapper::DepthPrePassOn);
  }
  const auto brokenOn = render(Mapper::DepthPrePassOn);
  checks.Expect(mapper->GetDepthPassTriangles() < 0.6 * triangles &&
      vtkPhongTest::CountDifferentPixels(brokenOff, brokenOn, 0) == 0,
    "points at NaN: culled, and identical to no pre-pass");
  scene.View.Renderer->RemoveActor(line);
  scene.ShellActor->VisibilityOn();
}

// A sphere in front of the shells, with point scalars as the shells have: the two share a
// block mapper (helper) of the composite mapper.
vtkSmartPointer<vtkPolyData> SphereWithScalars(double radius, double z)
{
  auto sphere = vtkPhongTest::MakeSphere(32, radius);
  vtkNew<vtkFloatArray> values;
  values->SetName("RTData");
  values->SetNumberOfTuples(sphere->GetNumberOfPoints());
  values->Fill(230.0);
  sphere->GetPointData()->SetScalars(values);
  return vtkPhongTest::Moved(sphere, 0.0, 0.0, z);
}

// The composite mapper (ParaView's Phong Surface) draws each helper's blocks with the
// pre-pass too, its depth pass culled to the clusters seen from the fourth frame on:
// - the shells and a sphere without scalars (two helpers): identical with and without it,
//   and Automatic takes it up for the shells after its probe;
// - the shells and a hidden sphere in front of them, in one helper: the clusters are all the
//   helper's triangles, the hidden block's too, so they are not used (else the hidden sphere
//   would cover the shells in the depth pass): identical;
// - the shells beside a cell-coloured sphere share a helper on VTK 9.1, which colours one of
//   the two wrongly (the scalars of the block appended last decide): that helper draws
//   plainly, as stock VTK does.
void CheckComposite(PrePassScene& scene, vtkPhongTest::Checks& checks)
{
  auto plain = vtkPhongTest::MakeSphere(32, 3.0);
  auto hidden = SphereWithScalars(4.0, 18.0);
  auto banded = vtkPhongTest::MakeBandedSphere(3.0);
  for (vtkPolyData* second : { plain.GetPointer(), hidden.GetPointer(), banded.GetPointer() })
  {
    const std::string what = second == plain ? "composite, shells and a sphere"
      : second == hidden                     ? "composite, shells and a hidden sphere in front"
                                             : "composite, shells and a cell-coloured sphere";
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetBlock(0, NestedShells());
    blocks->SetBlock(1, second);
    vtkNew<vtkPhongCompositePolyDataMapper> mapper;
    mapper->SetInputDataObject(blocks);
    vtkNew<vtkCompositeDataDisplayAttributes> attributes;
    attributes->SetBlockVisibility(second, second != hidden);
    mapper->SetCompositeDataDisplayAttributes(attributes);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetSpecular(0.4);
    scene.ShellActor->VisibilityOff();
    scene.View.Renderer->AddActor(actor);
    scene.View.Window->SetSize(400, 400);
    auto render = [&](int mode, int frames)
    {
      mapper->SetDepthPrePass(mode);
      for (int frame = 0; frame < frames; ++frame)
      {
        scene.View.Window->Render();
      }
      return vtkPhongTest::Snapshot(scene.View.Window);
    };
    const auto off = render(vtkPhongPolyDataMapper::DepthPrePassOff, 1);
    const auto on = render(vtkPhongPolyDataMapper::DepthPrePassOn, 1);
    const bool mixedHelper = second == banded && mapper->GetNumberOfHelpers() == 1;
    checks.Expect(mapper->GetUsedDepthPrePass() != mixedHelper,
      what + ", on: the pre-pass is " + (mixedHelper ? "not used (one helper)" : "used"));
    const auto fourth = render(vtkPhongPolyDataMapper::DepthPrePassOn, 3);
    if (second == hidden)
    {
      // The same helper with the clusters off: the plain depth pass leaves the hidden block
      // out as the lit draw does.
      mapper->DepthPrePassOcclusionCullingOff();
      const auto unclustered = render(vtkPhongPolyDataMapper::DepthPrePassOn, 4);
      checks.Expect(vtkPhongTest::CountDifferentPixels(off, unclustered, 0) == 0,
        what + ", occlusion culling off: identical");
      mapper->DepthPrePassOcclusionCullingOn();
    }
    const int differing = vtkPhongTest::CountDifferentPixels(off, on, 0);
    const int differingLater = vtkPhongTest::CountDifferentPixels(off, fourth, 0);
    checks.Expect(differing == 0 && differingLater == 0,
      what + ": identical with and without the pre-pass (" + std::to_string(differing) +
        " pixels differ in the first frame, " + std::to_string(differingLater) + " in the fourth)");
    if (second == plain)
    {
      std::vector<bool> used;
      mapper->SetDepthPrePass(vtkPhongPolyDataMapper::DepthPrePassAutomatic);
      for (int frame = 0; frame < 4; ++frame)
      {
        scene.View.Window->Render();
        used.push_back(mapper->GetUsedDepthPrePass());
      }
      checks.Expect(used[1] && used[3], what + ", automatic, 8 lights: probed, then kept");
    }
    scene.View.Renderer->RemoveActor(actor);
  }
  scene.ShellActor->VisibilityOn();
  scene.View.Window->SetSize(200, 200);
}

// The pre-pass used in each of `frames` frames drawn with Automatic.
std::vector<bool> AutomaticFrames(PrePassScene& scene, vtkPhongPolyDataMapper* mapper, int frames)
{
  mapper->SetDepthPrePass(vtkPhongPolyDataMapper::DepthPrePassAutomatic);
  std::vector<bool> used;
  for (int frame = 0; frame < frames; ++frame)
  {
    scene.View.Window->Render();
    used.push_back(mapper->GetUsedDepthPrePass());
  }
  return used;
}

// The mesh's cells from the farthest from `eye` to the nearest: drawn plainly, each hidden
// face is shaded before the face in front of it overwrites it.
vtkSmartPointer<vtkPolyData> FarthestFirst(vtkPolyData* mesh, const double eye[3])
{
  std::vector<std::pair<double, vtkIdType>> order;
  for (vtkIdType cell = 0; cell < mesh->GetNumberOfPolys(); ++cell)
  {
    double centre[3];
    vtkPhongTest::CellCentre(mesh, cell, centre);
    order.emplace_back(-vtkMath::Distance2BetweenPoints(centre, eye), cell);
  }
  std::sort(order.begin(), order.end());
  vtkNew<vtkIdList> ids;
  vtkNew<vtkCellArray> cells;
  for (const auto& entry : order)
  {
    mesh->GetCellPoints(entry.second, ids);
    cells->InsertNextCell(ids);
  }
  auto sorted = vtkSmartPointer<vtkPolyData>::New();
  sorted->ShallowCopy(mesh);
  sorted->SetPolys(cells);
  return sorted;
}

// A closed surface's back faces shade, drawn plainly, until its culling starts (a large
// mesh's analysis runs on a thread of its own for the first frames): the pre-pass may pay
// then and not once they are culled. The decision follows the culling at once, not at the
// next refresh (ReprobeInterval frames later).
void CheckCullingChange(
  PrePassScene& scene, vtkPhongPolyDataMapper* ballMapper, vtkPhongTest::Checks& checks)
{
  ballMapper->SetInputData(FarthestFirst(
    vtkPhongTest::MakeSphere(64, 12.0), scene.View.Renderer->GetActiveCamera()->GetPosition()));
  ballMapper->SetClosedSurfaceCulling(false);
  const std::vector<bool> unculled = AutomaticFrames(scene, ballMapper, 6);
  const double complexity = ballMapper->GetDepthComplexity();
  std::cout << "sphere, back faces drawn: " << complexity << " shaded fragments per visible one\n";
  checks.Expect(unculled[4] && unculled[5],
    "automatic, a sphere with its back faces drawn under 8 lights: the pre-pass pays");
  ballMapper->SetClosedSurfaceCulling(true);
  const std::vector<bool> culled = AutomaticFrames(scene, ballMapper, 4);
  checks.Expect(ballMapper->GetUsedClosedSurfaceCulling() && !culled[2] && !culled[3],
    "the same sphere culled: the pre-pass is left within 3 frames");
}

// Automatic: a plain frame counts the fragments it shades, the next one probes with the
// pre-pass, and from then on the pre-pass stays only while the lighting it saves outweighs
// the depth pass (vtkPhongDepthPrePass::Pays). In a 400x400 view under 8 lights the nested
// shells hide enough to pay, under 1 light not; a sphere hides nothing behind itself.
void CheckAutomatic(PrePassScene& scene, vtkPhongTest::Checks& checks)
{
  scene.View.Window->SetSize(400, 400);
  const std::vector<bool> shells = AutomaticFrames(scene, scene.Shells, 4);
  const double complexity = scene.Shells->GetDepthComplexity();
  std::cout << "shells: " << complexity << " shaded fragments per visible one\n";
  checks.Expect(!shells[0] && shells[1], "automatic: the first frame is plain, the second probes");
  checks.Expect(complexity > 2.0, "the shells: more than 2 shaded fragments per visible one");
  checks.Expect(shells[2] && shells[3], "automatic, 8 lights, hidden layers: the pre-pass stays");
  scene.SetLights(1);
  const std::vector<bool> oneLight = AutomaticFrames(scene, scene.Shells, 1);
  checks.Expect(!oneLight[0], "down to 1 light: the pre-pass is left at once");
  scene.SetLights(8);

  scene.ShellActor->VisibilityOff();
  vtkActor* ball = vtkPhongTest::AddActor(scene.View, vtkPhongTest::MakeSphere(64, 12.0));
  auto* ballMapper = vtkPhongPolyDataMapper::SafeDownCast(ball->GetMapper());
  const std::vector<bool> sphere = AutomaticFrames(scene, ballMapper, 4);
  std::cout << "sphere: " << ballMapper->GetDepthComplexity() << "\n";
  checks.Expect(sphere[1] && !sphere[2] && !sphere[3],
    "automatic, a sphere (nothing hidden): probed once, then left");
  checks.Expect(std::abs(ballMapper->GetDepthComplexity() - 1.0) < 0.01,
    "the sphere: one shaded fragment per visible one");
  CheckCullingChange(scene, ballMapper, checks);

  // The break-even against the scenes it was measured on (1280x1024, llvmpipe; plain draw
  // shaded, visible, triangles, lights; docs/results/performance.md, "Depth complexity").
  using PrePass = vtkPhongDepthPrePass;
  checks.Expect(PrePass::Pays(2.62e6, 0.47e6, 2.7e5, 8) &&
      PrePass::Pays(1.06e6, 0.47e6, 2.7e5, 8) && PrePass::Pays(1.06e6, 0.47e6, 6.5e4, 8),
    "8 lights: the pre-pass pays for the shells in either order and the outer shell alone");
  checks.Expect(!PrePass::Pays(2.62e6, 0.47e6, 2.7e5, 1) &&
      !PrePass::Pays(1.06e6, 0.47e6, 2.7e5, 1) && !PrePass::Pays(1.06e6, 0.47e6, 6.5e4, 1),
    "1 light: it does not");
  checks.Expect(!PrePass::Pays(6.7e5, 6.7e5, 1.3e5, 32), "nothing hidden: it never pays");
  scene.View.Renderer->RemoveActor(ball);
  scene.ShellActor->VisibilityOn();
  scene.View.Window->SetSize(200, 200);
}
}

int TestPhongDepthPrePass(int argc, char* argv[])
{
  using Mapper = vtkPhongPolyDataMapper;
  vtkPhongTest::Checks checks;
  if (argc < 2 || !vtkPhongOFFReader::CanReadFile(argv[1]))
  {
    std::cerr << "TestPhongDepthPrePass needs bunny00.off as its first argument\n";
    return EXIT_FAILURE;
  }
  CheckCGALMesh(argv[1], checks);
  CheckLargeMesh(checks);
  PrePassScene scene;

  const auto off = scene.Render8Bit(Mapper::DepthPrePassOff);
  checks.Expect(!scene.Shells->GetUsedDepthPrePass(), "off: no pre-pass");
  const auto on = scene.Render8Bit(Mapper::DepthPrePassOn);
  checks.Expect(scene.Shells->GetUsedDepthPrePass(), "on: the pre-pass is used");
  checks.Expect(vtkPhongTest::CountDifferentPixels(off, on, 0) == 0,
    "8-bit: identical with and without the pre-pass (" +
      std::to_string(vtkPhongTest::CountDifferentPixels(off, on, 0)) + " pixels differ)");
  checks.Expect(FloatEqual(scene.RenderFloat(Mapper::DepthPrePassOff),
                  scene.RenderFloat(Mapper::DepthPrePassOn)),
    "float: identical with and without the pre-pass");

  CheckCellColours(scene, checks);
  CheckComposite(scene, checks);
  CheckOcclusionCulling(scene, checks);
  CheckAutomatic(scene, checks);

  scene.ShellActor->GetProperty()->EdgeVisibilityOn();
  const auto edgesOff = scene.Render8Bit(Mapper::DepthPrePassOff);
  const auto edgesOn = scene.Render8Bit(Mapper::DepthPrePassOn);
  checks.Expect(!scene.Shells->GetUsedDepthPrePass() &&
      vtkPhongTest::CountDifferentPixels(edgesOff, edgesOn, 0) == 0,
    "edges shown: no pre-pass (VTK offsets edges against the surface), identical");
  scene.ShellActor->GetProperty()->EdgeVisibilityOff();

  scene.GlassActor->VisibilityOn();
  scene.View.Renderer->UseDepthPeelingOn();
  scene.View.Renderer->SetMaximumNumberOfPeels(4);
  scene.View.Renderer->SetOcclusionRatio(0.0);
  const auto peeledOff = scene.Render8Bit(Mapper::DepthPrePassOff);
  const auto peeledOn = scene.Render8Bit(Mapper::DepthPrePassOn);
  checks.Expect(!scene.Glass->GetUsedDepthPrePass(), "a translucent actor never uses it");
  checks.Expect(vtkPhongTest::CountDifferentPixels(peeledOff, peeledOn, 0) == 0,
    "translucent actor in front, depth peeling: identical");
  checks.Expect(
    vtkPhongTest::CountDifferentPixels(peeledOff, off, 8) > 100, "the translucent actor shows");
  scene.GlassActor->VisibilityOff();
  scene.View.Renderer->UseDepthPeelingOff();

  const auto pickedOff = scene.PickCells(Mapper::DepthPrePassOff);
  const auto pickedOn = scene.PickCells(Mapper::DepthPrePassOn);
  checks.Expect(!pickedOff.empty() && pickedOff == pickedOn,
    "picking finds the same " + std::to_string(pickedOff.size()) + " cells either way");
  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
