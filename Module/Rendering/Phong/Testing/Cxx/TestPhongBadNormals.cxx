// Normals people really have: some zero-length, some NaN, or all too short or too long
// for float. The fragments that interpolate them fall back to the face's geometric normal
// (per fragment) or to facing the eye (per vertex); no pixel is NaN (black) and no error
// stops the render.

#include "vtkPhongTestUtilities.h"

#include <limits>
#include <utility>

namespace
{
// The sphere under one light, its normals scaled by `scale`, as the 8-bit picture.
vtkSmartPointer<vtkImageData> RenderScaledNormals(double scale)
{
  vtkPhongTest::Scene view(96, 96);
  auto sphere = vtkPhongTest::MakeSphere(48, 0.45);
  vtkDataArray* normals = sphere->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
  {
    const double* n = normals->GetTuple3(i);
    normals->SetTuple3(i, scale * n[0], scale * n[1], scale * n[2]);
  }
  vtkNew<vtkPhongProperty> material;
  material->SetColor(0.8, 0.7, 0.5);
  material->SetAmbient(0.3);
  material->SetSpecular(0.4);
  material->SetShininess(30.0);
  vtkPhongTest::AddActor(view, sphere, material);
  view.LookFromZ(1.6);
  view.Window->Render();
  return vtkPhongTest::Snapshot(view.Window);
}

// Normals valid in double but too short or too long to normalize in float (1e-20 and 1e20
// times unit length): the shader normalized them to infinite vectors and drew white and black
// pixels. They now take the face's geometric normal: the picture of unit normals, faceted.
void CheckNormalsBeyondFloat(vtkPhongTest::Checks& checks)
{
  auto unit = RenderScaledNormals(1.0);
  const std::pair<double, const char*> scales[] = { { 1.0e-20, "1e-20" }, { 1.0e20, "1e20" } };
  for (const auto& scale : scales)
  {
    const int difference = vtkPhongTest::MaxDifference(unit, RenderScaledNormals(scale.first));
    checks.Expect(difference <= 24,
      std::string("normals ") + scale.second +
        " times unit length: the unit normals' picture, faceted (largest difference " +
        std::to_string(difference) + " levels)");
  }
}
}

int TestPhongBadNormals(int argc, char* argv[])
{
  vtkPhongTest::Scene scene(300, 150);
  auto sphere = vtkPhongTest::MakeSphere(48, 0.45);
  vtkDataArray* normals = sphere->GetPointData()->GetNormals();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
  {
    if (i % 3 == 0)
    {
      normals->SetTuple3(i, 0.0, 0.0, 0.0);
    }
    else if (i % 3 == 1)
    {
      normals->SetTuple3(i, nan, nan, nan);
    }
  }
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkPhongProperty> material;
    material->SetColor(0.8, 0.7, 0.5);
    material->SetAmbient(0.3);
    material->SetSpecular(0.4);
    material->SetShininess(30.0);
    if (i == 1)
    {
      material->SetInterpolationToPerVertexGouraud();
    }
    vtkActor* actor = vtkPhongTest::AddActor(scene, sphere, material);
    actor->SetPosition(i == 0 ? -0.55 : 0.55, 0.0, 0.0);
  }
  scene.LookFromZ(2.6);
  scene.Window->Render();

  // Every pixel inside each sphere's silhouette is at least its ambient level.
  vtkPhongTest::Checks checks;
  auto image = vtkPhongTest::Snapshot(scene.Window);
  const int centres[2] = { 75, 225 };
  for (int i = 0; i < 2; ++i)
  {
    int darkest = 255;
    for (int y = 55; y < 95; ++y)
    {
      for (int x = centres[i] - 20; x < centres[i] + 20; ++x)
      {
        darkest = std::min(darkest, int(vtkPhongTest::PixelAt(image, x, y)[0]));
      }
    }
    checks.Expect(darkest >= int(0.3 * 0.8 * 255) - 1,
      std::string(i == 0 ? "per-fragment" : "per-vertex") + ": no NaN pixel (darkest red " +
        std::to_string(darkest) + ")");
  }
  CheckNormalsBeyondFloat(checks);
  return vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);
}
