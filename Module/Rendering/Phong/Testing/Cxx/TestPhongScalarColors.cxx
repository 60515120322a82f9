// Scalar colouring replaces the ambient and diffuse colour, as in stock VTK:
// point scalars (elevation, interpolated) on the left sphere, cell scalars
// (one colour per face band) on the right, both with white highlights.

#include "vtkPhongTestUtilities.h"

#include "vtkCellData.h"
#include "vtkElevationFilter.h"

int TestPhongScalarColors(int argc, char* argv[])
{
  vtkPhongTest::Scene scene(400, 240);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputData(vtkPhongTest::MakeSphere(64, 0.45));
  elevation->SetLowPoint(0.0, -0.45, 0.0);
  elevation->SetHighPoint(0.0, 0.45, 0.0);
  elevation->Update();

  vtkNew<vtkPhongProperty> left;
  left->SetSpecular(0.5);
  left->SetShininess(40.0);
  left->SetAmbient(0.1);
  vtkActor* pointScalars =
    vtkPhongTest::AddActor(scene, vtkPolyData::SafeDownCast(elevation->GetOutput()), left);
  pointScalars->SetPosition(-0.55, 0.0, 0.0);

  auto banded = vtkPhongTest::MakeSphere(32, 0.45);
  vtkNew<vtkUnsignedCharArray> faceColors;
  faceColors->SetNumberOfComponents(3);
  faceColors->SetName("bands");
  for (vtkIdType cell = 0; cell < banded->GetNumberOfCells(); ++cell)
  {
    const unsigned char palette[4][3] = { { 220, 60, 60 }, { 60, 200, 90 }, { 70, 90, 220 },
      { 230, 200, 60 } };
    faceColors->InsertNextTypedTuple(palette[(cell / 7) % 4]);
  }
  banded->GetCellData()->SetScalars(faceColors);
  vtkNew<vtkPhongProperty> right;
  right->SetSpecular(0.5);
  right->SetShininess(40.0);
  right->SetAmbient(0.1);
  vtkActor* cellScalars = vtkPhongTest::AddActor(scene, banded, right);
  cellScalars->SetPosition(0.55, 0.0, 0.0);

  scene.LookFromZ(3.4);
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
