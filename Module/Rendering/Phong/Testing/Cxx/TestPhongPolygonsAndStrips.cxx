// Polygons and triangle strips are lit like triangles: a cube of quads (with
// its own point normals) and a hexagonal prism of polygons on the left, the
// sphere made into triangle strips on the right.

#include "vtkPhongTestUtilities.h"

#include "vtkCubeSource.h"
#include "vtkPolyDataNormals.h"
#include "vtkStripper.h"

namespace
{
// A hexagonal prism: two hexagons and six quads, no normals (VTK computes a
// flat normal per face in the shader).
vtkSmartPointer<vtkPolyData> MakeHexagonalPrism()
{
  vtkNew<vtkPoints> points;
  for (int level = 0; level < 2; ++level)
  {
    for (int corner = 0; corner < 6; ++corner)
    {
      const double angle = corner * vtkMath::Pi() / 3.0;
      points->InsertNextPoint(0.3 * std::cos(angle), 0.3 * std::sin(angle), level ? 0.2 : -0.2);
    }
  }
  vtkNew<vtkCellArray> polygons;
  const vtkIdType bottom[6] = { 5, 4, 3, 2, 1, 0 };
  const vtkIdType top[6] = { 6, 7, 8, 9, 10, 11 };
  polygons->InsertNextCell(6, bottom);
  polygons->InsertNextCell(6, top);
  for (vtkIdType corner = 0; corner < 6; ++corner)
  {
    const vtkIdType next = (corner + 1) % 6;
    const vtkIdType side[4] = { corner, next, next + 6, corner + 6 };
    polygons->InsertNextCell(4, side);
  }
  auto prism = vtkSmartPointer<vtkPolyData>::New();
  prism->SetPoints(points);
  prism->SetPolys(polygons);
  return prism;
}
}

int TestPhongPolygonsAndStrips(int argc, char* argv[])
{
  vtkPhongTest::Scene scene(400, 300);
  const double key[3] = { 1.0, 1.2, 1.5 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  vtkPhongTest::AddLight(scene, key, origin, white, false);

  auto material = [](double r, double g, double b)
  {
    auto property = vtkSmartPointer<vtkPhongProperty>::New();
    property->SetColor(r, g, b);
    property->SetAmbient(0.15);
    property->SetSpecular(0.5);
    property->SetShininess(30.0);
    return property;
  };

  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(0.5);
  cube->SetYLength(0.5);
  cube->SetZLength(0.5);
  cube->Update();
  vtkActor* quads = vtkPhongTest::AddActor(scene, cube->GetOutput(), material(0.9, 0.5, 0.2));
  quads->SetPosition(-0.6, 0.35, 0.0);
  quads->RotateX(30.0);
  quads->RotateY(35.0);

  vtkActor* hexagons = vtkPhongTest::AddActor(scene, MakeHexagonalPrism(), material(0.3, 0.8, 0.4));
  hexagons->SetPosition(-0.6, -0.4, 0.0);
  hexagons->RotateX(-50.0);

  vtkNew<vtkStripper> stripper;
  stripper->SetInputData(vtkPhongTest::MakeSphere(48, 0.45));
  stripper->Update();
  vtkActor* strips = vtkPhongTest::AddActor(scene, stripper->GetOutput(), material(0.3, 0.5, 0.95));
  strips->SetPosition(0.5, 0.0, 0.0);

  scene.LookFromZ(3.8);
  scene.Window->Render();

  vtkPhongTest::Checks checks;
  checks.Expect(stripper->GetOutput()->GetNumberOfStrips() > 0 &&
      stripper->GetOutput()->GetNumberOfPolys() == 0,
    "the sphere is drawn from triangle strips only");
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
