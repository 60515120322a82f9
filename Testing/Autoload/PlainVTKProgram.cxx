// A VTK program that knows nothing of vtkPhong: it links VTK alone, as users' programs do.
// It prints the class of each mapper VTK's factory makes for it, draws a sphere and a
// two-block composite dataset, and writes the picture. TestPhongAutoload.py runs it with
// and without VTK_AUTOLOAD_PATH.

#include "vtkActor.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkVersionMacros.h"
#include "vtkWindowToImageFilter.h"

#if VTK_MAJOR_VERSION > 9 || (VTK_MAJOR_VERSION == 9 && VTK_MINOR_VERSION >= 3)
#include "vtkCompositePolyDataMapper.h"
using CompositeMapper = vtkCompositePolyDataMapper;
// From VTK 9.3 the composite mapper is not made by the factory; it draws through a
// delegator that is, and that is the class a factory override reaches.
static const char* const CompositeDrawer = "vtkCompositePolyDataMapperDelegator";
#else
#include "vtkCompositePolyDataMapper2.h"
using CompositeMapper = vtkCompositePolyDataMapper2;
static const char* const CompositeDrawer = "vtkCompositePolyDataMapper2";
#endif

#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: PlainVTKProgram OUTPUT.png\n";
    return 2;
  }
  vtkNew<vtkRenderer> renderer;
  for (double x : { -0.6, 0.6 })
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(32);
    sphere->SetPhiResolution(32);
    sphere->SetCenter(x, 0.6, 0.0);
    sphere->SetRadius(0.5);
    sphere->Update();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetSpecular(0.6);
    actor->GetProperty()->SetSpecularPower(40.0);
    renderer->AddActor(actor);
    std::cout << "vtkPolyDataMapper: " << mapper->GetClassName() << "\n";
  }

  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  for (unsigned int block = 0; block < 2; ++block)
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(block == 0 ? -0.6 : 0.6, -0.6, 0.0);
    sphere->SetRadius(0.5);
    sphere->Update();
    blocks->SetBlock(block, sphere->GetOutput());
  }
  vtkNew<CompositeMapper> composite;
  composite->SetInputDataObject(blocks);
  vtkNew<vtkActor> compositeActor;
  compositeActor->SetMapper(composite);
  compositeActor->GetProperty()->SetSpecular(0.6);
  renderer->AddActor(compositeActor);
  vtkSmartPointer<vtkObject> drawer =
    vtkSmartPointer<vtkObject>::Take(vtkObjectFactory::CreateInstance(CompositeDrawer));
  std::cout << CompositeDrawer << ": " << (drawer ? drawer->GetClassName() : "(none)") << "\n";

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(300, 300);
  window->AddRenderer(renderer);
  window->Render();
  vtkNew<vtkWindowToImageFilter> snapshot;
  snapshot->SetInput(window);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(snapshot->GetOutputPort());
  writer->SetFileName(argv[1]);
  writer->Write();
  return 0;
}
