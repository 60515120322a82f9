// The default scene: a real mesh (CGAL's Stanford bunny, or any OFF file) on a
// floor, lit by three lights of different kinds (a directional key light, an
// attenuated point fill light, a spot rim light) with the Blinn-Phong lobe,
// rendered offscreen to a PNG whose path is printed.
//
//   PhongDefaultScene MESH.off OUTPUT.png [WIDTH HEIGHT]

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPhongOFFReader.h"
#include "vtkPhongPolyDataMapper.h"
#include "vtkPhongProperty.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkWindowToImageFilter.h"

#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc != 3 && argc != 5)
  {
    std::cerr << "usage: " << argv[0] << " MESH.off OUTPUT.png [WIDTH HEIGHT]\n";
    return EXIT_FAILURE;
  }
  const int width = argc == 5 ? std::atoi(argv[3]) : 1280;
  const int height = argc == 5 ? std::atoi(argv[4]) : 960;
  if (width <= 0 || height <= 0)
  {
    std::cerr << "error: WIDTH and HEIGHT must be positive integers\n";
    return EXIT_FAILURE;
  }

  vtkNew<vtkPhongOFFReader> reader;
  if (!vtkPhongOFFReader::CanReadFile(argv[1]))
  {
    std::cerr << "error: " << argv[1] << " is not a readable OFF file\n";
    return EXIT_FAILURE;
  }
  reader->SetFileName(argv[1]);
  vtkNew<vtkPolyDataNormals> normals; // smooth normals: the OFF file has none
  normals->SetInputConnection(reader->GetOutputPort());
  normals->SplittingOff();
  normals->Update();
  vtkPolyData* mesh = normals->GetOutput();
  if (mesh->GetNumberOfCells() == 0)
  {
    std::cerr << "error: " << argv[1] << " has no faces\n";
    return EXIT_FAILURE;
  }

  double bounds[6];
  mesh->GetBounds(bounds);
  const double size =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };

  vtkNew<vtkPhongPolyDataMapper> meshMapper;
  meshMapper->SetInputData(mesh);
  vtkNew<vtkPhongProperty> clay;
  clay->SetColor(0.86, 0.68, 0.52);
  clay->SetAmbient(0.2);
  clay->SetDiffuse(0.75);
  clay->SetSpecular(0.35);
  clay->SetSpecularColor(1.0, 0.97, 0.92);
  clay->SetLightingModelToBlinnPhong();
  clay->SetShininess(150.0);
  vtkNew<vtkActor> meshActor;
  meshActor->SetMapper(meshMapper);
  meshActor->SetProperty(clay);

  // A floor just under the mesh (y is up in CGAL's bunny).
  vtkNew<vtkPlaneSource> floorSource;
  floorSource->SetOrigin(center[0] - 1.5 * size, bounds[2], center[2] - 1.5 * size);
  floorSource->SetPoint1(center[0] + 1.5 * size, bounds[2], center[2] - 1.5 * size);
  floorSource->SetPoint2(center[0] - 1.5 * size, bounds[2], center[2] + 1.5 * size);
  floorSource->SetResolution(64, 64);
  vtkNew<vtkPhongPolyDataMapper> floorMapper;
  floorMapper->SetInputConnection(floorSource->GetOutputPort());
  vtkNew<vtkPhongProperty> floor;
  floor->SetColor(0.55, 0.6, 0.65);
  floor->SetAmbient(0.2);
  floor->SetDiffuse(0.8);
  floor->SetSpecular(0.15);
  floor->SetLightingModelToBlinnPhong();
  floor->SetShininess(40.0);
  vtkNew<vtkActor> floorActor;
  floorActor->SetMapper(floorMapper);
  floorActor->SetProperty(floor);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(meshActor);
  renderer->AddActor(floorActor);
  renderer->SetBackground(0.07, 0.08, 0.1);
  renderer->SetAmbient(0.25, 0.27, 0.32); // a dim blue sky; stock VTK ignores it
  renderer->AutomaticLightCreationOff();

  // Key: a warm directional light from the upper front left.
  vtkNew<vtkLight> key;
  key->SetLightTypeToSceneLight();
  key->SetPosition(center[0] - size, center[1] + 2.0 * size, center[2] + 1.5 * size);
  key->SetFocalPoint(center);
  key->SetDiffuseColor(1.0, 0.9, 0.78);
  key->SetSpecularColor(1.0, 0.95, 0.9);
  key->SetIntensity(0.9);
  renderer->AddLight(key);

  // Fill: a cool point light on the right, fading with distance.
  vtkNew<vtkLight> fill;
  fill->SetLightTypeToSceneLight();
  fill->PositionalOn();
  fill->SetConeAngle(180.0);
  fill->SetPosition(center[0] + 1.2 * size, center[1] + 0.3 * size, center[2] + 0.8 * size);
  fill->SetFocalPoint(center);
  fill->SetDiffuseColor(0.55, 0.7, 1.0);
  fill->SetSpecularColor(0.55, 0.7, 1.0);
  fill->SetAttenuationValues(0.2, 0.0, 0.8 / (size * size));
  fill->SetIntensity(0.9);
  renderer->AddLight(fill);

  // Rim: a spot from behind and above, cutting out the silhouette.
  vtkNew<vtkLight> rim;
  rim->SetLightTypeToSceneLight();
  rim->PositionalOn();
  rim->SetPosition(center[0] + 0.3 * size, center[1] + 2.0 * size, center[2] - 2.0 * size);
  rim->SetFocalPoint(center);
  rim->SetConeAngle(25.0);
  rim->SetExponent(2.0);
  rim->SetDiffuseColor(1.0, 1.0, 1.0);
  rim->SetSpecularColor(1.0, 1.0, 1.0);
  rim->SetIntensity(1.2);
  renderer->AddLight(rim);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0] + 0.15 * size, center[1] + 0.35 * size, center[2] + 2.2 * size);
  camera->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCamera(bounds);
  camera->Zoom(1.25);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->SetMultiSamples(8);
  window->AddRenderer(renderer);
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(argv[2]);
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode())
  {
    std::cerr << "error: could not write " << argv[2] << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "Rendered " << mesh->GetNumberOfCells() << " triangles of " << argv[1] << " with "
            << meshMapper->GetLastShaderSignature() << "\n";
  std::cout << argv[2] << "\n";
  return EXIT_SUCCESS;
}
