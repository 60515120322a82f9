// The depth pre-pass changes no pixel. Nested closed shells (contours of vtkRTAnalyticSource)
// under 8 lights, drawn with the pre-pass off and on: the 8-bit and the float pictures are
// identical, also with a translucent actor in front under depth peeling (whose mapper never
// uses the pre-pass); with edges shown it is not used. Picking (vtkHardwareSelector) finds the same cells
// either way. Automatic uses the pre-pass under 8 lights and not under 1.

#include "vtkPhongReferenceTesting.h"

#include "vtkAppendPolyData.h"
#include "vtkContourFilter.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkRTAnalyticSource.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"

#include <set>
#include <string>

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
}

int TestPhongDepthPrePass(int, char*[])
{
  using Mapper = vtkPhongPolyDataMapper;
  vtkPhongTest::Checks checks;
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

  scene.Render8Bit(Mapper::DepthPrePassAutomatic);
  checks.Expect(scene.Shells->GetUsedDepthPrePass(), "automatic, 8 lights: the pre-pass is used");
  scene.SetLights(1);
  scene.Render8Bit(Mapper::DepthPrePassAutomatic);
  checks.Expect(!scene.Shells->GetUsedDepthPrePass(), "automatic, 1 light: no pre-pass");
  scene.SetLights(8);

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
