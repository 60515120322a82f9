// Specular anti-aliasing (vtkPhongLightingSettings::SpecularAntiAliasing) against what a
// pixel should show: the average of the exact model over the pixel, 16 samples computed in
// double (vtkPhongReference shading the G-buffer of a window 4x as wide and high, averaged
// over each pixel's 4 x 4 samples). A tessellated sphere of 130k triangles, specular only,
// one directional light whose highlight moves 0.1 px a frame (--frames N, default 24):
// - narrow lobes (n = 1e3 and 1e4 on spheres of 40 and 120 px radius, Blinn; n = 1e3 Phong):
//   the filtered picture's RMS and largest error, and its flicker (the frame-to-frame change
//   less the reference's), at least 5x lower than one exact sample per pixel (the flicker
//   only where one sample flickers at all: above 0.01 level RMS); the
//   highlight's energy no less steady than twice the reference's plus 0.01 (its coefficient
//   of variation over the frames);
// - a wide lobe (n = 40 on the 120 px sphere): the filter changes nothing that shows, at
//   most 0.05 level RMS;
// - off (the default), the shader carries no trace of it; on, its program is its own; under
//   an error budget the sums stay per fragment (the budget is defined without the filter).
#include "vtkPhongReferenceTesting.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkPhongPolyDataMapper.h"
#include "vtkPhongProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace
{
constexpr int SamplesPerSide = 4;  // 16 samples a pixel
constexpr double NoFlicker = 0.01; // levels RMS: far below what shows

struct Case
{
  const char* Name;
  double RadiusPixels;
  double Shininess;
  bool Phong;
};

// One view of the lit sphere: the window, its mapper and light.
struct View
{
  vtkPhongTest::Scene Scene;
  vtkPhongPolyDataMapper* Mapper = nullptr;
  vtkLight* Light = nullptr;

  // size: this window's; coarseSize: the one-sample view's, whose pixels this one's match
  // (a multiple of its size: that many samples a side in each of its pixels).
  View(const Case& c, int size, int coarseSize, vtkPolyData* sphere)
    : Scene(size, size)
  {
    this->Scene.Renderer->AutomaticLightCreationOff();
    this->Scene.Renderer->SetAmbient(0.0, 0.0, 0.0);
    const double white[3] = { 1.0, 1.0, 1.0 }, origin[3] = { 0.0, 0.0, 0.0 };
    const double up[3] = { 0.0, 0.0, 1.0 };
    this->Light = vtkPhongTest::AddLight(this->Scene, up, origin, white, false);
    vtkNew<vtkPhongProperty> material;
    material->SetColor(1.0, 1.0, 1.0);
    material->SetAmbient(0.0);
    material->SetDiffuse(0.0);
    material->SetSpecular(1.0);
    material->SetShininess(c.Shininess);
    material->SetLightingModel(c.Phong ? vtkPhongProperty::Phong : vtkPhongProperty::BlinnPhong);
    material->SetInterpolationToPhong();
    vtkActor* actor = vtkPhongTest::AddActor(this->Scene, sphere);
    actor->SetProperty(material);
    this->Mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper());
    // Parallel, the sphere (radius 0.5) c.RadiusPixels in radius in the coarse view: the
    // half height is coarseSize / 2 pixels, at 2 c.RadiusPixels pixels a unit.
    this->Scene.LookFromZ(3.0);
    vtkCamera* camera = this->Scene.Renderer->GetActiveCamera();
    camera->SetParallelProjection(true);
    camera->SetParallelScale(coarseSize / (4.0 * c.RadiusPixels));
  }
};

// A case's two views of one sphere: one sample a pixel, and 16.
struct Views
{
  const int Size; // the one-sample view's
  vtkSmartPointer<vtkPolyData> Sphere = vtkPhongTest::MakeSphere(256);
  View Coarse, Fine;

  explicit Views(const Case& c)
    : Size(static_cast<int>(2.0 * c.RadiusPixels) + 16)
    , Coarse(c, Size, Size, Sphere)
    , Fine(c, SamplesPerSide * Size, Size, Sphere)
  {
  }
};

// The light of frame f: its highlight (where the normal is the halfway vector) moves along x
// by 0.1 px a frame, from a place off the pixel grid's symmetries.
void SetLight(View& view, const Case& c, int frame)
{
  const double start = 0.5, step = 0.2 / c.RadiusPixels; // the halfway vector turns half as fast
  const double angle = start + step * frame / std::cos(0.5 * (start + step * frame));
  view.Light->SetPosition(std::sin(angle), 0.3, std::cos(angle));
}

// The reference at the coarse view's pixels: each pixel the mean of its 16 samples, alpha 1
// only where all 16 are on the surface.
vtkSmartPointer<vtkImageData> PixelAverage(vtkImageData* fine, int size)
{
  auto average = vtkSmartPointer<vtkImageData>::New();
  average->SetDimensions(size, size, 1);
  average->AllocateScalars(VTK_DOUBLE, 4);
  vtkDataArray* in = fine->GetPointData()->GetScalars();
  vtkDataArray* out = average->GetPointData()->GetScalars();
  const int fineSize = size * SamplesPerSide;
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      double sum[4] = { 0.0, 0.0, 0.0, 1.0 };
      for (int b = 0; b < SamplesPerSide; ++b)
      {
        for (int a = 0; a < SamplesPerSide; ++a)
        {
          const vtkIdType sample =
            static_cast<vtkIdType>(SamplesPerSide * y + b) * fineSize + SamplesPerSide * x + a;
          for (int k = 0; k < 3; ++k)
          {
            sum[k] += in->GetComponent(sample, k) / (SamplesPerSide * SamplesPerSide);
          }
          sum[3] = std::min(sum[3], in->GetComponent(sample, 3) >= 1.0 ? 1.0 : 0.0);
        }
      }
      out->SetTuple(static_cast<vtkIdType>(y) * size + x, sum);
    }
  }
  return average;
}

struct Frame
{
  vtkSmartPointer<vtkImageData> Exact, Filtered, Reference;
};

// The figures of one case over its frames, in 8-bit levels.
struct Figures
{
  double SquaredExact = 0.0, SquaredFiltered = 0.0, MaxExact = 0.0, MaxFiltered = 0.0;
  double FlickerExact = 0.0, FlickerFiltered = 0.0;
  vtkIdType Values = 0, FlickerValues = 0;
  std::vector<double> EnergyExact, EnergyFiltered, EnergyReference;
  bool Valid = true;

  static double RMS(double squares, vtkIdType count)
  {
    return count > 0 ? std::sqrt(squares / count) : 0.0;
  }
  static double Variation(const std::vector<double>& energy)
  {
    double mean = 0.0, squares = 0.0;
    for (double e : energy)
    {
      mean += e / energy.size();
    }
    for (double e : energy)
    {
      squares += (e - mean) * (e - mean) / energy.size();
    }
    return mean > 0.0 ? std::sqrt(squares) / mean : 0.0;
  }
};

double Value(vtkImageData* image, vtkIdType pixel, int k)
{
  return 255.0 * image->GetPointData()->GetScalars()->GetComponent(pixel, k);
}

bool Compared(const Frame& frame, vtkIdType pixel)
{
  return Value(frame.Reference, pixel, 3) >= 255.0 && Value(frame.Exact, pixel, 3) > 0.0 &&
    Value(frame.Filtered, pixel, 3) > 0.0;
}

// Adds one frame (and its change since the last) to the figures.
void Accumulate(const Frame& frame, const Frame* last, Figures& figures)
{
  const vtkIdType pixels = frame.Reference->GetNumberOfPoints();
  double energy[3] = { 0.0, 0.0, 0.0 };
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    if (!Compared(frame, p))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const double reference = Value(frame.Reference, p, k);
      const double exact = Value(frame.Exact, p, k), filtered = Value(frame.Filtered, p, k);
      figures.Valid = figures.Valid && std::isfinite(exact) && std::isfinite(filtered);
      figures.SquaredExact += (exact - reference) * (exact - reference);
      figures.SquaredFiltered += (filtered - reference) * (filtered - reference);
      figures.MaxExact = std::max(figures.MaxExact, std::abs(exact - reference));
      figures.MaxFiltered = std::max(figures.MaxFiltered, std::abs(filtered - reference));
      ++figures.Values;
      energy[0] += exact;
      energy[1] += filtered;
      energy[2] += reference;
      if (last && Compared(*last, p))
      {
        const double change = reference - Value(last->Reference, p, k);
        const double exactChange = exact - Value(last->Exact, p, k) - change;
        const double filteredChange = filtered - Value(last->Filtered, p, k) - change;
        figures.FlickerExact += exactChange * exactChange;
        figures.FlickerFiltered += filteredChange * filteredChange;
        ++figures.FlickerValues;
      }
    }
  }
  figures.EnergyExact.push_back(energy[0]);
  figures.EnergyFiltered.push_back(energy[1]);
  figures.EnergyReference.push_back(energy[2]);
}

// One frame: one exact sample per pixel, the filtered picture, and the 16-sample reference.
Frame Draw(Views& views, const Case& c, int frame)
{
  View& coarse = views.Coarse;
  View& fine = views.Fine;
  SetLight(coarse, c, frame);
  SetLight(fine, c, frame);
  vtkNew<vtkPhongFloatRenderPass> pass;
  Frame result;
  coarse.Mapper->SpecularAntiAliasingOff();
  result.Exact = vtkPhongTest::RenderFloat(coarse.Scene, pass);
  coarse.Mapper->SpecularAntiAliasingOn();
  result.Filtered = vtkPhongTest::RenderFloat(coarse.Scene, pass);
  vtkNew<vtkPhongFloatRenderPass> finePass;
  vtkNew<vtkPhongReference> reference;
  reference->SetRenderer(fine.Scene.Renderer);
  reference->SetActor(fine.Scene.Renderer->GetActors()->GetLastActor());
  auto shaded = vtkPhongTest::ShadeGBuffer(fine.Scene, finePass, reference);
  result.Reference = shaded ? PixelAverage(shaded, views.Size) : nullptr;
  return result;
}

Figures Measure(const Case& c, int frames)
{
  Views views(c);
  Figures figures;
  Frame last;
  for (int f = 0; f < frames; ++f)
  {
    Frame frame = Draw(views, c, f);
    if (!frame.Reference)
    {
      figures.Valid = false;
      return figures;
    }
    Accumulate(frame, f > 0 ? &last : nullptr, figures);
    last = frame;
  }
  return figures;
}

bool CheckNarrowLobe(const Case& c, int frames)
{
  const Figures f = Measure(c, frames);
  const double rmsExact = Figures::RMS(f.SquaredExact, f.Values);
  const double rmsFiltered = Figures::RMS(f.SquaredFiltered, f.Values);
  const double flickerExact = Figures::RMS(f.FlickerExact, f.FlickerValues);
  const double flickerFiltered = Figures::RMS(f.FlickerFiltered, f.FlickerValues);
  const double cvReference = Figures::Variation(f.EnergyReference);
  const double cvExact = Figures::Variation(f.EnergyExact);
  const double cvFiltered = Figures::Variation(f.EnergyFiltered);
  std::cout << c.Name << ": RMS " << rmsExact << " -> " << rmsFiltered << " levels ("
            << rmsExact / rmsFiltered << "x), largest " << f.MaxExact << " -> " << f.MaxFiltered
            << " (" << f.MaxExact / f.MaxFiltered << "x), flicker " << flickerExact << " -> "
            << flickerFiltered << " (" << flickerExact / flickerFiltered << "x), energy variation "
            << cvExact << " -> " << cvFiltered << " (reference " << cvReference << "), "
            << f.Values / 3 << " pixel-frames\n";
  bool ok = f.Valid && f.Values > 0;
  auto expect = [&](bool condition, const std::string& what)
  {
    if (!condition)
    {
      std::cerr << c.Name << ": " << what << "\n";
      ok = false;
    }
  };
  expect(rmsFiltered * 5.0 <= rmsExact, "RMS error not 5x lower");
  expect(f.MaxFiltered * 5.0 <= f.MaxExact, "largest error not 5x lower");
  // A lobe several pixels wide (n = 1e3 at 120 px: 3.8 px) does not flicker at one sample a
  // pixel (a thousandth of a level, the tessellation's): there the filter must not add any.
  expect(flickerFiltered * 5.0 <= flickerExact ||
      (flickerExact < NoFlicker && flickerFiltered <= flickerExact),
    "flicker not 5x lower");
  expect(cvFiltered <= 2.0 * cvReference + 0.01, "highlight energy less steady than allowed");
  return ok;
}

// A lobe several pixels wide: the filter must not change it (S3).
bool CheckWideLobe(const Case& c)
{
  Views views(c);
  const Frame frame = Draw(views, c, 0);
  double squares = 0.0;
  vtkIdType values = 0;
  for (vtkIdType p = 0; frame.Reference && p < frame.Reference->GetNumberOfPoints(); ++p)
  {
    for (int k = 0; k < 3 && Compared(frame, p); ++k, ++values)
    {
      const double change = Value(frame.Filtered, p, k) - Value(frame.Exact, p, k);
      squares += change * change;
    }
  }
  const double rms = Figures::RMS(squares, values);
  std::cout << c.Name << ": the filter changes the picture by " << rms << " levels RMS over "
            << values / 3 << " pixels\n";
  return values > 0 && rms <= 0.05;
}

// Off, no trace in the shader; on, its own program; under a budget, sums per fragment.
bool CheckShaders()
{
  // A coarse sphere, a wide lobe, a loose budget: every sum per vertex fits, unfiltered.
  const Case c = { "shaders", 120.0, 10.0, false };
  auto sphere = vtkPhongTest::MakeSphere(64);
  View view(c, 256, 256, sphere);
  auto signature = [&view]()
  {
    view.Scene.Window->Render();
    return view.Mapper->GetLastShaderSignature();
  };
  const std::string off = signature();
  view.Mapper->SetErrorBudget(16.0);
  const std::string budgetOff = signature();
  view.Mapper->SpecularAntiAliasingOn();
  const std::string budgetOn = signature();
  view.Mapper->SetErrorBudget(0.0);
  const std::string on = signature();
  const char* const feature = "SPECULAR_ANTI_ALIASING";
  auto has = [](const std::string& s, const char* what)
  { return s.find(what) != std::string::npos; };
  const bool ok = !has(off, feature) && has(on, feature) && has(budgetOff, "PER_VERTEX") &&
    !has(budgetOff, feature) && has(budgetOn, feature) && !has(budgetOn, "PER_VERTEX");
  if (!ok)
  {
    std::cerr << "signatures: off " << off << "; on " << on << "; under a budget, off " << budgetOff
              << "; on " << budgetOn << "\n";
  }
  return ok;
}
}

int TestPhongSpecularAntiAliasing(int argc, char* argv[])
{
  int frames = 24;
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::strcmp(argv[i], "--frames") == 0)
    {
      frames = std::max(2, std::atoi(argv[i + 1]));
    }
  }
  bool ok = CheckShaders();
  const Case narrow[] = {
    { "Blinn n 1e3, radius 40 px", 40.0, 1.0e3, false },
    { "Blinn n 1e4, radius 40 px", 40.0, 1.0e4, false },
    { "Blinn n 1e3, radius 120 px", 120.0, 1.0e3, false },
    { "Blinn n 1e4, radius 120 px", 120.0, 1.0e4, false },
    { "Phong n 1e3, radius 40 px", 40.0, 1.0e3, true },
  };
  for (const Case& c : narrow)
  {
    ok = CheckNarrowLobe(c, frames) && ok;
  }
  ok = CheckWideLobe({ "Blinn n 40, radius 120 px", 120.0, 40.0, false }) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
