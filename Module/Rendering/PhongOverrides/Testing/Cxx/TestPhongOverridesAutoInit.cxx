// A C++ program that links vtkPhong::RenderingPhongOverrides (its autoinit through
// vtk_module_autoinit, as this test executable is built) gets vtkPhong's mappers from VTK's
// factory before its first line: a plain vtkPolyDataMapper draws with vtkPhong's shader, and
// vtkPhongObjectFactory::SetOverridesEnabled switches that off and on at run time.

#include "vtkPhongTestUtilities.h"

#include "vtkObjectFactory.h"
#include "vtkPhongCompositePolyDataMapper.h"
#include "vtkPhongObjectFactory.h"
#include "vtkPolyDataMapper.h"
#include "vtkSphereSource.h"

#include <string>

namespace
{
std::string ClassMadeFor(const char* vtkClass)
{
  vtkObject* made = vtkObjectFactory::CreateInstance(vtkClass);
  const std::string name = made ? made->GetClassName() : "nothing";
  if (made)
  {
    made->Delete();
  }
  return name;
}
}

int TestPhongOverridesAutoInit(int, char*[])
{
  vtkPhongTest::Checks checks;
  checks.Expect(vtkPhongObjectFactory::GetOverridesEnabled(), "the autoinit switched them on");

  vtkNew<vtkSphereSource> sphere;
  vtkSmartPointer<vtkPolyDataMapper> mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(sphere->GetOutputPort());
  checks.Expect(mapper->IsA("vtkPhongPolyDataMapper"),
    std::string("vtkPolyDataMapper::New() makes a vtkPhongPolyDataMapper, not a ") +
      mapper->GetClassName());
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
  const char* compositeClass = "vtkCompositePolyDataMapper";
#else
  const char* compositeClass = "vtkCompositePolyDataMapper2";
#endif
  checks.Expect(ClassMadeFor(compositeClass) == "vtkPhongCompositePolyDataMapper",
    std::string("the factory's ") + compositeClass + " is vtkPhong's");

  vtkPhongTest::Scene scene(64, 64);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetInterpolationToPhong();
  actor->GetProperty()->SetSpecular(0.5);
  scene.Renderer->AddActor(actor);
  scene.LookFromZ(3.0);
  scene.Window->Render();
  auto* phong = vtkPhongPolyDataMapper::SafeDownCast(mapper);
  checks.Expect(phong && !std::string(phong->GetLastShaderSignature()).empty(),
    "the plain mapper draws with vtkPhong's generated shader");

  vtkPhongObjectFactory::SetOverridesEnabled(false);
  vtkSmartPointer<vtkPolyDataMapper> stock = vtkSmartPointer<vtkPolyDataMapper>::New();
  checks.Expect(!stock->IsA("vtkPhongPolyDataMapper") && stock->IsA("vtkOpenGLPolyDataMapper"),
    std::string("switched off, VTK's own mapper comes back: ") + stock->GetClassName());
  vtkPhongObjectFactory::SetOverridesEnabled(true);
  stock = vtkSmartPointer<vtkPolyDataMapper>::New();
  checks.Expect(stock->IsA("vtkPhongPolyDataMapper"), "switched on again, vtkPhong's");
  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
