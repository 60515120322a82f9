// Lines and points keep working: a helix of lines with normals (lit per
// fragment), the same helix drawn as tubes, a sphere's points drawn as lit
// spheres, and plain unlit points (VTK does not light points without normals).

#include "vtkPhongTestUtilities.h"

int TestPhongLinesAndPoints(int argc, char* argv[])
{
  vtkPhongTest::Scene scene(400, 300);
  const double key[3] = { 1.0, 1.0, 1.5 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double white[3] = { 1.0, 1.0, 1.0 };
  vtkPhongTest::AddLight(scene, key, origin, white, false);

  // A helix polyline whose normals point away from its axis.
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  vtkNew<vtkCellArray> lines;
  const int samples = 200;
  lines->InsertNextCell(samples);
  for (int i = 0; i < samples; ++i)
  {
    const double angle = 6.0 * vtkMath::Pi() * i / (samples - 1);
    points->InsertNextPoint(
      0.3 * std::cos(angle), -0.5 + i / double(samples - 1), 0.3 * std::sin(angle));
    normals->InsertNextTuple3(std::cos(angle), 0.0, std::sin(angle));
    lines->InsertCellPoint(i);
  }
  vtkNew<vtkPolyData> helix;
  helix->SetPoints(points);
  helix->SetLines(lines);
  helix->GetPointData()->SetNormals(normals);

  auto material = [](double r, double g, double b)
  {
    auto property = vtkSmartPointer<vtkPhongProperty>::New();
    property->SetColor(r, g, b);
    property->SetAmbient(0.2);
    property->SetSpecular(0.6);
    property->SetShininess(30.0);
    return property;
  };

  auto lineMaterial = material(0.9, 0.7, 0.2);
  lineMaterial->SetLineWidth(2.0);
  vtkActor* thinLines = vtkPhongTest::AddActor(scene, helix, lineMaterial);
  thinLines->SetPosition(-0.75, 0.0, 0.0);

  auto tubeMaterial = material(0.3, 0.8, 0.5);
  tubeMaterial->SetLineWidth(8.0);
  tubeMaterial->RenderLinesAsTubesOn();
  vtkActor* tubes = vtkPhongTest::AddActor(scene, helix, tubeMaterial);
  tubes->SetPosition(-0.05, 0.0, 0.0);

  auto sphere = vtkPhongTest::MakeSphere(12, 0.35);
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(sphere->GetPoints());
  vtkNew<vtkCellArray> vertices;
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    vertices->InsertNextCell(1, &i);
  }
  cloud->SetVerts(vertices);
  auto ballMaterial = material(0.4, 0.5, 1.0);
  ballMaterial->SetPointSize(14.0);
  ballMaterial->RenderPointsAsSpheresOn();
  vtkActor* balls = vtkPhongTest::AddActor(scene, cloud, ballMaterial);
  balls->SetPosition(0.65, 0.3, 0.0);

  auto dotMaterial = material(1.0, 0.4, 0.4);
  dotMaterial->SetPointSize(4.0);
  vtkActor* dots = vtkPhongTest::AddActor(scene, cloud, dotMaterial);
  dots->SetPosition(0.65, -0.5, 0.0);
  dots->SetScale(0.6);

  scene.LookFromZ(3.6);
  scene.Window->Render();
  return vtkPhongTest::Finish(argc, argv, scene.Window);
}
