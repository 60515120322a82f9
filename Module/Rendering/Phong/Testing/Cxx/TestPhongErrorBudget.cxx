// The error budget (vtkPhongLightingSettings::ErrorBudget) end to end: each scene is drawn
// into a float target and compared with the exact per-fragment model computed in double from
// the same render's G-buffer (vtkPhongReference). Under a budget the largest difference over
// every pixel and channel must stay within it, with the mode the test expects: every light
// sum per vertex (a fine sphere under directional lights, a loose budget), the specular sums
// alone per vertex and the diffuse per fragment (tighter budgets, finer spheres: the
// terminator's kink does not fit), or per fragment where per vertex would cost more
// (sub-pixel triangles), could not be bounded (a point light) or does not fit (a coarse
// sphere at a tight budget). A budget of 0 keeps the exact shaders. CGAL's bunny00 (the
// first argument), a file without normals, is lit with the normals the mapper computes.
// Then random scenes (--random N, default 40; --seed S) and an orbit that crosses the
// decision thresholds (--orbit FRAMES, default 120): every frame within its budget, no
// exception. `./vtkphong.sh budget-sweep` runs 1000 random scenes.
#include "vtkPhongReferenceTesting.h"
#include "vtkPhongTestActors.h"
#include "vtkPhongTestTorus.h"

#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkIdList.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPhongCompositePolyDataMapper.h"
#include "vtkPhongLightingSettings.h"
#include "vtkPhongOFFReader.h"
#include "vtkPhongPolyDataMapper.h"
#include "vtkPhongProperty.h"
#include "vtkPhongShaderTemplate.h"
#include "vtkPolyDataNormals.h"
#include "vtkTessellatedBoxSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
enum Mode
{
  PerFragment = vtkPhongLightingSettings::BudgetPerFragment,
  SpecularPerVertex = vtkPhongLightingSettings::BudgetSpecularPerVertex,
  PerVertex = vtkPhongLightingSettings::BudgetPerVertex
};
const char* ModeNames[] = { "per fragment", "specular per vertex", "per vertex" };

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
  Mode Expected;
  bool Composite = false; // two blocks through vtkPhongCompositePolyDataMapper
  bool OneSided = false;  // the renderer's two-sided lighting off
  double Specular = 0.5;
  // The point light's attenuation, not VTK's default: 1, (1, 0.5, 0); 2, (0, 1, 0), no
  // constant term.
  int Attenuated = 0;
  vtkPhongTest::ActorKind Actor = vtkPhongTest::ActorKind::Plain;
};

// The case's actor: one mesh through vtkPhongPolyDataMapper, or the mesh and a small sphere
// beside it as two blocks of one vtkPhongCompositePolyDataMapper (one block mapper, one
// vertex buffer: the bound bins both blocks).
vtkActor* AddSurface(vtkPhongTest::Scene& view, const Case& c, vtkPolyData* mesh)
{
  if (!c.Composite)
  {
    vtkActor* actor = vtkPhongTest::AddActor(view, mesh, nullptr, vtkPhongTest::MakeActor(c.Actor));
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
  vtkSmartPointer<vtkActor> actor = vtkPhongTest::MakeActor(c.Actor);
  actor->SetMapper(mapper);
  view.Renderer->AddActor(actor);
  return actor;
}

// What the last plan chose, as either mapper reports it.
struct Plan
{
  std::string Signature;
  double Bound = 0.0; // levels
  int Mode = PerFragment;
  std::string ModeName;
  int SquaredShininess = 0;
};

template <class Mapper>
Plan LastPlanOf(Mapper* mapper)
{
  Plan plan;
  plan.Signature = mapper->GetLastShaderSignature();
  plan.Bound = mapper->GetErrorBound();
  plan.Mode = mapper->GetBudgetMode();
  plan.ModeName = mapper->GetBudgetModeAsString();
  plan.SquaredShininess = mapper->GetSquaredShininess();
  return plan;
}

Plan LastPlan(vtkActor* actor)
{
  if (auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper()))
  {
    return LastPlanOf(mapper);
  }
  return LastPlanOf(vtkPhongCompositePolyDataMapper::SafeDownCast(actor->GetMapper()));
}

// Whether the mapper's report (GetBudgetMode, its name, GetSquaredShininess) is what the shader
// it built does, as its signature's features say.
bool ReportMatchesShader(const Plan& plan)
{
  const std::string& signature = plan.Signature;
  const int built = signature.find("PER_VERTEX") == std::string::npos ? PerFragment
    : signature.find("DIFFUSE_PER_FRAGMENT") != std::string::npos     ? SpecularPerVertex
                                                                      : PerVertex;
  const std::string squared = " | shininess " + std::to_string(plan.SquaredShininess);
  const bool squaring = signature.find("WHOLE_SHININESS") != std::string::npos;
  const bool ok = plan.Mode == built && plan.ModeName == ModeNames[built] &&
    squaring == (plan.SquaredShininess > 0) &&
    (!squaring || signature.find(squared) != std::string::npos);
  if (!ok)
  {
    std::cerr << "the mapper reports " << plan.ModeName << " (" << plan.Mode
              << "), squared shininess " << plan.SquaredShininess << "; its shader: " << signature
              << "\n";
  }
  return ok;
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
    vtkLight* light = vtkPhongTest::AddLight(view, position, origin, white, true);
    light->SetIntensity(0.3);
    light->SetConeAngle(180.0); // a point light, not VTK's default spot of 30 degrees
    if (c.Attenuated)
    {
      light->SetAttenuationValues(
        c.Attenuated == 1 ? 1.0 : 0.0, c.Attenuated == 1 ? 0.5 : 1.0, 0.0);
    }
  }
}

// What one frame of a scene chose and how far it strayed: the picture, in a float target,
// against vtkPhongReference shading the same render's G-buffer in double.
struct Outcome
{
  Mode Chosen = PerFragment;
  double Bound = 0.0; // levels
  double Error = 0.0; // levels, the largest over every pixel and channel
  vtkIdType Pixels = 0;
  bool Valid = false; // compared, and no NaN or infinite pixel
  std::string Signature;
  int SquaredShininess = 0;
  bool Reported = true;   // the mapper's report matches its shader (ReportMatchesShader)
  vtkIdType Excused = 0;  // pixels on a discontinuity of the model (ExcuseDiscontinuities)
  bool Constants = false; // the second frame took the constants (UNIFORM_CONSTANTS)
  // How much further from the double model the picture lies than the exact mode's own
  // picture, at its worst pixel and channel, in levels (0 for the exact mode): what the
  // plan's bound bounds.
  double Departure = 0.0;
  // Within the budget, and within the bound the plan reports (a bound that the picture
  // exceeds is wrong even where the budget hides it; 1e-3 level for programs that differ in
  // nothing the bound charges, whose compilations may still round apart).
  bool Within(double budget) const
  {
    return this->Error <= budget && this->Departure <= this->Bound + 1.0e-3;
  }
};

void SetBudget(vtkActor* actor, double levels)
{
  if (auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper()))
  {
    mapper->SetErrorBudget(levels);
    return;
  }
  vtkPhongCompositePolyDataMapper::SafeDownCast(actor->GetMapper())->SetErrorBudget(levels);
}

// The colour channels of the budget's picture, the exact mode's and the double model's, pixel
// by pixel.
struct ThreePictures
{
  vtkDataArray* Judged;
  vtkDataArray* Own;
  vtkDataArray* Model;
  int Channels;
  ThreePictures(vtkImageData* picture, vtkImageData* exact, vtkImageData* reference)
    : Judged(picture->GetPointData()->GetScalars())
    , Own(exact->GetPointData()->GetScalars())
    , Model(reference->GetPointData()->GetScalars())
    , Channels(std::min({ Judged->GetNumberOfComponents(), Own->GetNumberOfComponents(),
        Model->GetNumberOfComponents(), 3 }))
  {
  }
};

// Where the exact mode's own picture strays from the double model by more than its rounding
// (0.05 level), the model is discontinuous there (the specular gate at N.L = 1e-4, which
// float and double may decide differently, as docs/lighting-model.md says): the budget's
// picture is not judged at that pixel and takes the reference's value. Returns how many
// pixels were excused.
vtkIdType ExcuseDiscontinuities(vtkImageData* picture, vtkImageData* exact, vtkImageData* reference)
{
  const ThreePictures p(picture, exact, reference);
  vtkIdType excused = 0;
  for (vtkIdType pixel = 0; pixel < p.Judged->GetNumberOfTuples(); ++pixel)
  {
    bool strays = false;
    for (int c = 0; c < p.Channels; ++c)
    {
      strays = strays ||
        std::abs(p.Own->GetComponent(pixel, c) - p.Model->GetComponent(pixel, c)) > 0.05 / 255.0;
    }
    for (int c = 0; strays && c < p.Channels; ++c)
    {
      p.Judged->SetComponent(pixel, c, p.Model->GetComponent(pixel, c));
    }
    excused += strays ? 1 : 0;
  }
  return excused;
}

// The largest of |picture - reference| - |exact - reference| over every pixel and channel:
// how much further from the reference `picture` lies than `exact` does.
double LargestExcess(vtkImageData* picture, vtkImageData* exact, vtkImageData* reference)
{
  const ThreePictures p(picture, exact, reference);
  double largest = 0.0;
  for (vtkIdType pixel = 0; pixel < p.Judged->GetNumberOfTuples(); ++pixel)
  {
    for (int c = 0; c < p.Channels; ++c)
    {
      const double r = p.Model->GetComponent(pixel, c);
      const double excess = std::abs(p.Judged->GetComponent(pixel, c) - r) -
        std::abs(p.Own->GetComponent(pixel, c) - r);
      largest = std::max(largest, std::isnan(excess) ? HUGE_VAL : excess);
    }
  }
  return largest;
}

// What a frame of a scene chose and how far it strayed: the picture, in a float target,
// against vtkPhongReference shading the same render's G-buffer in double. Beyond `budget`,
// the pixels where the exact mode strays as well are excused (ExcuseDiscontinuities). Two
// frames of the same view are judged: a still scene's second may take the constants
// (UNIFORM_CONSTANTS) and their charge, so both answer to the second's bound, in the first's mode.
Outcome Measure(vtkPhongTest::Scene& view, vtkActor* actor, double budget)
{
  vtkNew<vtkPhongFloatRenderPass> pass;
  vtkNew<vtkPhongReference> reference;
  reference->SetRenderer(view.Renderer);
  reference->SetActor(actor);
  std::vector<vtkSmartPointer<vtkImageData>> pictures{ vtkPhongTest::RenderFloat(view, pass) };
  const Plan first = LastPlan(actor);
  pictures.push_back(vtkPhongTest::RenderFloat(view, pass));
  const Plan second = LastPlan(actor);
  Outcome outcome;
  outcome.Signature = first.Signature;
  outcome.Bound = second.Bound;
  outcome.Chosen = static_cast<Mode>(first.Mode);
  outcome.SquaredShininess = first.SquaredShininess;
  outcome.Reported =
    ReportMatchesShader(first) && ReportMatchesShader(second) && first.Mode == second.Mode;
  outcome.Constants = second.Signature.find("UNIFORM_CONSTANTS") != std::string::npos;
  auto exact = vtkPhongTest::ShadeGBuffer(view, pass, reference);
  vtkSmartPointer<vtkImageData> exactPicture;
  if (budget > 0.0)
  {
    // The exact mode's picture of the same frame (its planning leaves the budget's
    // hysteresis alone).
    SetBudget(actor, 0.0);
    exactPicture = vtkPhongTest::RenderFloat(view, pass);
    SetBudget(actor, budget);
  }
  outcome.Valid = outcome.Reported;
  for (const auto& picture : pictures)
  {
    auto measured = vtkPhongTest::MeasureAgainst(picture, exact, 1);
    if (budget > 0.0)
    {
      outcome.Departure =
        std::max(outcome.Departure, LargestExcess(picture, exactPicture, exact) * 255.0);
      if (measured.MaxAbsolute * 255.0 > budget)
      {
        outcome.Excused =
          std::max(outcome.Excused, ExcuseDiscontinuities(picture, exactPicture, exact));
        measured = vtkPhongTest::MeasureAgainst(picture, exact, 1);
      }
    }
    outcome.Error = std::max(outcome.Error, measured.MaxAbsolute * 255.0);
    outcome.Pixels = measured.ComparedPixels;
    outcome.Valid =
      outcome.Valid && measured.Valid && measured.NaNPixels == 0 && measured.InfPixels == 0;
  }
  return outcome;
}

// The BudgetUse view draws every pixel of the surface in one colour: the chosen mode's hue
// (blue per fragment, green the specular sums per vertex, orange every sum per vertex) at a
// brightness from 0.25 (nothing of the budget spent) to 1 (all of it). Checked on each
// case's frame, in a float target: every covered pixel the colour its mode and bound give.
// The bound is the drawn plan's: from a still scene's second frame on, the constants
// add their charge to what the case's first frame spent.
bool ShowsBudgetUse(vtkPhongTest::Scene& view, const Case& c, const Outcome& outcome)
{
  vtkNew<vtkPhongFloatRenderPass> pass;
  vtkPhongTest::SetDebugView(view, vtkPhongPolyDataMapper::BudgetUse);
  vtkSmartPointer<vtkImageData> picture = vtkPhongTest::RenderFloat(view, pass);
  vtkPhongTest::SetDebugView(view, vtkPhongPolyDataMapper::Final);
  const double drawn = LastPlan(view.Renderer->GetActors()->GetLastActor()).Bound;
  const double hues[3][3] = { { 0.0, 0.4, 1.0 }, { 0.0, 1.0, 0.3 }, { 1.0, 0.4, 0.0 } };
  const double share = c.Budget > 0.0 ? std::min(drawn / c.Budget, 1.0) : 0.0;
  double expected[3];
  for (int k = 0; k < 3; ++k)
  {
    expected[k] = (0.25 + 0.75 * share) * hues[outcome.Chosen][k];
  }
  if (!(drawn >= outcome.Bound && drawn <= std::max(c.Budget, outcome.Bound)))
  {
    std::cerr << c.Name << ": the BudgetUse frame's bound " << drawn << " levels, the case's "
              << outcome.Bound << "\n";
    return false;
  }
  vtkDataArray* colours = picture->GetPointData()->GetScalars();
  vtkIdType covered = 0, wrong = 0;
  for (vtkIdType p = 0; p < colours->GetNumberOfTuples(); ++p)
  {
    const double* pixel = colours->GetTuple(p);
    if (pixel[0] == 0.0 && pixel[1] == 0.0 && pixel[2] == 0.0)
    {
      continue; // the background
    }
    ++covered;
    for (int k = 0; k < 3; ++k)
    {
      wrong += std::abs(pixel[k] - expected[k]) > 1e-4 ? 1 : 0;
    }
  }
  if (covered == 0 || wrong > 0)
  {
    std::cerr << c.Name << ": the BudgetUse view shows " << wrong << " channels of " << covered
              << " pixels away from (" << expected[0] << ", " << expected[1] << ", " << expected[2]
              << ")\n";
    return false;
  }
  return true;
}

bool RunCase(const Case& c, vtkPolyData* file)
{
  vtkPhongTest::Scene view(c.WindowSize, c.WindowSize);
  view.Renderer->AutomaticLightCreationOff();
  view.Renderer->SetAmbient(0.3, 0.3, 0.3);
  view.Renderer->SetTwoSidedLighting(!c.OneSided);
  AddLights(view, c);
  vtkNew<vtkPhongProperty> material;
  material->SetColor(0.8, 0.6, 0.4);
  material->SetAmbient(0.1);
  material->SetDiffuse(0.7);
  material->SetSpecular(c.Specular);
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

  const Outcome outcome = Measure(view, actor, c.Budget);
  std::cout << c.Name << ": " << ModeNames[outcome.Chosen] << ", bound " << outcome.Bound
            << " levels, largest error " << outcome.Error << " levels over " << outcome.Pixels
            << " pixels (budget " << c.Budget << ")\n";
  const Mode mode = outcome.Chosen;
  const double bound = outcome.Bound, errorLevels = outcome.Error;
  const std::string& signature = outcome.Signature;
  bool ok = outcome.Valid;
  if (mode != c.Expected)
  {
    std::cerr << c.Name << ": expected " << ModeNames[c.Expected] << "; signature " << signature
              << "\n";
    ok = false;
  }
  // Under a budget a whole shininess from 2 to 1e3 raises the lobe by squaring; never in the
  // exact mode, nor under an attenuation without a constant term (no largest value to charge).
  const bool whole = c.Budget > 0.0 && c.Specular > 0.0 && c.Shininess >= 2.0 &&
    c.Shininess <= 1.0e3 && c.Shininess == std::floor(c.Shininess) && c.Attenuated != 2;
  if (outcome.SquaredShininess != (whole ? static_cast<int>(c.Shininess) : 0))
  {
    std::cerr << c.Name << ": " << (whole ? "expected" : "unexpected")
              << " a lobe by squaring; signature " << signature << "\n";
    ok = false;
  }
  // The exact mode's own float rounding is far below a level; a budget is a hard maximum.
  const double allowed = c.Budget > 0.0 ? c.Budget : 0.05;
  if (!outcome.Within(allowed) || !(bound <= std::max(c.Budget, 0.5)))
  {
    std::cerr << c.Name << ": error " << errorLevels << " levels beyond the budget " << allowed
              << ", or its excess over the exact picture's error " << outcome.Departure
              << " beyond the bound " << bound << ", or the bound beyond the budget\n";
    ok = false;
  }
  return ShowsBudgetUse(view, c, outcome) && ok;
}

// A camera on a sphere around the origin looking at it.
void PlaceCamera(vtkRenderer* renderer, double distance, double azimuth, double elevation)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(distance * std::sin(azimuth) * std::cos(elevation),
    distance * std::sin(elevation), distance * std::cos(azimuth) * std::cos(elevation));
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(30.0);
  renderer->ResetCameraClippingRange();
}

// RunRandom's second generator's scenes: more lights of every kind, a normalized lobe, other
// shininesses, some not whole.
void AddVariety(vtkPhongTest::Scene& view, vtkPhongProperty* material, std::mt19937& extra)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  if (extra() % 6 == 0)
  {
    const double origin[3] = { 0.0, 0.0, 0.0 };
    for (int i = 0; i < 24; ++i)
    {
      const double position[3] = { 4.0 * unit(extra) - 2.0, 4.0 * unit(extra) - 2.0,
        3.0 * unit(extra) - 0.5 };
      const double color[3] = { unit(extra), unit(extra), unit(extra) };
      const int kind = static_cast<int>(extra() % 4); // directional, point, spot, headlight
      vtkLight* light = vtkPhongTest::AddLight(view, position, origin, color,
        kind == 1 || kind == 2, kind == 3 ? VTK_LIGHT_TYPE_HEADLIGHT : VTK_LIGHT_TYPE_SCENE_LIGHT);
      light->SetIntensity(0.05 + 0.05 * unit(extra));
      light->SetConeAngle(kind == 2 ? 20.0 + 40.0 * unit(extra) : 180.0);
      light->SetExponent(kind == 2 ? 1.0 + 4.0 * unit(extra) : 1.0);
      light->SetAttenuationValues(1.0, 0.5 * unit(extra), 0.5 * unit(extra));
    }
    material->SetSoftSpotEdge(extra() % 2 == 0);
  }
  if (extra() % 4 == 0)
  {
    material->SetLightingModel(
      extra() % 2 ? vtkPhongProperty::NormalizedBlinnPhong : vtkPhongProperty::NormalizedPhong);
  }
  if (extra() % 8 == 0)
  {
    material->SetShininess(extra() % 2 ? 30.0 : 1.0e4);
  }
  // Not whole, the lobes keep pow per fragment, against which the specular sums per vertex pay
  // from two lobes (squared, from 20): the sweep reaches that mode.
  if (extra() % 4 == 0)
  {
    material->SetShininess(material->GetShininess() + 0.5);
  }
}

// Random scenes from a fixed seed, each frame within its budget with no exception: a sphere
// of 16 to 256 rows, an ellipsoid (its normals transformed) or CGAL's bunny00 (normals
// computed by the mapper); 1 to 8 directional lights of random directions, colours and
// intensities, and in one scene of four a point or spot light; n from 1 to 1e3, Blinn or
// Phong; one- or two-sided; parallel or perspective from 1.6 to 8 radii (nearer more often);
// the actor turned and scaled (a similarity), in one scene of eight stretched (not one);
// windows of 240 to 480 pixels; budgets of 0.25 to 8 levels. A second generator adds, without
// changing those draws: in one scene of six 24 dim lights more of every kind (attenuated
// points, spots with falloff exponents and hard or soft edges, a headlight), in one of eight a
// point light just off the surface, in one of four a normalized lobe, in one of eight n = 30
// or 1e4, in one of four n + 0.5. Counts how often each mode was chosen.
bool RunRandom(int count, unsigned seed, vtkPolyData* bunny)
{
  std::mt19937 random(seed);
  std::mt19937 extra(seed + 7919);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double shininess[] = { 1.0, 10.0, 40.0, 200.0, 1.0e3 };
  const double budgets[] = { 0.25, 0.5, 1.0, 2.0, 4.0, 8.0 };
  const int rows[] = { 16, 64, 128, 160, 192, 256 };
  int chosen[3] = { 0, 0, 0 };
  vtkIdType excused = 0;
  int constants = 0;
  bool ok = true;
  for (int index = 0; index < count; ++index)
  {
    const double budget = budgets[random() % 6];
    const int size = 240 + static_cast<int>(random() % 5) * 60;
    vtkPhongTest::Scene view(size, size);
    view.Renderer->AutomaticLightCreationOff();
    view.Renderer->SetAmbient(0.2 * unit(random), 0.2 * unit(random), 0.2 * unit(random));
    view.Renderer->SetTwoSidedLighting(random() % 2 == 0);
    const int lights = 1 + static_cast<int>(random() % 8);
    const double origin[3] = { 0.0, 0.0, 0.0 };
    for (int i = 0; i < lights; ++i)
    {
      const double position[3] = { 2.0 * unit(random) - 1.0, 2.0 * unit(random) - 1.0,
        2.0 * unit(random) - 0.5 };
      const double color[3] = { 0.5 + 0.5 * unit(random), 0.5 + 0.5 * unit(random),
        0.5 + 0.5 * unit(random) };
      vtkPhongTest::AddLight(view, position, origin, color, false)
        ->SetIntensity((0.3 + unit(random)) / lights);
    }
    if (random() % 4 == 0)
    {
      const double position[3] = { 0.3, 0.8, 1.2 };
      const double white[3] = { 1.0, 1.0, 1.0 };
      vtkLight* positional = vtkPhongTest::AddLight(view, position, origin, white, true);
      positional->SetConeAngle(random() % 2 ? 30.0 : 180.0);
      positional->SetIntensity(0.4);
      // Attenuated in one case of two (drawn from `extra`: `random`'s draws stay as they were).
      if (extra() % 2 == 0)
      {
        positional->SetAttenuationValues(0.3 + unit(extra), 0.5 * unit(extra), 0.5 * unit(extra));
      }
    }
    vtkNew<vtkPhongProperty> material;
    material->SetColor(unit(random), unit(random), unit(random));
    material->SetAmbient(0.2 * unit(random));
    material->SetDiffuse(0.3 + 0.7 * unit(random));
    material->SetSpecular(random() % 5 == 0 ? 0.0 : unit(random));
    material->SetShininess(shininess[random() % 5]);
    material->SetLightingModel(
      random() % 2 ? vtkPhongProperty::BlinnPhong : vtkPhongProperty::Phong);
    material->SetInterpolationToPhong();
    AddVariety(view, material, extra);
    const int shape = static_cast<int>(random() % 6);
    vtkSmartPointer<vtkPolyData> mesh = shape < 4 ? vtkPhongTest::MakeSphere(rows[random() % 6])
      : shape == 4                                ? vtkPhongTest::MakeSphere(rows[random() % 6])
                                                  : vtkSmartPointer<vtkPolyData>(bunny);
    if (shape == 4)
    {
      vtkNew<vtkTransform> stretch;
      stretch->Scale(1.0, 0.6, 0.8);
      vtkNew<vtkTransformPolyDataFilter> filter;
      filter->SetTransform(stretch);
      filter->SetInputData(mesh);
      filter->Update();
      mesh = filter->GetOutput();
    }
    vtkActor* actor = vtkPhongTest::AddActor(view, mesh);
    auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper());
    mapper->SetErrorBudget(budget);
    actor->SetProperty(material);
    actor->RotateWXYZ(360.0 * unit(random), unit(random), unit(random), unit(random) + 0.1);
    const double scale = 0.7 + 0.6 * unit(random);
    actor->SetScale(scale, scale, random() % 8 == 0 ? 1.3 * scale : scale);
    double bounds[6];
    mesh->GetBounds(bounds);
    actor->SetOrigin(
      (bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2);
    actor->SetPosition(-actor->GetOrigin()[0], -actor->GetOrigin()[1], -actor->GetOrigin()[2]);
    const double radius =
      0.5 * scale * std::sqrt(vtkMath::Distance2BetweenPoints(bounds, bounds + 3));
    const bool parallel = random() % 2 == 0;
    PlaceCamera(view.Renderer, radius * (1.6 + 6.4 * unit(random) * unit(random)),
      6.283 * unit(random), 1.2 * unit(random) - 0.6);
    view.Renderer->GetActiveCamera()->SetParallelProjection(parallel);
    view.Renderer->GetActiveCamera()->SetParallelScale(radius * (0.8 + unit(random)));
    view.Renderer->ResetCameraClippingRange();
    if (extra() % 8 == 0)
    {
      const double near[3] = { 0.7 * radius, 0.3 * radius, 0.75 * radius };
      const double warm[3] = { 1.0, 0.9, 0.8 };
      vtkPhongTest::AddLight(view, near, origin, warm, true)->SetIntensity(0.2);
    }
    const Outcome outcome = Measure(view, actor, budget);
    excused += outcome.Excused;
    constants += outcome.Constants ? 1 : 0;
    ++chosen[outcome.Chosen];
    if (!outcome.Valid || !outcome.Within(budget) || !(outcome.Bound <= budget))
    {
      std::cerr << "random scene " << index << " (seed " << seed
                << "): " << ModeNames[outcome.Chosen] << ", bound " << outcome.Bound << ", error "
                << outcome.Error << " levels, budget " << budget << ", valid " << outcome.Valid
                << "; " << outcome.Signature << "\n";
      ok = false;
    }
  }
  std::cout << count << " random scenes (seed " << seed << "): " << chosen[PerFragment]
            << " per fragment, " << chosen[SpecularPerVertex] << " specular per vertex, "
            << chosen[PerVertex] << " per vertex; " << constants
            << " with constants in their second frame; " << excused
            << " pixels excused (the exact mode strays there too)\n";
  if (count >= 20 && constants == 0)
  {
    std::cerr << "no random scene took the constants\n";
    ok = false;
  }
  // A long sweep must reach both per-vertex modes (about 1 and 5 scenes in 100 take them;
  // the fixed cases above expect each mode by name).
  const bool reached = count < 500 || (chosen[PerVertex] > 0 && chosen[SpecularPerVertex] > 0);
  if (!reached)
  {
    std::cerr << "the random scenes did not reach the per-vertex modes\n";
    ok = false;
  }
  return ok;
}

// A camera turning around a sphere of 192 rows and moving in and out (1.6 to 7 radii,
// perspective) under 3 directional lights, budget 1.5 levels, shininess 40.5 (pow per
// fragment, against which the specular mode pays from two lobes): the view vector's spread and
// the covered fragments change, and with them the mode. Every frame within the budget; at
// least two modes seen.
bool RunOrbit(int frames)
{
  vtkPhongTest::Scene view(400, 400);
  Case c = { "orbit", 192, 400, 3, false, 40.5, true, false, 1.5, PerFragment };
  view.Renderer->AutomaticLightCreationOff();
  view.Renderer->SetAmbient(0.3, 0.3, 0.3);
  AddLights(view, c);
  vtkNew<vtkPhongProperty> material;
  material->SetColor(0.8, 0.6, 0.4);
  material->SetDiffuse(0.7);
  material->SetSpecular(0.5);
  material->SetShininess(c.Shininess);
  material->SetLightingModelToBlinnPhong();
  material->SetInterpolationToPhong();
  vtkActor* actor = AddSurface(view, c, vtkPhongTest::MakeSphere(c.Resolution));
  actor->SetProperty(material);
  int seen[3] = { 0, 0, 0 };
  int switches = 0;
  vtkIdType excused = 0;
  Mode last = PerFragment;
  bool ok = true;
  for (int frame = 0; frame < frames; ++frame)
  {
    const double phase = 6.283185307 * frame / frames;
    PlaceCamera(
      view.Renderer, 0.5 * (5.5 - 3.0 * std::cos(2.0 * phase)), phase, 0.3 * std::sin(phase));
    const Outcome outcome = Measure(view, actor, c.Budget);
    excused += outcome.Excused;
    ++seen[outcome.Chosen];
    switches += frame > 0 && outcome.Chosen != last ? 1 : 0;
    last = outcome.Chosen;
    if (!outcome.Valid || !outcome.Within(c.Budget))
    {
      std::cerr << "orbit frame " << frame << ": " << ModeNames[outcome.Chosen] << ", bound "
                << outcome.Bound << ", error " << outcome.Error << " levels\n";
      ok = false;
    }
  }
  std::cout << "orbit, " << frames << " frames: " << seen[PerFragment] << " per fragment, "
            << seen[SpecularPerVertex] << " specular per vertex, " << seen[PerVertex]
            << " per vertex, " << switches << " switches; " << excused
            << " pixels excused (the exact mode strays there too)\n";
  if ((seen[0] > 0) + (seen[1] > 0) + (seen[2] > 0) < 2)
  {
    std::cerr << "the orbit crossed no decision threshold\n";
    ok = false;
  }
  return ok;
}

// The value after `flag` in argv, or `fallback`.
// The squaring's own rounding, which vtkPhongErrorBudget::WholePowerError charges as gamma_n =
// n u / (1 - n u) of the lobe (each product's rounding raised to the factors it enters), in
// at most 2 floor(log2 n) + 1 products: the statements the shader runs
// (vtkPhongShaderTemplate::WholePowerSteps) carried out in float for every n from 2 to 1000 on
// 100 values of x each (random in [0, 1], near 1, tiny, 0 and 1), against x^n in double.
// Below float's normal range a flush to 0 may take up to 2^-126 more (llvmpipe's), far below
// a level.
bool CheckWholePowerRounding()
{
  std::mt19937 random(1000);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double u = std::ldexp(1.0, -24);
  double worst = 0.0;
  int evaluated = 0;
  bool ok = true;
  for (int n = 2; n <= 1000; ++n)
  {
    const std::string steps = vtkPhongShaderTemplate::WholePowerSteps(n);
    int products = 0, most = 1; // 2 floor(log2 n) + 1
    for (std::size_t at = steps.find("*="); at != std::string::npos; at = steps.find("*=", at + 2))
    {
      ++products;
    }
    for (int k = n; k > 1; k >>= 1)
    {
      most += 2;
    }
    if (products == 0 || products > most)
    {
      std::cerr << "n = " << n << ": " << products << " products, more than " << most << ": "
                << steps << "\n";
      ok = false;
      continue;
    }
    const double gamma = n * u / (1.0 - n * u);
    for (int trial = 0; trial < 100; ++trial)
    {
      const double r = unit(random);
      const float x0 = static_cast<float>(trial == 0 ? 0.0
          : trial == 1                               ? 1.0
          : trial % 4 == 0                           ? 1.0 - 1.0e-3 * r
          : trial % 7 == 0                           ? 1.0e-3 * r
                                                     : r);
      // The statements, one by one: "power *= x;" and "x *= x;".
      float x = x0, power = 1.0f;
      std::istringstream statements(steps);
      for (std::string target, operation, operand; statements >> target >> operation >> operand;)
      {
        (target == "power" ? power : x) *= x;
      }
      const double exact = std::pow(static_cast<double>(x0), n);
      const double error = std::abs(static_cast<double>(power) - exact);
      ++evaluated;
      if (error > gamma * exact + std::ldexp(1.0, -126))
      {
        std::cerr << "x^" << n << " for x = " << x0 << ": " << power << " against " << exact
                  << ", beyond gamma_" << n << "\n";
        ok = false;
      }
      worst = exact > 1.0e-30 ? std::max(worst, error / (gamma * exact)) : worst;
    }
  }
  std::cout << "the squaring's rounding: " << evaluated
            << " powers, n from 2 to 1000, largest error / charge " << worst << "\n";
  return ok;
}

// Issue 27's scene matrix, every pair of its factors' values in at least one scene (a greedy
// pairwise cover; the whole product is 72 576 scenes): the mesh (sphere 64 and 256, torus 128,
// CGAL's bunny00 and refined_elephant with normals the mapper computes, a box), the lights (a
// headlight, 8 directional, 8 mixed, 32 mixed, spots with hard and with soft edges, a point
// light just off the surface), n in {1, 10, 40, 200, 1e3, 1e4}, Phong or Blinn, plain or
// normalized, one- or two-sided, parallel or perspective, median triangles of about 0.5, 4
// and 30 px, budgets of 0.25, 0.5, 1 and 2 levels. Every frame within its budget.
struct MatrixScene
{
  int Mesh, Lights, Shininess, Blinn, Normalized, TwoSided, Perspective, Size, Budget;
};

const char* MatrixMeshes[] = { "sphere 64", "sphere 256", "torus 128", "bunny00",
  "refined_elephant", "box" };
const char* MatrixLights[] = { "headlight", "8 directional", "8 mixed", "32 mixed", "hard spots",
  "soft spots", "near point" };
const double MatrixShininess[] = { 1.0, 10.0, 40.0, 200.0, 1.0e3, 1.0e4 };
const double MatrixSizes[] = { 0.5, 4.0, 30.0 };
const double MatrixBudgets[] = { 0.25, 0.5, 1.0, 2.0 };

// Greedy: each scene the one of 64 random candidates that covers the most pairs not yet
// covered, until every pair is.
std::vector<MatrixScene> PairwiseScenes()
{
  const std::array<int, 9> levels = { 6, 7, 6, 2, 2, 2, 2, 3, 4 };
  std::vector<std::vector<std::vector<char>>> covered(9);
  int uncovered = 0;
  for (int a = 0; a < 9; ++a)
  {
    covered[a].resize(9);
    for (int b = a + 1; b < 9; ++b)
    {
      covered[a][b].assign(levels[a] * levels[b], 0);
      uncovered += levels[a] * levels[b];
    }
  }
  std::mt19937 random(2711);
  std::vector<MatrixScene> scenes;
  while (uncovered > 0)
  {
    std::array<int, 9> best{};
    int bestGain = -1;
    for (int candidate = 0; candidate < 64; ++candidate)
    {
      std::array<int, 9> values;
      for (int a = 0; a < 9; ++a)
      {
        values[a] = static_cast<int>(random() % levels[a]);
      }
      int gain = 0;
      for (int a = 0; a < 9; ++a)
      {
        for (int b = a + 1; b < 9; ++b)
        {
          gain += covered[a][b][values[a] * levels[b] + values[b]] ? 0 : 1;
        }
      }
      if (gain > bestGain)
      {
        bestGain = gain;
        best = values;
      }
    }
    for (int a = 0; a < 9; ++a)
    {
      for (int b = a + 1; b < 9; ++b)
      {
        char& pair = covered[a][b][best[a] * levels[b] + best[b]];
        uncovered -= pair ? 0 : 1;
        pair = 1;
      }
    }
    scenes.push_back(
      { best[0], best[1], best[2], best[3], best[4], best[5], best[6], best[7], best[8] });
  }
  return scenes;
}

// The matrix's meshes, centred at the origin with a bounding radius of 1.
vtkSmartPointer<vtkPolyData> MatrixMesh(int mesh, const std::string& meshDirectory)
{
  vtkSmartPointer<vtkPolyData> shape;
  if (mesh <= 1)
  {
    shape = vtkPhongTest::MakeSphere(mesh == 0 ? 64 : 256, 1.0);
  }
  else if (mesh == 2)
  {
    shape = vtkPhongTest::MakeTorus(0.7, 0.3, 128, 64);
  }
  else if (mesh <= 4)
  {
    vtkNew<vtkPhongOFFReader> reader;
    reader->SetFileName(
      (meshDirectory + (mesh == 3 ? "/bunny00.off" : "/refined_elephant.off")).c_str());
    reader->Update();
    shape = reader->GetOutput();
  }
  else
  {
    // Faces of 16 x 16 squares, each face's points its own (flat normals, sharp edges).
    vtkNew<vtkTessellatedBoxSource> box;
    box->SetLevel(16);
    box->QuadsOff();
    box->DuplicateSharedPointsOn();
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputConnection(box->GetOutputPort());
    normals->SplittingOff();
    normals->Update();
    shape = normals->GetOutput();
  }
  double bounds[6];
  shape->GetBounds(bounds);
  vtkNew<vtkTransform> fit;
  const double radius = 0.5 * std::sqrt(vtkMath::Distance2BetweenPoints(bounds, bounds + 3));
  fit->Scale(1.0 / radius, 1.0 / radius, 1.0 / radius);
  fit->Translate(
    -0.5 * (bounds[0] + bounds[1]), -0.5 * (bounds[2] + bounds[3]), -0.5 * (bounds[4] + bounds[5]));
  vtkNew<vtkTransformPolyDataFilter> filter;
  filter->SetTransform(fit);
  filter->SetInputData(shape);
  filter->Update();
  return filter->GetOutput();
}

// The median triangle area of a mesh (its polygons fanned as VTK draws them).
double MedianTriangleArea(vtkPolyData* mesh)
{
  std::vector<double> areas;
  vtkNew<vtkIdList> ids;
  auto polys = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    polys->GetCurrentCell(ids);
    double p0[3], p1[3], p2[3];
    mesh->GetPoint(ids->GetId(0), p0);
    for (vtkIdType t = 1; t + 1 < ids->GetNumberOfIds(); ++t)
    {
      mesh->GetPoint(ids->GetId(t), p1);
      mesh->GetPoint(ids->GetId(t + 1), p2);
      areas.push_back(vtkTriangle::TriangleArea(p0, p1, p2));
    }
  }
  std::nth_element(areas.begin(), areas.begin() + areas.size() / 2, areas.end());
  return areas[areas.size() / 2];
}

// The matrix's light sets around a mesh of radius 1 at the origin; `top` the mesh's point
// nearest +z's axis from above (the near point light sits just off it).
void AddMatrixLights(vtkPhongTest::Scene& view, int set, const double top[3])
{
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  if (set == 0)
  {
    vtkPhongTest::AddLight(view, origin, origin, white, false, VTK_LIGHT_TYPE_HEADLIGHT);
    return;
  }
  if (set == 6)
  {
    const double near[3] = { 1.04 * top[0], 1.04 * top[1], 1.04 * top[2] + 0.02 };
    vtkPhongTest::AddLight(view, near, origin, white, true)->SetIntensity(0.3);
    const double key[3] = { 1.0, 1.0, 2.0 };
    vtkPhongTest::AddLight(view, key, origin, white, false)->SetIntensity(0.5);
    return;
  }
  const int count = set == 3 ? 32 : set <= 2 ? 8 : 3;
  for (int i = 0; i < count; ++i)
  {
    const double angle = 6.283185307 * i / count + 0.3;
    const double color[3] = { 0.6 + 0.4 * std::cos(angle), 0.8, 0.6 + 0.4 * std::sin(angle) };
    // Directional first, then points, then spots (mixed: half, a quarter, a quarter).
    const bool spot = set >= 4 || (set >= 2 && 4 * i >= 3 * count);
    const bool point = !spot && set >= 2 && 2 * i >= count;
    const double distance = spot ? 3.0 : 2.1;
    const double position[3] = { distance * std::cos(angle), distance * std::sin(angle), distance };
    // Spots aimed off the centre, so that their cones' edges cross the mesh.
    const double aim[3] = { 0.5 * std::cos(angle + 1.0), 0.5 * std::sin(angle + 1.0), 0.0 };
    vtkLight* light =
      vtkPhongTest::AddLight(view, position, spot ? aim : origin, color, spot || point);
    light->SetIntensity((set >= 4 ? 1.2 : 2.0) / count);
    light->SetConeAngle(spot ? 14.0 : 180.0);
    light->SetExponent(spot ? 2.0 : 1.0);
    if (point || spot)
    {
      light->SetAttenuationValues(0.5, 0.1, 0.05);
    }
  }
}

bool RunMatrixScene(const MatrixScene& m, vtkPolyData* mesh, double medianArea, int index)
{
  constexpr int Pixels = 400;
  vtkPhongTest::Scene view(Pixels, Pixels);
  view.Renderer->AutomaticLightCreationOff();
  view.Renderer->SetAmbient(0.15, 0.15, 0.15);
  view.Renderer->SetTwoSidedLighting(m.TwoSided != 0);
  double top[3] = { 0.0, 0.0, 1.0 };
  double highest = -1.0e300;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    if (p[0] * p[0] + p[1] * p[1] < 0.04 && p[2] > highest)
    {
      highest = p[2];
      std::copy(p, p + 3, top);
    }
  }
  AddMatrixLights(view, m.Lights, top);
  vtkNew<vtkPhongProperty> material;
  material->SetColor(0.8, 0.6, 0.4);
  material->SetAmbient(0.2);
  material->SetDiffuse(0.7);
  material->SetSpecular(0.5);
  material->SetShininess(MatrixShininess[m.Shininess]);
  material->SetLightingModel(m.Normalized
      ? (m.Blinn ? vtkPhongProperty::NormalizedBlinnPhong : vtkPhongProperty::NormalizedPhong)
      : (m.Blinn ? vtkPhongProperty::BlinnPhong : vtkPhongProperty::Phong));
  material->SetInterpolationToPhong();
  material->SetSoftSpotEdge(m.Lights == 5);
  vtkActor* actor = vtkPhongTest::AddActor(view, mesh, material);
  const double budget = MatrixBudgets[m.Budget];
  vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper())->SetErrorBudget(budget);
  // Pixels per unit at the surface facing the camera that make the median triangle, about 0.6
  // of its area facing the view, cover the size wanted.
  const double perUnit = std::sqrt(MatrixSizes[m.Size] / (0.6 * medianArea));
  vtkCamera* camera = view.Renderer->GetActiveCamera();
  const double direction[3] = { 0.30, 0.25, 0.92 };
  const double surface = 1.0; // the mesh's bounding radius: its nearest surface is within it
  const double distance = m.Perspective ? surface +
      std::max(Pixels / (2.0 * std::tan(vtkMath::RadiansFromDegrees(15.0)) * perUnit), 0.3)
                                        : 4.0;
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(distance * direction[0], distance * direction[1], distance * direction[2]);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(30.0);
  camera->SetParallelProjection(m.Perspective == 0);
  camera->SetParallelScale(Pixels / (2.0 * perUnit));
  view.Renderer->ResetCameraClippingRange();
  const Outcome outcome = Measure(view, actor, budget);
  std::cout << "matrix " << index << ": " << MatrixMeshes[m.Mesh] << ", " << MatrixLights[m.Lights]
            << ", n " << MatrixShininess[m.Shininess] << (m.Normalized ? " normalized" : "")
            << (m.Blinn ? " Blinn" : " Phong") << (m.TwoSided ? ", two-sided" : ", one-sided")
            << (m.Perspective ? ", perspective" : ", parallel") << ", about " << MatrixSizes[m.Size]
            << " px triangles, budget " << budget << ": " << ModeNames[outcome.Chosen] << ", bound "
            << outcome.Bound << ", error " << outcome.Error << " over " << outcome.Pixels
            << " pixels\n";
  const bool ok =
    outcome.Valid && outcome.Within(budget) && outcome.Bound <= budget && outcome.Pixels > 0;
  if (!ok)
  {
    std::cerr << "matrix scene " << index << " broke its budget (or drew nothing); "
              << outcome.Signature << "\n";
  }
  return ok;
}

bool RunMatrix(const std::string& meshDirectory)
{
  const std::vector<MatrixScene> scenes = PairwiseScenes();
  std::vector<vtkSmartPointer<vtkPolyData>> meshes;
  std::vector<double> medianAreas;
  for (int mesh = 0; mesh < 6; ++mesh)
  {
    meshes.push_back(MatrixMesh(mesh, meshDirectory));
    medianAreas.push_back(MedianTriangleArea(meshes.back()));
  }
  bool ok = true;
  for (std::size_t i = 0; i < scenes.size(); ++i)
  {
    ok = RunMatrixScene(
           scenes[i], meshes[scenes[i].Mesh], medianAreas[scenes[i].Mesh], static_cast<int>(i)) &&
      ok;
  }
  std::cout << "scene matrix: " << scenes.size() << " scenes cover every pair of values\n";
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
    { "exact, budget 0", 128, 600, 3, false, 40.0, true, true, 0.0, PerFragment },
    { "sphere 128, 3 lights, Blinn 40, 3 levels", 128, 600, 3, false, 40.0, true, true, 3.0,
      PerVertex },
    { "sphere 128, 3 lights, Phong 40, perspective, 10 levels", 128, 600, 3, false, 40.0, false,
      false, 10.0, PerVertex },
    { "sphere 128, 8 lights, Blinn 10, perspective, 6 levels", 128, 600, 8, false, 10.0, true,
      false, 6.0, PerVertex },
    { "sphere 128, 2 lights, Blinn 200, 8 levels", 128, 600, 2, false, 200.0, true, true, 8.0,
      PerVertex },
    // A shininess that is not whole keeps pow per fragment, against which the specular sums per
    // vertex pay from two lobes; against lobes squared per fragment, from 20.
    { "sphere 128, 3 lights, Blinn 40.5, 2 levels: the terminator's kink does not fit", 128, 600, 3,
      false, 40.5, true, true, 2.0, SpecularPerVertex },
    { "sphere 128, 3 lights, Blinn 40, 2 levels: 3 squared lobes cost less per fragment", 128, 600,
      3, false, 40.0, true, true, 2.0, PerFragment },
    { "sphere 256, 24 lights, Blinn 40, 0.5 level: 24 squared lobes cost more per fragment", 256,
      600, 24, false, 40.0, true, true, 0.5, SpecularPerVertex },
    { "sphere 128, 3 lights, Blinn 40, 1 level: the lobe does not fit", 128, 600, 3, false, 40.0,
      true, true, 1.0, PerFragment },
    { "sphere 256, 3 lights, Blinn 40.5, 1 level", 256, 600, 3, false, 40.5, true, true, 1.0,
      SpecularPerVertex },
    // Issue 13's 8 lights: each of an eighth of the light, every sum fits per vertex.
    { "sphere 256, 8 lights, Blinn 40, perspective, 1 level", 256, 600, 8, false, 40.0, true, false,
      1.0, PerVertex },
    { "sphere 256, 8 lights, Phong 40, one-sided, 1 level", 256, 600, 8, false, 40.0, false, true,
      1.0, PerVertex, false, true },
    { "sphere 256, 3 lights, Blinn 40.5, one-sided, perspective, 1 level", 256, 600, 3, false, 40.5,
      true, false, 1.0, SpecularPerVertex, false, true },
    { "sphere 256, 3 lights, Blinn 40.5, 0.5 level", 256, 600, 3, false, 40.5, true, true, 0.5,
      SpecularPerVertex },
    { "sphere 64, no specular, 0.25 level: no lobes to move per vertex", 64, 600, 3, false, 40.0,
      true, false, 0.25, PerFragment, false, false, 0.0 },
    { "sphere 128, one light, Blinn 40, 2 levels: one lobe does not pay", 128, 600, 1, false, 40.0,
      true, true, 2.0, PerFragment },
    { "coarse sphere 24, 0.25 level: does not fit", 24, 600, 3, false, 40.0, true, true, 0.25,
      PerFragment },
    { "sub-pixel sphere 400 in 150 px: costs more", 400, 150, 3, false, 40.0, true, true, 2.0,
      PerFragment },
    // A point light without attenuation is bounded: its direction's spread over a triangle.
    { "sphere 128, 2 lights and a point light, Blinn 40, perspective, 6 levels", 128, 600, 2, true,
      40.0, true, false, 6.0, PerVertex },
    { "sphere 128, 2 lights and a point light, Phong 40, 8 levels", 128, 600, 2, true, 40.0, false,
      true, 8.0, PerVertex },
    // An attenuated point light is bounded with its attenuation's change over a triangle,
    // where it has a constant term (the largest attenuation bounds the float margin).
    { "an attenuated point light, 3 levels", 128, 600, 2, true, 40.0, true, true, 3.0, PerFragment,
      false, false, 0.5, 1 },
    { "an attenuated point light, perspective, 8 levels", 128, 600, 2, true, 40.0, true, false, 8.0,
      PerVertex, false, false, 0.5, 1 },
    { "a point light attenuated without a constant term: not bounded", 128, 600, 2, true, 40.0,
      true, true, 8.0, PerFragment, false, false, 0.5, 2 },
    { "sphere 128, 3 lights, Blinn 40.5, 1 level: not a whole shininess", 128, 600, 3, false, 40.5,
      true, true, 1.0, PerFragment },
    { "composite, two blocks, sphere 128, 3 lights, Blinn 40, 3 levels", 128, 600, 3, false, 40.0,
      true, true, 3.0, PerVertex, true },
    { "composite, two blocks, sphere 128, 3 lights, Blinn 40.5, 2 levels", 128, 600, 3, false, 40.5,
      true, true, 2.0, SpecularPerVertex, true },
    // Actors that hand the mapper an internal actor without bounds (vtkFollower: vedo 2023's
    // meshes; vtkLODActor) decide as a vtkActor does.
    { "a vtkFollower, sphere 128, 3 lights, Blinn 40, 3 levels", 128, 600, 3, false, 40.0, true,
      true, 3.0, PerVertex, false, false, 0.5, 0, vtkPhongTest::ActorKind::Follower },
    { "a vtkLODActor, sphere 128, 3 lights, Blinn 40, 3 levels", 128, 600, 3, false, 40.0, true,
      true, 3.0, PerVertex, false, false, 0.5, 0, vtkPhongTest::ActorKind::LOD },
    { "a vtkFollower, composite, sphere 128, 3 lights, Blinn 40.5, 2 levels", 128, 600, 3, false,
      40.5, true, true, 2.0, SpecularPerVertex, true, false, 0.5, 0,
      vtkPhongTest::ActorKind::Follower },
    { "bunny00, computed normals, 3 lights, Blinn 40, 2 levels", 0, 600, 3, false, 40.0, true,
      false, 2.0, PerFragment },
    // The scan's noisy normals make the bound 125 levels: only a huge budget goes per vertex,
    // which still exercises the computed normals on the per-vertex path.
    { "bunny00, computed normals, 3 lights, Blinn 40, 200 levels", 0, 1000, 3, false, 40.0, true,
      false, 200.0, PerVertex },
  };
  bool ok = CheckWholePowerRounding();
  for (const Case& c : cases)
  {
    ok = RunCase(c, reader->GetOutput()) && ok;
  }
  // ctest runs a quick, fixed-seed subset; ./vtkphong.sh budget-sweep runs 1000 scenes.
  ok = RunRandom(vtkPhongTest::IntegerOption(argc, argv, "--random", 40),
         vtkPhongTest::IntegerOption(argc, argv, "--seed", 27), reader->GetOutput()) &&
    ok;
  ok = RunOrbit(vtkPhongTest::IntegerOption(argc, argv, "--orbit", 120)) && ok;
  if (vtkPhongTest::IntegerOption(argc, argv, "--matrix", 1) != 0)
  {
    const std::string file = argv[1];
    ok = RunMatrix(file.substr(0, file.find_last_of('/'))) && ok;
  }
  return ok ? 0 : 1;
}
