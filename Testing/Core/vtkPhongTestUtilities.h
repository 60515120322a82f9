// Helpers shared by the vtkPhong C++ tests: a standard offscreen scene, test
// meshes, a GL error check and an error collector. Header-only on purpose: each
// test is one source file of the test driver.

#ifndef vtkPhongTestUtilities_h
#define vtkPhongTestUtilities_h

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkImageExtractComponents.h"
#include "vtkImageMathematics.h"
#include "vtkImageShiftScale.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPhongCompositePolyDataMapper.h"
#include "vtkPhongOpenGL.h"
#include "vtkPhongPolyDataMapper.h"
#include "vtkPhongProperty.h"
#include "vtkPhongSharedDisplay.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTesting.h"
#include "vtkTexture.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace vtkPhongTest
{

// A 300x300 offscreen window with one renderer and VTK's defaults, black background.
struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;

  explicit Scene(int width = 300, int height = 300)
  {
    UseSharedDisplay(this->Window);
    this->Window->SetSize(width, height);
    this->Window->SetMultiSamples(0); // exact, repeatable pixels for the baselines
    this->Window->SetOffScreenRendering(1);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
  }

  // Look at the origin from +z at the given distance, with a 30 degree view angle.
  void LookFromZ(double distance)
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(0.0, 0.0, distance);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(30.0);
    this->Renderer->ResetCameraClippingRange();
  }
};

inline vtkSmartPointer<vtkPolyData> MakeSphere(int resolution, double radius = 0.5)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution);
  sphere->Update();
  return sphere->GetOutput();
}

// A 32 x 32 sphere coloured in bands of 7 cells (cell scalars, red and blue).
inline vtkSmartPointer<vtkPolyData> MakeBandedSphere(double radius = 0.5)
{
  auto banded = MakeSphere(32, radius);
  vtkNew<vtkUnsignedCharArray> bands;
  bands->SetNumberOfComponents(3);
  for (vtkIdType cell = 0; cell < banded->GetNumberOfCells(); ++cell)
  {
    const unsigned char colour[2][3] = { { 220, 60, 60 }, { 60, 90, 220 } };
    bands->InsertNextTypedTuple(colour[(cell / 7) % 2]);
  }
  banded->GetCellData()->SetScalars(bands);
  return banded;
}

// A copy of the mesh translated by (x, y, z).
inline vtkSmartPointer<vtkPolyData> Moved(vtkPolyData* mesh, double x, double y, double z)
{
  vtkNew<vtkTransform> transform;
  transform->Translate(x, y, z);
  vtkNew<vtkTransformPolyDataFilter> move;
  move->SetInputData(mesh);
  move->SetTransform(transform);
  move->Update();
  return move->GetOutput();
}

// The mean of a cell's points.
inline void CellCentre(vtkPolyData* mesh, vtkIdType cell, double centre[3])
{
  vtkNew<vtkIdList> ids;
  mesh->GetCellPoints(cell, ids);
  centre[0] = centre[1] = centre[2] = 0.0;
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
  {
    const double* point = mesh->GetPoint(ids->GetId(k));
    for (int axis = 0; axis < 3; ++axis)
    {
      centre[axis] += point[axis] / ids->GetNumberOfIds();
    }
  }
}

// A polygonal mesh of double-precision points from lists of points and faces (any sizes).
inline vtkSmartPointer<vtkPolyData> MakeMesh(const std::vector<std::array<double, 3>>& points,
  const std::vector<std::vector<vtkIdType>>& faces)
{
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const auto& p : points)
  {
    pts->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& face : faces)
  {
    polys->InsertNextCell(static_cast<vtkIdType>(face.size()), face.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(pts);
  mesh->SetPolys(polys);
  return mesh;
}

// A square in the z = 0 plane, facing +z, subdivided so per-vertex lighting can resolve it.
inline vtkSmartPointer<vtkPolyData> MakePlane(double halfSize, int resolution)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-halfSize, -halfSize, 0.0);
  plane->SetPoint1(halfSize, -halfSize, 0.0);
  plane->SetPoint2(-halfSize, halfSize, 0.0);
  plane->SetResolution(resolution, resolution);
  plane->Update();
  return plane->GetOutput();
}

inline vtkSmartPointer<vtkLight> MakeSceneLight(
  const double position[3], const double focalPoint[3], const double color[3], bool positional)
{
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  light->SetPosition(position[0], position[1], position[2]);
  light->SetFocalPoint(focalPoint[0], focalPoint[1], focalPoint[2]);
  light->SetColor(color[0], color[1], color[2]);
  light->SetPositional(positional);
  return light;
}

// Adds a light to the scene's renderer and returns it for further settings.
inline vtkLight* AddLight(Scene& scene, const double position[3], const double focalPoint[3],
  const double color[3], bool positional, int lightType = VTK_LIGHT_TYPE_SCENE_LIGHT)
{
  auto light = MakeSceneLight(position, focalPoint, color, positional);
  // A camera light's position and focal point are in camera coordinates.
  light->SetLightType(lightType);
  scene.Renderer->AddLight(light);
  return light;
}

// An 8x8 checkerboard of two colours, for texture tests.
inline vtkSmartPointer<vtkTexture> MakeCheckerTexture(
  const unsigned char dark[3], const unsigned char light[3], int squares = 8)
{
  const int size = 64;
  vtkNew<vtkImageData> image;
  image->SetDimensions(size, size, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      const bool odd = (((x * squares) / size) + ((y * squares) / size)) % 2 != 0;
      auto* pixel = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
      for (int c = 0; c < 3; ++c)
      {
        pixel[c] = odd ? light[c] : dark[c];
      }
    }
  }
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOff();
  return texture;
}

// `actor`: one of the caller's class (a vtkFollower, a vtkLODActor); null, a new vtkActor.
inline vtkActor* AddActor(
  Scene& scene, vtkPolyData* mesh, vtkProperty* property = nullptr, vtkActor* actor = nullptr)
{
  vtkNew<vtkPhongPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  vtkSmartPointer<vtkActor> added = actor;
  if (!added)
  {
    added = vtkSmartPointer<vtkActor>::New();
  }
  added->SetMapper(mapper);
  if (property)
  {
    added->SetProperty(property);
  }
  scene.Renderer->AddActor(added);
  return added; // the renderer holds it
}

// A coarse sphere (12 x 12) lit by a key light at 45 degrees with a sharp
// highlight: the interpolation tests show how each mode resolves it.
inline void BuildInterpolationScene(Scene& scene, vtkPhongProperty* material)
{
  scene.Renderer->AutomaticLightCreationOff();
  const double key[3] = { 1.0, 1.0, 2.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  AddLight(scene, key, origin, white, false);
  material->SetColor(0.2, 0.7, 0.4);
  material->SetAmbient(0.1);
  material->SetDiffuse(0.8);
  material->SetSpecular(0.7);
  material->SetShininess(60.0);
  AddActor(scene, MakeSphere(12), material);
  scene.LookFromZ(2.3);
}

// A spot light (cone 25 degrees, exponent 4) on a floor, with a dim blue
// renderer ambient; returns the floor's material for the option under test.
inline vtkPhongProperty* BuildSpotScene(Scene& scene)
{
  scene.Renderer->AutomaticLightCreationOff();
  const double source[3] = { -0.6, 0.3, 1.6 };
  const double target[3] = { 0.1, -0.1, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  vtkLight* spot = AddLight(scene, source, target, white, true);
  spot->SetConeAngle(25.0);
  spot->SetExponent(4.0);

  auto floor = vtkSmartPointer<vtkPhongProperty>::New();
  floor->SetColor(0.9, 0.9, 0.9);
  floor->SetAmbient(0.1);
  floor->SetSpecular(0.3);
  floor->SetShininess(40.0);
  AddActor(scene, MakePlane(1.5, 60), floor);
  scene.Renderer->SetAmbient(0.2, 0.2, 0.3);
  scene.LookFromZ(4.0);
  return floor; // the actor keeps it alive
}

// The scene of the debug-view tests: a sphere on a floor under a directional,
// a point and a spot light, with an emissive material.
inline vtkPhongPolyDataMapper* BuildDebugScene(Scene& scene)
{
  scene.Renderer->AutomaticLightCreationOff();
  scene.Renderer->SetAmbient(0.3, 0.3, 0.4);
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double sun[3] = { 1.0, 1.5, 2.0 };
  const double pointAt[3] = { -0.7, 0.6, 0.7 };
  const double spotAt[3] = { 0.8, -0.6, 1.2 };
  const double spotTarget[3] = { 0.5, -0.5, 0.0 };
  const double warm[3] = { 1.0, 0.85, 0.7 };
  const double green[3] = { 0.4, 1.0, 0.4 };
  const double blue[3] = { 0.5, 0.6, 1.0 };
  AddLight(scene, sun, origin, warm, false)->SetIntensity(0.7);
  vtkLight* point = AddLight(scene, pointAt, origin, green, true);
  point->SetConeAngle(180.0);
  point->SetAttenuationValues(1.0, 0.0, 1.0);
  point->SetAmbientColor(0.1, 0.3, 0.1);
  vtkLight* spot = AddLight(scene, spotAt, spotTarget, blue, true);
  spot->SetConeAngle(30.0);
  spot->SetExponent(2.0);

  vtkNew<vtkPhongProperty> floor;
  floor->SetColor(0.8, 0.8, 0.8);
  floor->SetAmbient(0.2);
  floor->SetSpecular(0.3);
  floor->SetShininess(30.0);
  AddActor(scene, MakePlane(1.5, 60), floor);

  vtkNew<vtkPhongProperty> ball;
  ball->SetColor(0.9, 0.5, 0.3);
  ball->SetAmbient(0.3);
  ball->SetSpecular(0.6);
  ball->SetShininess(60.0);
  ball->SetEmission(0.0, 0.0, 0.25);
  vtkActor* sphere = AddActor(scene, MakeSphere(64, 0.4), ball);
  sphere->SetPosition(0.0, 0.0, 0.4);

  scene.LookFromZ(4.5);
  scene.Renderer->GetActiveCamera()->Elevation(-40.0);
  scene.Renderer->GetActiveCamera()->OrthogonalizeViewUp();
  scene.Renderer->ResetCameraClippingRange();

  // Every actor shares the debug view: return one mapper, set the rest alike.
  return vtkPhongPolyDataMapper::SafeDownCast(sphere->GetMapper());
}

// Sets the debug view on every vtkPhong mapper of the scene.
inline void SetDebugView(Scene& scene, int view, int lightIndex = 0)
{
  vtkActorCollection* actors = scene.Renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor())
  {
    if (auto* mapper = vtkPhongPolyDataMapper::SafeDownCast(actor->GetMapper()))
    {
      mapper->SetDebugView(view);
      mapper->SetDebugLightIndex(lightIndex);
    }
    else if (auto* composite = vtkPhongCompositePolyDataMapper::SafeDownCast(actor->GetMapper()))
    {
      composite->SetDebugView(view);
      composite->SetDebugLightIndex(lightIndex);
    }
  }
}

// Fails (returns false) if OpenGL has recorded an error since the last check.
inline bool NoGLErrors(vtkRenderWindow* window, const char* where)
{
  window->MakeCurrent();
  bool clean = true;
  for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError())
  {
    std::cerr << "OpenGL error 0x" << std::hex << error << std::dec << " after " << where << "\n";
    clean = false;
  }
  return clean;
}

// Collects the error and warning events of observed objects, so tests can
// expect errors without the test harness counting them as failures.
class ErrorCollector
{
public:
  ErrorCollector()
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback(&ErrorCollector::OnEvent);
  }

  void Observe(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this->Callback);
    object->AddObserver(vtkCommand::WarningEvent, this->Callback);
  }

  bool Contains(const std::string& text) const
  {
    for (const auto& message : this->Messages)
    {
      if (message.find(text) != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }

  std::vector<std::string> Messages;

private:
  static void OnEvent(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<ErrorCollector*>(clientData);
    self->Messages.emplace_back(callData ? static_cast<const char*>(callData) : "");
  }
  vtkNew<vtkCallbackCommand> Callback;
};

// The rendered image, for pixel checks.
// The window's picture; `rerender` false reads the last frame instead of rendering another
// (which counts as a frame for what a mapper decides from frame to frame).
inline vtkSmartPointer<vtkImageData> Snapshot(vtkRenderWindow* window, bool rerender = true)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->SetShouldRerender(rerender);
  grab->Update();
  return grab->GetOutput();
}

inline const unsigned char* PixelAt(vtkImageData* image, int x, int y)
{
  return static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
}

// Largest per-channel difference between two snapshots of the same size.
inline int MaxDifference(vtkImageData* a, vtkImageData* b)
{
  auto* pa = static_cast<unsigned char*>(a->GetScalarPointer());
  auto* pb = static_cast<unsigned char*>(b->GetScalarPointer());
  const vtkIdType count = a->GetNumberOfPoints() * a->GetNumberOfScalarComponents();
  int largest = 0;
  for (vtkIdType i = 0; i < count; ++i)
  {
    largest = std::max(largest, std::abs(int(pa[i]) - int(pb[i])));
  }
  return largest;
}

// How many pixels differ by more than threshold levels in some channel.
inline int CountDifferentPixels(vtkImageData* a, vtkImageData* b, int threshold)
{
  auto* pa = static_cast<unsigned char*>(a->GetScalarPointer());
  auto* pb = static_cast<unsigned char*>(b->GetScalarPointer());
  const int channels = a->GetNumberOfScalarComponents();
  int count = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    for (int c = 0; c < channels; ++c)
    {
      if (std::abs(int(pa[i * channels + c]) - int(pb[i * channels + c])) > threshold)
      {
        ++count;
        break;
      }
    }
  }
  return count;
}

// Whether two arrays hold exactly the same values (NaN where the other has NaN).
inline bool ArraysEqual(vtkDataArray* a, vtkDataArray* b)
{
  if (!a || !b || a->GetNumberOfTuples() != b->GetNumberOfTuples() ||
    a->GetNumberOfComponents() != b->GetNumberOfComponents())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    const vtkVariant x = a->GetVariantValue(i), y = b->GetVariantValue(i);
    if (x != y && !(std::isnan(x.ToDouble()) && std::isnan(y.ToDouble())))
    {
      return false;
    }
  }
  return true;
}

// Reports a failed expectation and remembers it.
struct Checks
{
  bool Passed = true;
  void Expect(bool condition, const std::string& what)
  {
    if (!condition)
    {
      std::cerr << "Check failed: " << what << "\n";
      this->Passed = false;
    }
  }
  // |value - expected| <= tolerance, with both printed on failure.
  void Near(double value, double expected, double tolerance, const std::string& what)
  {
    this->Expect(std::abs(value - expected) <= tolerance,
      what + ": got " + std::to_string(value) + ", expected " + std::to_string(expected) + " +- " +
        std::to_string(tolerance));
  }
};

// VTK's image comparison averages a smoothed, shift-tolerant difference and
// lets a highlight change shape unnoticed. The strict check compares the same
// baseline pixel by pixel: it fails when more than StrictPixelBudget pixels
// differ by more than StrictLevels in a channel. The budget allows a few
// silhouette pixels to flip if the rasterizer changes; the module's own
// pictures are exactly repeatable on Debian 12's llvmpipe.
constexpr int StrictLevels = 6;
constexpr int StrictPixelBudget = 24;

// The baseline and its alternates, as VTK's harness names them: Name.png, Name_1.png, ...
// An alternate holds what another release's VTK draws (edges, points), never a looser copy.
inline std::vector<std::string> BaselineAndAlternates(const std::string& baselineFile)
{
  std::vector<std::string> files{ baselineFile };
  const std::string stem = baselineFile.substr(0, baselineFile.size() - 4); // less ".png"
  for (int i = 1;; ++i)
  {
    const std::string alternate = stem + "_" + std::to_string(i) + ".png";
    if (!vtksys::SystemTools::FileExists(alternate))
    {
      return files;
    }
    files.push_back(alternate);
  }
}

inline vtkSmartPointer<vtkImageData> ReadBaselineRGB(const std::string& file)
{
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(file.c_str()))
  {
    return nullptr;
  }
  reader->SetFileName(file.c_str());
  vtkNew<vtkImageExtractComponents> rgb;
  rgb->SetInputConnection(reader->GetOutputPort());
  rgb->SetComponents(0, 1, 2);
  rgb->Update();
  return rgb->GetOutput();
}

// Leaves the picture and its amplified per-pixel difference where VTK puts its own.
inline void WriteStrictDifference(vtkTesting* testing, const std::string& baselineFile,
  vtkImageData* rendered, vtkImageData* baseline)
{
  const char* temporary = testing->GetTempDirectory();
  std::string name = vtksys::SystemTools::GetFilenameWithoutLastExtension(baselineFile);
  vtkNew<vtkImageMathematics> difference;
  difference->SetOperationToSubtract();
  difference->SetInput1Data(rendered);
  difference->SetInput2Data(baseline);
  vtkNew<vtkImageMathematics> magnitude;
  magnitude->SetOperationToAbsoluteValue();
  magnitude->SetInputConnection(difference->GetOutputPort());
  vtkNew<vtkImageShiftScale> amplify;
  amplify->SetInputConnection(magnitude->GetOutputPort());
  amplify->SetScale(4.0);
  amplify->ClampOverflowOn();
  amplify->SetOutputScalarTypeToUnsignedChar();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName((std::string(temporary) + "/" + name + ".strict.png").c_str());
  writer->SetInputData(rendered);
  writer->Write();
  writer->SetFileName((std::string(temporary) + "/" + name + ".strict-diff.png").c_str());
  writer->SetInputConnection(amplify->GetOutputPort());
  writer->Write();
}

inline bool StrictlyMatchesBaseline(int argc, char* argv[], vtkRenderWindow* window)
{
  vtkNew<vtkTesting> testing;
  testing->AddArguments(argc, argv);
  if (!testing->IsValidImageSpecified())
  {
    return true; // no baseline: VTK's harness reports that
  }
  auto rendered = Snapshot(window);
  int dims[3];
  rendered->GetDimensions(dims);
  // The closest of the baseline and its alternates must be within the budget.
  std::string closestFile;
  vtkSmartPointer<vtkImageData> closest;
  int fewestChanged = -1;
  for (const std::string& file : BaselineAndAlternates(testing->GetValidImageFileName()))
  {
    vtkSmartPointer<vtkImageData> baseline = ReadBaselineRGB(file);
    if (!baseline)
    {
      return true; // a missing baseline is VTK's harness' failure to report
    }
    int baselineDims[3];
    baseline->GetDimensions(baselineDims);
    if (dims[0] != baselineDims[0] || dims[1] != baselineDims[1])
    {
      std::cerr << "Strict check: the image is " << dims[0] << "x" << dims[1] << ", " << file
                << " is " << baselineDims[0] << "x" << baselineDims[1] << "\n";
      continue;
    }
    const int changed = CountDifferentPixels(rendered, baseline, StrictLevels);
    if (changed <= StrictPixelBudget)
    {
      return true;
    }
    if (fewestChanged < 0 || changed < fewestChanged)
    {
      fewestChanged = changed;
      closestFile = file;
      closest = baseline;
    }
  }
  if (closest)
  {
    std::cerr << "Strict check: " << fewestChanged << " pixels differ from " << closestFile
              << " (the closest baseline) by more than " << StrictLevels << " levels (budget "
              << StrictPixelBudget << ")\n";
    WriteStrictDifference(testing, closestFile, rendered, closest);
  }
  return false;
}

// The integer after `flag` among the test's arguments (`--seed 7`), else `fallback`: for
// tests whose long runs (./vtkphong.sh) take more scenes than ctest's.
inline int IntegerOption(int argc, char* argv[], const char* flag, int fallback)
{
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == flag)
    {
      return std::atoi(argv[i + 1]);
    }
  }
  return fallback;
}

// Compare with the baseline (VTK's harness, then strictly) and check GL
// errors; returns the test's exit code.
inline int Finish(int argc, char* argv[], vtkRenderWindow* window, bool otherChecksPassed = true)
{
  const bool glClean = NoGLErrors(window, "rendering");
  const int result = vtkRegressionTestImage(window);
  const bool strict = result == vtkTesting::FAILED || StrictlyMatchesBaseline(argc, argv, window);
  return (result != vtkTesting::FAILED && strict && glClean && otherChecksPassed) ? EXIT_SUCCESS
                                                                                  : EXIT_FAILURE;
}

} // namespace vtkPhongTest

#endif
