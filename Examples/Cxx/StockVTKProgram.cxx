// A plain VTK program: no vtkPhong class, header or call in it. Built with
// vtkPhong::RenderingPhongOverrides in its vtk_module_autoinit (CMakeLists.txt), it lights
// with vtkPhong: the mapper VTK's factory makes is printed, and the picture written.
//
//   StockVTKProgram OUTPUT.png

#include "vtkActor.h"
#include "vtkLightKit.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkWindowToImageFilter.h"

#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: StockVTKProgram OUTPUT.png\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetInterpolationToPhong();
  actor->GetProperty()->SetSpecular(0.5);
  actor->GetProperty()->SetSpecularPower(40.0);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkLightKit> lights;
  lights->AddLightsToRenderer(renderer);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(320, 240);
  window->AddRenderer(renderer);
  window->Render();

  vtkNew<vtkWindowToImageFilter> snapshot;
  snapshot->SetInput(window);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(snapshot->GetOutputPort());
  writer->SetFileName(argv[1]);
  writer->Write();
  std::cout << "mapper: " << mapper->GetClassName() << "\n";
  return EXIT_SUCCESS;
}
