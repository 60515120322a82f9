// The error budget (vtkPhongLightingSettings::ErrorBudget) end to end: each scene is drawn
// into a float target and compared with the exact per-fragment model computed in double from
// the same render's G-buffer (vtkPhongReference). Under a budget the largest difference over
// every pixel and channel must stay within it, with per-vertex lighting chosen where the
// test expects it (a fine sphere under directional lights) and refused where it would cost
// more (sub-pixel triangles), could not be bounded (a point light) or does not fit (a coarse
// sphere at a tight budget). A budget of 0 keeps the exact shaders. CGAL's bunny00 (the
// first argument), a file without normals, is lit with the normals the mapper computes.
#include "vtkPhongReferenceTesting.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPhongCompositePolyDataMapper.h"
#include "vtkPhongOFFReader.h"
#include "vtkPhongPolyDataMapper.h"
#include "vtkPhongProperty.h"

#include <cmath>
#include <iostream>
#include <string>

namespace
{
struct Case
{
  const char* Name;
  int Resolution;  // of the sphere; 0: the mesh file
  int WindowSize;  // pixels
  int Lights;      // directional, spread around the view
  bool PointLight; // one point light added
  double Shininess;
  bool Blinn;
  bool Parallel;
  double Budget; // levels
  bool ExpectPerVertex;
  bool Composite = false; // two blocks through vtkPhongCompositePolyDataMapper
};

// The case's actor: one mesh through vtkPhongPolyDataMapper, or the mesh and a small sphere
// beside it as two blocks of one vtkPhongCompositePolyDataMapper (one block mapper, one
// vertex buffer: the bound bins both blocks).
vtkActor* AddSurface(vtkPhongTest::Scene& view, const Case& c, vtkPolyData* mesh)
{
  if (!c.Composite)
  {
    vtkActor* actor = vtkPhongTest::AddActor(view, mesh);
    vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper())->SetErrorBudget(c.Budget);
    return actor;
  }
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, mesh);
  blocks->SetBlock(
    1, vtkPhongTest::Moved(vtkPhongTest::MakeSphere(c.Resolution, 0.15), 0.55, 0.45, 0.3));
  vtkNew<vtkPhongCompositePolyDataMapper> mapper;
  mapper->SetInputDataObject(blocks);
  mapper->SetErrorBudget(c.Budget);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  view.Renderer->AddActor(actor);
  return actor;
}

// The last plan's signature and bound, from either mapper.
void LastPlan(vtkActor* actor, std::string& signature, double& bound)
{
  if (auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper()))
  {
    signature = mapper->GetLastShaderSignature();
    bound = mapper->GetErrorBound();
    return;
  }
  auto* composite = vtkPhongCompositePolyDataMapper::SafeDownCast(actor->GetMapper());
  signature = composite->GetLastShaderSignature();
  bound = composite->GetErrorBound();
}

void AddLights(vtkPhongTest::Scene& view, const Case& c)
{
  const double white[3] = { 1.0, 1.0, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  for (int i = 0; i < c.Lights; ++i)
  {
    const double angle = 2.399963 * i; // the golden angle: directions spread evenly
    const double position[3] = { std::cos(angle) * (0.3 + 0.1 * i), std::sin(angle) * 0.8, 1.0 };
    vtkLight* light = vtkPhongTest::AddLight(view, position, origin, white, false);
    light->SetIntensity(1.0 / c.Lights);
  }
  if (c.PointLight)
  {
    const double position[3] = { 0.0, 0.9, 0.9 };
    vtkPhongTest::AddLight(view, position, origin, white, true)->SetIntensity(0.3);
  }
}

bool RunCase(const Case& c, vtkPolyData* file)
{
  vtkPhongTest::Scene view(c.WindowSize, c.WindowSize);
  view.Renderer->AutomaticLightCreationOff();
  view.Renderer->SetAmbient(0.3, 0.3, 0.3);
  AddLights(view, c);
  vtkNew<vtkPhongProperty> material;
  material->SetColor(0.8, 0.6, 0.4);
  material->SetAmbient(0.1);
  material->SetDiffuse(0.7);
  material->SetSpecular(0.5);
  material->SetShininess(c.Shininess);
  material->SetLightingModel(c.Blinn ? vtkPhongProperty::BlinnPhong : vtkPhongProperty::Phong);
  material->SetInterpolationToPhong();
  vtkSmartPointer<vtkPolyData> mesh =
    c.Resolution ? vtkPhongTest::MakeSphere(c.Resolution) : vtkSmartPointer<vtkPolyData>(file);
  vtkActor* actor = AddSurface(view, c, mesh);
  actor->SetProperty(material);
  view.LookFromZ(2.2);
  if (!c.Resolution)
  {
    view.Renderer->ResetCamera();
  }
  view.Renderer->GetActiveCamera()->SetParallelProjection(c.Parallel);
  view.Renderer->GetActiveCamera()->SetParallelScale(0.6);

  vtkNew<vtkPhongFloatRenderPass> pass;
  vtkNew<vtkPhongReference> reference;
  reference->SetRenderer(view.Renderer);
  reference->SetActor(actor);
  auto picture = vtkPhongTest::RenderFloat(view, pass);
  std::string signature;
  double bound = 0.0;
  LastPlan(actor, signature, bound);
  auto exact = vtkPhongTest::ShadeGBuffer(view, pass, reference);
  const auto measured = vtkPhongTest::MeasureAgainst(picture, exact, 1);
  const bool perVertex = signature.find("PER_VERTEX") != std::string::npos;
  const double errorLevels = measured.MaxAbsolute * 255.0;
  std::cout << c.Name << ": " << (perVertex ? "per vertex" : "per fragment") << ", bound " << bound
            << " levels, largest error " << errorLevels << " levels over "
            << measured.ComparedPixels << " pixels (budget " << c.Budget << ")\n";
  bool ok = measured.Valid && measured.NaNPixels == 0 && measured.InfPixels == 0;
  if (perVertex != c.ExpectPerVertex)
  {
    std::cerr << c.Name << ": expected " << (c.ExpectPerVertex ? "per-vertex" : "per-fragment")
              << " lighting; signature " << signature << "\n";
    ok = false;
  }
  // The exact mode's own float rounding is far below a level; a budget is a hard maximum.
  const double allowed = c.Budget > 0.0 ? c.Budget : 0.05;
  if (!(errorLevels <= allowed) || !(bound <= std::max(c.Budget, 0.5)))
  {
    std::cerr << c.Name << ": error " << errorLevels << " or bound " << bound << " levels beyond "
              << allowed << "\n";
    ok = false;
  }
  return ok;
}
}

int TestPhongErrorBudget(int argc, char* argv[])
{
  if (argc < 2 || !vtkPhongOFFReader::CanReadFile(argv[1]))
  {
    std::cerr << "TestPhongErrorBudget needs bunny00.off as its first argument\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkPhongOFFReader> reader;
  reader->SetFileName(argv[1]);
  reader->Update();
  const Case cases[] = {
    { "exact, budget 0", 128, 600, 3, false, 40.0, true, true, 0.0, false },
    { "sphere 128, 3 lights, Blinn 40, 3 levels", 128, 600, 3, false, 40.0, true, true, 3.0, true },
    { "sphere 128, 3 lights, Phong 40, perspective, 10 levels", 128, 600, 3, false, 40.0, false,
      false, 10.0, true },
    { "sphere 128, 8 lights, Blinn 10, perspective, 6 levels", 128, 600, 8, false, 10.0, true,
      false, 6.0, true },
    { "sphere 128, 2 lights, Blinn 200, 8 levels", 128, 600, 2, false, 200.0, true, true, 8.0,
      true },
    { "sphere 128, 3 lights, Blinn 40, 1 level: the terminator's kink does not fit", 128, 600, 3,
      false, 40.0, true, true, 1.0, false },
    { "coarse sphere 24, 0.25 level: does not fit", 24, 600, 3, false, 40.0, true, true, 0.25,
      false },
    { "sub-pixel sphere 400 in 150 px: costs more", 400, 150, 3, false, 40.0, true, true, 2.0,
      false },
    { "a point light: not bounded", 128, 600, 2, true, 40.0, true, true, 1.0, false },
    { "composite, two blocks, sphere 128, 3 lights, Blinn 40, 3 levels", 128, 600, 3, false, 40.0,
      true, true, 3.0, true, true },
    { "composite, two blocks, 3 lights, Blinn 40, 1 level", 128, 600, 3, false, 40.0, true, true,
      1.0, false, true },
    { "bunny00, computed normals, 3 lights, Blinn 40, 2 levels", 0, 600, 3, false, 40.0, true,
      false, 2.0, false },
    // The scan's noisy normals make the bound 125 levels: only a huge budget goes per vertex,
    // which still exercises the computed normals on the per-vertex path.
    { "bunny00, computed normals, 3 lights, Blinn 40, 200 levels", 0, 1000, 3, false, 40.0, true,
      false, 200.0, true },
  };
  bool ok = true;
  for (const Case& c : cases)
  {
    ok = RunCase(c, reader->GetOutput()) && ok;
  }
  return ok ? 0 : 1;
}
