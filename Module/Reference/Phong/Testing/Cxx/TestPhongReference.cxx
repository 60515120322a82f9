// The double-precision reference on its own: closed-form values of the equation for every
// term, lobe and light kind, VTK's placement of headlights and camera lights, parameters out of
// range, the exactness of the ray-cast surfaces (sphere, plane through the actor's matrix,
// torus), the agreement of its two entry points (an analytic image shaded again as a
// G-buffer), and its error paths. TestPhongExtremes measures the GPU against it.

#include "vtkPhongReferenceTesting.h"

#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"

#include <array>
#include <limits>

namespace
{
using RGB = std::array<double, 3>;

// A renderer that is never drawn: the reference reads its camera and lights. The camera looks
// from (0, 0, 5) at the origin, so the point (0, 0, 0) is seen with V = (0, 0, 1).
struct ReferenceScene
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkPhongProperty> Material;
  vtkNew<vtkPhongReference> Reference;

  ReferenceScene()
  {
    this->Renderer->AutomaticLightCreationOff();
    this->Renderer->SetAmbient(0.0, 0.0, 0.0);
    this->Actor->SetProperty(this->Material);
    this->Material->SetColor(1.0, 1.0, 1.0);
    this->Material->SetAmbient(0.0);
    this->Material->SetDiffuse(0.0);
    this->Material->SetSpecular(0.0);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(0.0, 0.0, 5.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    this->Reference->SetRenderer(this->Renderer);
    this->Reference->SetActor(this->Actor);
    this->Reference->SetImageSize(64, 64);
  }

  vtkLight* Add(double x, double y, double z, bool positional)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPosition(x, y, z);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    light->SetPositional(positional);
    light->SetConeAngle(180.0);
    light->SetAttenuationValues(1.0, 0.0, 0.0);
    this->Renderer->AddLight(light);
    return light;
  }

  RGB Shade(const double position[3], const double normal[3], bool backFace = false)
  {
    RGB rgb;
    this->Reference->ShadePoint(position, normal, backFace, rgb.data());
    return rgb;
  }
};

const double origin[3] = { 0.0, 0.0, 0.0 };
const double up[3] = { 0.0, 0.0, 1.0 };

void ExpectRGB(vtkPhongTest::Checks& checks, const RGB& got, const RGB& expected,
  const std::string& what, double tolerance = 1e-12)
{
  for (int c = 0; c < 3; ++c)
  {
    checks.Near(got[c], expected[c], tolerance * std::max(1.0, std::abs(expected[c])),
      what + " [" + std::to_string(c) + "]");
  }
}

void ExpectGray(vtkPhongTest::Checks& checks, const RGB& got, double expected,
  const std::string& what, double tolerance = 1e-12)
{
  ExpectRGB(checks, got, { expected, expected, expected }, what, tolerance);
}

// Render the analytic surface and check every hit: the implicit function (relative to
// scale) and the normal's length; and the number of hits when expectedHits >= 0.
template <typename Implicit>
void CheckHits(vtkPhongTest::Checks& checks, vtkPhongReference* reference, Implicit implicit,
  double scale, vtkIdType expectedHits, double hitTolerance, const std::string& what)
{
  vtkNew<vtkImageData> image;
  checks.Expect(reference->RenderAnalytic(image) == 1, what + ": rendered");
  vtkDataArray* positions = image->GetPointData()->GetArray("PositionWC");
  vtkDataArray* normals = image->GetPointData()->GetArray("NormalWC");
  vtkDataArray* rgba = image->GetPointData()->GetScalars();
  if (!positions || !normals || !rgba)
  {
    checks.Expect(false, what + ": the image has RGBA, PositionWC and NormalWC");
    return;
  }
  vtkIdType hits = 0;
  double worstSurface = 0.0, worstNormal = 0.0;
  for (vtkIdType i = 0; i < rgba->GetNumberOfTuples(); ++i)
  {
    if (rgba->GetComponent(i, 3) == 0.0)
    {
      continue;
    }
    ++hits;
    double p[3], n[3];
    positions->GetTuple(i, p);
    normals->GetTuple(i, n);
    worstSurface = std::max(worstSurface, std::abs(implicit(p)) / scale);
    worstNormal = std::max(worstNormal, std::abs(vtkMath::Norm(n) - 1.0));
  }
  checks.Expect(expectedHits < 0 || std::abs(hits - expectedHits) <= hitTolerance * expectedHits,
    what + ": " + std::to_string(hits) + " pixels hit, about " + std::to_string(expectedHits) +
      " expected");
  checks.Expect(worstSurface < 1e-12,
    what + ": hits lie on the surface (worst " + std::to_string(worstSurface) + ")");
  checks.Expect(worstNormal < 1e-14, what + ": unit normals");
}
}

int TestPhongReference(int, char*[])
{
  vtkPhongTest::Checks checks;

  { // E + ka*Ca*Ia, no light
    ReferenceScene scene;
    scene.Renderer->SetAmbient(0.5, 0.25, 1.0);
    scene.Material->SetAmbient(0.4);
    scene.Material->SetAmbientColor(1.0, 0.5, 0.5);
    scene.Material->SetEmission(0.1, 0.2, 0.3);
    ExpectRGB(checks, scene.Shade(origin, up), { 0.3, 0.25, 0.5 }, "emission + ka*Ca*Ia");
  }
  { // kd*Cd*Ld*I*(N.L) + ks*Cs*Ls*I*S with the light behind the eye: R = V, S = 1 for any n
    ReferenceScene scene;
    vtkLight* light = scene.Add(0.0, 0.0, 1.0, false);
    light->SetIntensity(0.5);
    light->SetDiffuseColor(1.0, 0.5, 0.0);
    light->SetSpecularColor(0.0, 1.0, 1.0);
    scene.Material->SetDiffuse(0.8);
    scene.Material->SetSpecular(0.6);
    scene.Material->SetShininess(1.0e6);
    ExpectRGB(checks, scene.Shade(origin, up), { 0.4, 0.5, 0.3 }, "diffuse + specular");
  }
  { // a light 60 degrees off the normal, V = N: Phong R.V = 1/2, Blinn N.H = cos(30 degrees)
    const double n = 10.0;
    const double phong = std::pow(0.5, n);
    const double blinn = std::pow(std::sqrt(3.0) / 2.0, n);
    const std::pair<int, double> lobes[] = { { vtkPhongProperty::Phong, phong },
      { vtkPhongProperty::BlinnPhong, blinn },
      { vtkPhongProperty::NormalizedPhong, phong * (n + 2.0) / 2.0 },
      { vtkPhongProperty::NormalizedBlinnPhong, blinn * (n + 8.0) / 8.0 } };
    for (const auto& lobe : lobes)
    {
      ReferenceScene scene;
      scene.Add(std::sqrt(3.0) / 2.0, 0.0, 0.5, false);
      scene.Material->SetSpecular(1.0);
      scene.Material->SetShininess(n);
      scene.Material->SetLightingModel(lobe.first);
      ExpectGray(checks, scene.Shade(origin, up), lobe.second,
        std::string("lobe ") + scene.Material->GetLightingModelAsString());
    }
  }
  { // the gate: shut below N.L = 1e-4, open above; the smooth terminator scales by N.L
    ReferenceScene scene;
    vtkLight* light = scene.Add(1.0, 0.0, 5.0e-5, false);
    scene.Material->SetSpecular(1.0);
    scene.Material->SetShininess(0.0);
    ExpectGray(checks, scene.Shade(origin, up), 0.0, "gate shut at N.L = 5e-5");
    light->SetPosition(1.0, 0.0, 2.0e-4);
    ExpectGray(checks, scene.Shade(origin, up), 1.0, "gate open at N.L = 2e-4 (n = 0)");
    scene.Material->SmoothTerminatorOn();
    light->SetPosition(1.0, 0.0, 1.0);
    ExpectGray(checks, scene.Shade(origin, up), std::sqrt(0.5), "smooth terminator: S*N.L");
  }
  { // n = 0 where R points away from the eye: the lobe is 1, not pow(0, 0) undefined
    ReferenceScene scene;
    scene.Add(-1.0, 0.0, 0.1, false);
    scene.Material->SetSpecular(1.0);
    scene.Material->SetShininess(0.0);
    const double side[3] = { 3.0, 0.0, 0.0 }; // V = (-3, 0, 5)/|.|: R.V < 0
    ExpectGray(checks, scene.Shade(side, up), 1.0, "n = 0 with R.V < 0");
    scene.Material->SetShininess(2.0);
    ExpectGray(checks, scene.Shade(side, up), 0.0, "n = 2 with R.V < 0");
  }
  { // L = -V on a back face lit one-sided: N.L = 1, no halfway vector, no highlight
    ReferenceScene scene;
    scene.Renderer->TwoSidedLightingOff();
    scene.Add(0.0, 0.0, -1.0, false);
    scene.Material->SetDiffuse(1.0);
    scene.Material->SetSpecular(1.0);
    scene.Material->SetLightingModelToBlinnPhong();
    const double averted[3] = { 0.0, 0.0, -1.0 };
    for (double n : { 0.0, 1.0, 100.0 })
    {
      scene.Material->SetShininess(n);
      ExpectGray(
        checks, scene.Shade(origin, averted, true), 1.0, "L = -V, n = " + std::to_string(n));
    }
  }
  { // point light: A = 1/(c + l*d + q*d^2), its ambient colour counts
    ReferenceScene scene;
    scene.Renderer->SetAmbient(1.0, 1.0, 1.0);
    vtkLight* light = scene.Add(0.0, 0.0, 2.0, true);
    light->SetAttenuationValues(1.0, 0.5, 0.25); // d = 2: denominator 3
    light->SetAmbientColor(0.3, 0.3, 0.3);
    scene.Material->SetAmbient(0.5);
    scene.Material->SetDiffuse(1.0);
    ExpectGray(checks, scene.Shade(origin, up), 0.5 + 0.5 * 0.3 / 3.0 + 1.0 / 3.0,
      "point light with attenuation and ambient colour");
    // The light on the point: L = N, the denominator floored at 1e-20.
    light->SetPosition(0.0, 0.0, 0.0);
    light->SetAttenuationValues(0.0, 0.0, 1.0);
    light->SetAmbientColor(0.0, 0.0, 0.0);
    scene.Material->SetAmbient(0.0);
    ExpectGray(checks, scene.Shade(origin, up), 1.0e20, "light at the point: A = 1e20");
  }
  { // spot: cos(phi) = 2/sqrt(5) (26.57 degrees), exponent 2, hard and soft cone edges
    ReferenceScene scene;
    vtkLight* spot = scene.Add(0.0, 0.0, 2.0, true);
    spot->SetFocalPoint(1.0, 0.0, 0.0);
    spot->SetConeAngle(30.0);
    spot->SetExponent(2.0);
    scene.Material->SetDiffuse(1.0);
    const double cosPhi = 2.0 / std::sqrt(5.0);
    ExpectGray(checks, scene.Shade(origin, up), cosPhi * cosPhi, "inside the cone");
    scene.Material->SoftSpotEdgeOn();
    scene.Material->SetSpotEdgeWidth(5.0);
    const double edge0 = std::cos(vtkMath::RadiansFromDegrees(30.0));
    const double edge1 = std::cos(vtkMath::RadiansFromDegrees(25.0));
    const double t = (cosPhi - edge0) / (edge1 - edge0);
    ExpectGray(
      checks, scene.Shade(origin, up), cosPhi * cosPhi * t * t * (3.0 - 2.0 * t), "soft cone edge");
    spot->SetConeAngle(20.0);
    ExpectGray(checks, scene.Shade(origin, up), 0.0, "outside the cone");
  }
  { // parameters out of range count as 0
    ReferenceScene scene;
    scene.Material->SetDiffuse(1.0);
    vtkLight* negative = scene.Add(0.0, 0.0, 1.0, false);
    negative->SetIntensity(-1.0);
    vtkLight* nan = scene.Add(0.0, 0.0, 1.0, false);
    nan->SetDiffuseColor(std::numeric_limits<double>::quiet_NaN(), 1.0, 0.5);
    ExpectRGB(checks, scene.Shade(origin, up), { 0.0, 1.0, 0.5 },
      "negative intensity and NaN colour component count as 0");
  }
  { // headlight and camera lights follow the camera as vtkRenderer places them
    ReferenceScene scene;
    scene.Material->SetDiffuse(1.0);
    vtkNew<vtkLight> headlight;
    headlight->SetLightTypeToHeadlight();
    headlight->SetPositional(true);
    headlight->SetConeAngle(180.0);
    headlight->SetAttenuationValues(0.0, 0.0, 1.0);
    scene.Renderer->AddLight(headlight);
    ExpectGray(checks, scene.Shade(origin, up), 1.0 / 25.0, "positional headlight at the camera");
    headlight->SwitchOff();
    vtkNew<vtkLight> cameraLight;
    cameraLight->SetLightTypeToCameraLight();
    cameraLight->SetPosition(1.0, 0.0, 1.0); // one camera distance to the right of the camera
    cameraLight->SetPositional(true);
    cameraLight->SetConeAngle(180.0);
    cameraLight->SetAttenuationValues(0.0, 0.0, 1.0);
    scene.Renderer->AddLight(cameraLight);
    ExpectGray(checks, scene.Shade(origin, up), (5.0 / std::sqrt(50.0)) / 50.0,
      "camera light in camera coordinates");
  }
  { // two-sided lighting: a back face takes the back-face property
    ReferenceScene scene;
    scene.Add(0.0, 0.0, 1.0, false);
    scene.Material->SetDiffuse(1.0);
    vtkNew<vtkPhongProperty> back;
    back->SetColor(0.2, 0.4, 0.6);
    back->SetAmbient(0.0);
    back->SetDiffuse(1.0);
    back->SetSpecular(0.0);
    back->SetEmission(0.1, 0.0, 0.0);
    scene.Actor->SetBackfaceProperty(back);
    ExpectRGB(checks, scene.Shade(origin, up, true), { 0.3, 0.4, 0.6 }, "back material");
    scene.Renderer->TwoSidedLightingOff();
    ExpectGray(checks, scene.Shade(origin, up, true), 1.0, "one-sided: the front material");
  }

  // Ray-cast surfaces: every hit lies on the surface.
  {
    ReferenceScene scene;
    scene.Add(1.0, 1.0, 1.0, false);
    scene.Material->SetDiffuse(1.0);
    scene.Reference->SetSurfaceToSphere(0.2, -0.1, 0.3, 1.0);
    // The sphere seen from 5 - 0.3 = 4.7 away: angular radius asin(1/4.7) in a 30 degree view.
    const double radiusPixels = 32.0 * std::tan(std::asin(1.0 / std::sqrt(4.7 * 4.7 + 0.05))) /
      std::tan(vtkMath::RadiansFromDegrees(15.0));
    CheckHits(
      checks, scene.Reference,
      [](const double p[3])
      {
        const double d[3] = { p[0] - 0.2, p[1] + 0.1, p[2] - 0.3 };
        return vtkMath::Dot(d, d) - 1.0;
      },
      1.0, static_cast<vtkIdType>(vtkMath::Pi() * radiusPixels * radiusPixels), 0.05, "sphere");

    // A plane through the actor's matrix: hits satisfy the transformed plane's equation.
    const double o[3] = { -1.0, -1.0, 0.0 }, p1[3] = { 1.0, -1.0, 0.0 }, p2[3] = { -1.0, 1.0, 0.0 };
    scene.Reference->SetSurfaceToPlane(o, p1, p2);
    scene.Actor->RotateX(30.0);
    scene.Actor->SetPosition(0.1, 0.2, 0.3);
    vtkMatrix4x4* matrix = scene.Actor->GetMatrix();
    const double normal[3] = { matrix->GetElement(0, 2), matrix->GetElement(1, 2),
      matrix->GetElement(2, 2) };
    const double centre[3] = { 0.1, 0.2, 0.3 };
    // Projected area of a 2x2 square tilted by 30 degrees at distance about 4.7.
    const double pixelsPerUnit = 32.0 / (4.7 * std::tan(vtkMath::RadiansFromDegrees(15.0)));
    CheckHits(
      checks, scene.Reference,
      [&](const double p[3])
      {
        const double d[3] = { p[0] - centre[0], p[1] - centre[1], p[2] - centre[2] };
        return vtkMath::Dot(d, normal);
      },
      1.0,
      static_cast<vtkIdType>(
        4.0 * std::cos(vtkMath::RadiansFromDegrees(30.0)) * pixelsPerUnit * pixelsPerUnit),
      0.15, "plane through the actor's matrix");

    // A torus around z: (|p|^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + y^2).
    scene.Actor->SetOrientation(0.0, 0.0, 0.0);
    scene.Actor->SetPosition(0.0, 0.0, 0.0);
    scene.Actor->RotateX(-60.0);
    scene.Reference->SetSurfaceToTorus(0.0, 0.0, 0.0, 1.0, 0.3);
    vtkNew<vtkMatrix4x4> inverse;
    vtkMatrix4x4::Invert(scene.Actor->GetMatrix(), inverse);
    CheckHits(
      checks, scene.Reference,
      [&](const double world[3])
      {
        double p[4] = { world[0], world[1], world[2], 1.0 };
        inverse->MultiplyPoint(p, p);
        const double s = p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + 1.0 - 0.09;
        return s * s - 4.0 * (p[0] * p[0] + p[1] * p[1]);
      },
      1.0, -1, 0.0, "torus");
  }

  // The two entry points agree: an analytic picture, turned into a view-coordinate G-buffer,
  // shades to the same colours.
  {
    ReferenceScene scene;
    scene.Renderer->SetAmbient(0.2, 0.2, 0.2);
    scene.Add(1.0, 1.0, 2.0, false);
    vtkLight* point = scene.Add(-1.0, 0.5, 1.5, true);
    point->SetAttenuationValues(1.0, 0.3, 0.1);
    scene.Material->SetAmbient(0.2);
    scene.Material->SetDiffuse(0.7);
    scene.Material->SetSpecular(0.5);
    scene.Material->SetShininess(30.0);
    scene.Reference->SetSurfaceToSphere(0.0, 0.0, 0.0, 1.0);
    vtkNew<vtkImageData> analytic;
    scene.Reference->RenderAnalytic(analytic);
    vtkMatrix4x4* view = scene.Renderer->GetActiveCamera()->GetModelViewTransformMatrix();
    vtkDataArray* positions = analytic->GetPointData()->GetArray("PositionWC");
    vtkDataArray* normals = analytic->GetPointData()->GetArray("NormalWC");
    vtkDataArray* colours = analytic->GetPointData()->GetScalars();
    vtkNew<vtkImageData> positionVC, normalVC;
    for (vtkImageData* image : { positionVC.Get(), normalVC.Get() })
    {
      image->SetDimensions(analytic->GetDimensions());
      vtkNew<vtkDoubleArray> values;
      values->SetNumberOfComponents(4);
      values->SetNumberOfTuples(colours->GetNumberOfTuples());
      image->GetPointData()->SetScalars(values);
    }
    for (vtkIdType i = 0; i < colours->GetNumberOfTuples(); ++i)
    {
      double p[4] = { 0, 0, 0, 1 }, n[4] = { 0, 0, 0, 0 };
      positions->GetTuple(i, p);
      normals->GetTuple(i, n);
      p[3] = 1.0;
      view->MultiplyPoint(p, p);
      n[3] = 0.0;
      view->MultiplyPoint(n, n); // the view is a rotation: normals turn like vectors
      const double alpha = colours->GetComponent(i, 3);
      const double position[4] = { p[0], p[1], p[2], alpha };
      const double normal[4] = { n[0], n[1], n[2], alpha };
      positionVC->GetPointData()->GetScalars()->SetTuple(i, position);
      normalVC->GetPointData()->GetScalars()->SetTuple(i, normal);
    }
    vtkNew<vtkImageData> shaded;
    checks.Expect(
      scene.Reference->ShadeGBuffer(positionVC, normalVC, shaded) == 1, "G-buffer shaded");
    double worst = 0.0;
    for (vtkIdType i = 0; i < colours->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < 4; ++c)
      {
        worst = std::max(worst,
          std::abs(shaded->GetPointData()->GetScalars()->GetComponent(i, c) -
            colours->GetComponent(i, c)));
      }
    }
    checks.Expect(
      worst < 1e-13, "G-buffer and analytic shading agree (worst " + std::to_string(worst) + ")");
  }

  // Error paths: an error each, never a crash.
  {
    vtkPhongTest::ErrorCollector errors;
    vtkNew<vtkPhongReference> lonely;
    errors.Observe(lonely);
    vtkNew<vtkImageData> image;
    lonely->SetImageSize(8, 8);
    checks.Expect(lonely->RenderAnalytic(image) == 0 && errors.Contains("needs a renderer"),
      "no scene: an error");
    ReferenceScene scene;
    errors.Observe(scene.Reference);
    checks.Expect(
      scene.Reference->RenderAnalytic(image) == 0 && errors.Contains("No analytic surface"),
      "no surface: an error");
    scene.Reference->SetSurfaceToSphere(0.0, 0.0, 0.0, 0.0);
    checks.Expect(scene.Reference->RenderAnalytic(image) == 0 && errors.Contains("degenerate"),
      "a sphere of radius 0: an error");
    scene.Reference->SetImageSize(0, 0); // the renderer is in no window: no size
    scene.Reference->SetSurfaceToSphere(0.0, 0.0, 0.0, 1.0);
    checks.Expect(scene.Reference->RenderAnalytic(image) == 0 && errors.Contains("No image size"),
      "no image size: an error");
    vtkNew<vtkImageData> small, large;
    small->SetDimensions(4, 4, 1);
    small->AllocateScalars(VTK_FLOAT, 4);
    large->SetDimensions(8, 4, 1);
    large->AllocateScalars(VTK_FLOAT, 4);
    checks.Expect(
      scene.Reference->ShadeGBuffer(small, large, image) == 0 && errors.Contains("equal size"),
      "mismatched G-buffer: an error");
  }

  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
