// Helpers shared by the vtkPhong C++ tests: a standard offscreen scene, test
// meshes, a GL error check and an error collector. Header-only on purpose: each
// test is one source file of the test driver.

#ifndef vtkPhongTestUtilities_h
#define vtkPhongTestUtilities_h

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPhongPolyDataMapper.h"
#include "vtkPhongProperty.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"
#include "vtk_glew.h"

#include <cmath>
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

inline vtkActor* AddActor(Scene& scene, vtkPolyData* mesh, vtkProperty* property = nullptr)
{
  vtkNew<vtkPhongPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  if (property)
  {
    actor->SetProperty(property);
  }
  scene.Renderer->AddActor(actor);
  return actor;
}

// Fails (returns false) if OpenGL has recorded an error since the last check.
inline bool NoGLErrors(vtkRenderWindow* window, const char* where)
{
  window->MakeCurrent();
  bool clean = true;
  for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError())
  {
    std::cerr << "OpenGL error 0x" << std::hex << error << std::dec << " after " << where
              << "\n";
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
inline vtkSmartPointer<vtkImageData> Snapshot(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  return grab->GetOutput();
}

inline const unsigned char* PixelAt(vtkImageData* image, int x, int y)
{
  return static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
}

// Compare with the baseline and check GL errors; returns the test's exit code.
inline int Finish(int argc, char* argv[], vtkRenderWindow* window, bool otherChecksPassed = true)
{
  const bool glClean = NoGLErrors(window, "rendering");
  const int result = vtkRegressionTestImage(window);
  return (result != vtkTesting::FAILED && glClean && otherChecksPassed) ? EXIT_SUCCESS
                                                                         : EXIT_FAILURE;
}

} // namespace vtkPhongTest

#endif
