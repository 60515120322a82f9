#include "vtkPhongReference.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPhongProperty.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

// Everything below is written from docs/lighting-model.md, in double precision. It must not
// call into the shader path (planner, template, uniforms) or read the GLSL: it is the independent
// side of every comparison.

namespace
{
using glm::dmat3;
using glm::dmat4;
using glm::dvec3;
using glm::dvec4;

dmat4 ToGLM(vtkMatrix4x4* matrix)
{
  dmat4 result;
  for (int row = 0; row < 4; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      result[column][row] = matrix->GetElement(row, column); // GLM is column-major
    }
  }
  return result;
}

dvec3 Transform(const dmat4& matrix, const dvec3& point)
{
  const dvec4 result = matrix * dvec4(point, 1.0);
  return dvec3(result) / result.w;
}

dvec3 ToDVec3(const double* values)
{
  return dvec3(values[0], values[1], values[2]);
}

// The model's treatment of values out of range: not finite (or, where asked, negative)
// counts as 0.
double Finite(double value)
{
  return std::isfinite(value) ? value : 0.0;
}

double FiniteNonNegative(double value)
{
  return (std::isfinite(value) && value >= 0.0) ? value : 0.0;
}

dvec3 FiniteColor(const double* rgb)
{
  return dvec3(Finite(rgb[0]), Finite(rgb[1]), Finite(rgb[2]));
}

dvec3 FiniteNonNegativeColor(const double* rgb)
{
  return dvec3(FiniteNonNegative(rgb[0]), FiniteNonNegative(rgb[1]), FiniteNonNegative(rgb[2]));
}

// smoothstep as GLSL defines it, with a zero-width band read as a step at the edge.
double SmoothStep(double edge0, double edge1, double x)
{
  if (!(edge1 > edge0))
  {
    return x >= edge0 ? 1.0 : 0.0;
  }
  const double t = std::min(std::max((x - edge0) / (edge1 - edge0), 0.0), 1.0);
  return t * t * (3.0 - 2.0 * t);
}

enum class LightKind
{
  Directional,
  Point,
  Spot
};

struct ReferenceLight
{
  LightKind Kind = LightKind::Directional;
  dvec3 PositionWC{ 0.0 };
  dvec3 ToLightWC{ 0.0, 0.0, 1.0 }; // directional lights: unit L
  dvec3 AxisWC{ 0.0, 0.0, -1.0 };   // spots: unit, from the light to its focal point
  double CosCutoff = -1.0;
  double CosInner = -1.0;
  double Exponent = 0.0;
  dvec3 Attenuation{ 1.0, 0.0, 0.0 };
  dvec3 Ambient{ 0.0 };  // La * I
  dvec3 Diffuse{ 0.0 };  // Ld * I
  dvec3 Specular{ 0.0 }; // Ls * I
};

struct ReferenceMaterial
{
  dvec3 Emission{ 0.0 };
  dvec3 Ambient{ 0.0 };  // ka * Ca
  dvec3 Diffuse{ 0.0 };  // kd * Cd
  dvec3 Specular{ 0.0 }; // ks * Cs, times the lobe's normalization
  double Shininess = 1.0;
};

// A property's material under the lighting model. The normalized lobes' factor is a constant
// of the material, so it is folded into the specular term, as the shader does.
ReferenceMaterial MaterialOf(vtkProperty* property, int model)
{
  ReferenceMaterial material;
  auto* phong = vtkPhongProperty::SafeDownCast(property);
  material.Shininess = phong ? phong->GetShininess() : property->GetSpecularPower();
  const double n = material.Shininess;
  double normalization = 1.0;
  if (model == vtkPhongProperty::NormalizedPhong)
  {
    normalization = (n + 2.0) / 2.0;
  }
  else if (model == vtkPhongProperty::NormalizedBlinnPhong)
  {
    normalization = (n + 8.0) / 8.0;
  }
  material.Ambient = Finite(property->GetAmbient()) * FiniteColor(property->GetAmbientColor());
  material.Diffuse = Finite(property->GetDiffuse()) * FiniteColor(property->GetDiffuseColor());
  material.Specular =
    Finite(property->GetSpecular()) * normalization * FiniteColor(property->GetSpecularColor());
  if (phong)
  {
    material.Emission = FiniteNonNegativeColor(phong->GetEmission());
  }
  return material;
}

// Headlights and camera lights follow the camera as vtkRenderer places them. Camera-light
// coordinates have the camera at (0, 0, 1) looking at the focal point at the origin, one
// unit being the camera's distance.
dmat4 CameraLightToWorld(vtkCamera* camera)
{
  return glm::inverse(ToGLM(camera->GetViewTransformMatrix())) *
    dmat4(dvec4(camera->GetDistance(), 0, 0, 0), dvec4(0, camera->GetDistance(), 0, 0),
      dvec4(0, 0, camera->GetDistance(), 0), dvec4(0, 0, -camera->GetDistance(), 1));
}

// The light's position and focal point in world coordinates; a headlight sits at the camera
// and looks at its focal point.
void PlaceLight(vtkLight* light, vtkCamera* camera, bool follow, const dmat4& cameraLightToWorld,
  dvec3& position, dvec3& focalPoint)
{
  if (follow && light->LightTypeIsHeadlight())
  {
    position = ToDVec3(camera->GetPosition());
    focalPoint = ToDVec3(camera->GetFocalPoint());
  }
  else if (follow && light->LightTypeIsCameraLight())
  {
    position = Transform(cameraLightToWorld, ToDVec3(light->GetPosition()));
    focalPoint = Transform(cameraLightToWorld, ToDVec3(light->GetFocalPoint()));
  }
  else
  {
    double transformed[3];
    light->GetTransformedPosition(transformed);
    position = ToDVec3(transformed);
    light->GetTransformedFocalPoint(transformed);
    focalPoint = ToDVec3(transformed);
  }
}

ReferenceLight ToReferenceLight(vtkLight* light, const dvec3& position, const dvec3& focalPoint,
  const dvec3& viewDirectionWC, double spotEdgeWidth)
{
  ReferenceLight reference;
  const dvec3 axis = focalPoint - position;
  const double axisLength = glm::length(axis);
  // Without a direction a light shines along the view direction.
  const dvec3 unitAxis =
    (axisLength > 0.0 && std::isfinite(axisLength)) ? axis / axisLength : viewDirectionWC;
  if (!light->GetPositional())
  {
    reference.Kind = LightKind::Directional;
    reference.ToLightWC = -unitAxis;
  }
  else
  {
    reference.Kind = light->GetConeAngle() < 90.0 ? LightKind::Spot : LightKind::Point;
    reference.PositionWC = position;
    reference.AxisWC = unitAxis;
    const double* attenuation = light->GetAttenuationValues();
    reference.Attenuation = dvec3(FiniteNonNegative(attenuation[0]),
      FiniteNonNegative(attenuation[1]), FiniteNonNegative(attenuation[2]));
    const double cone = std::max(light->GetConeAngle(), 0.0);
    reference.CosCutoff = std::cos(glm::radians(cone));
    reference.CosInner = std::cos(glm::radians(std::max(cone - spotEdgeWidth, 0.0)));
    reference.Exponent = FiniteNonNegative(light->GetExponent());
  }
  const double intensity = FiniteNonNegative(light->GetIntensity());
  reference.Ambient = intensity * FiniteNonNegativeColor(light->GetAmbientColor());
  reference.Diffuse = intensity * FiniteNonNegativeColor(light->GetDiffuseColor());
  reference.Specular = intensity * FiniteNonNegativeColor(light->GetSpecularColor());
  return reference;
}

// The terms of the sum in Internals::Shade, one light at a time.

double SpotFactor(const ReferenceLight& light, const dvec3& L, bool softSpotEdge)
{
  const double cosPhi = glm::dot(-L, light.AxisWC);
  double spot = cosPhi >= light.CosCutoff ? std::pow(std::max(cosPhi, 0.0), light.Exponent) : 0.0;
  if (softSpotEdge)
  {
    spot *= SmoothStep(light.CosCutoff, light.CosInner, cosPhi);
  }
  return spot;
}

// A_i, the spot factor included. L is the unit vector from P to the light; it is set here
// for positional lights only (a directional light's is fixed).
double Attenuation(
  const ReferenceLight& light, const dvec3& P, const dvec3& N, bool softSpotEdge, dvec3& L)
{
  if (light.Kind == LightKind::Directional)
  {
    return 1.0;
  }
  const dvec3 toLight = light.PositionWC - P;
  const double d = glm::length(toLight);
  L = d > 0.0 ? toLight / d : N; // a light at the point lights it head-on
  const double denominator =
    light.Attenuation.x + light.Attenuation.y * d + light.Attenuation.z * d * d;
  double A = 1.0 / std::max(denominator, 1.0e-20);
  if (light.Kind == LightKind::Spot)
  {
    A *= SpotFactor(light, L, softSpotEdge);
  }
  return A;
}

double BlinnPhongLobe(const dvec3& N, const dvec3& L, const dvec3& V, double n)
{
  const dvec3 sum = L + V;
  const double length = glm::length(sum);
  if (!(length > 0.0)) // L = -V has no halfway vector, and no highlight
  {
    return 0.0;
  }
  const double cosine = std::min(std::max(glm::dot(N, sum / length), 0.0), 1.0);
  return n > 0.0 ? std::pow(cosine, n) : 1.0;
}

double PhongLobe(const dvec3& N, const dvec3& L, const dvec3& V, double NdotL, double n)
{
  const dvec3 R = 2.0 * NdotL * N - L;
  const double cosine = std::min(std::max(glm::dot(R, V), 0.0), 1.0);
  return n > 0.0 ? std::pow(cosine, n) : 1.0; // pow(0, 0) is 1 here
}

void SetRGBA(double* pixel, const dvec3& color)
{
  pixel[0] = color.r;
  pixel[1] = color.g;
  pixel[2] = color.b;
  pixel[3] = 1.0;
}
}

struct vtkPhongReference::Internals
{
  std::vector<ReferenceLight> Lights;
  ReferenceMaterial Front;
  ReferenceMaterial Back; // the front material unless two-sided with a back-face property
  dvec3 GlobalAmbient{ 1.0 };
  bool BlinnLobe = false;
  bool SmoothTerminator = false;
  bool SoftSpotEdge = false;
  double SpotEdgeWidth = 0.0;

  bool Parallel = false;
  dvec3 EyeWC{ 0.0 };
  dvec3 ToEyeParallelWC{ 0.0, 0.0, 1.0 };
  dmat4 WorldToView{ 1.0 };
  dmat4 ViewToWorld{ 1.0 };
  dmat4 ClipToWorld{ 1.0 };
  dmat4 ModelToWorld{ 1.0 };
  dmat4 WorldToModel{ 1.0 };
  dmat3 ModelNormalToWorld{ 1.0 };

  // C = E + ka*Ca*Ia + sum_i A_i (ka*Ca*La_i*I_i + kd*Cd*Ld_i*I_i*max(N.L_i, 0)
  //                               + ks*Cs*Ls_i*I_i*S_i*G_i)
  dvec3 Shade(const dvec3& P, const dvec3& N, bool backFace) const
  {
    const ReferenceMaterial& material = backFace ? this->Back : this->Front;
    const dvec3 V = this->Parallel ? this->ToEyeParallelWC : glm::normalize(this->EyeWC - P);
    const double n = material.Shininess;

    dvec3 ambientLight = this->GlobalAmbient;
    dvec3 diffuseLight(0.0);
    dvec3 specularLight(0.0);
    for (const ReferenceLight& light : this->Lights)
    {
      dvec3 L = light.ToLightWC;
      const double A = Attenuation(light, P, N, this->SoftSpotEdge, L);
      const double NdotL = glm::dot(N, L);
      const double lobe =
        this->BlinnLobe ? BlinnPhongLobe(N, L, V, n) : PhongLobe(N, L, V, NdotL, n);
      // The gate opens at N.L > 1e-4, not 0 (docs/lighting-model.md): N.L = 0 is
      // ill-conditioned in any precision.
      const double gate =
        this->SmoothTerminator ? std::max(NdotL, 0.0) : (NdotL > 1.0e-4 ? 1.0 : 0.0);

      ambientLight += A * light.Ambient;
      diffuseLight += (A * std::max(NdotL, 0.0)) * light.Diffuse;
      specularLight += (A * lobe * gate) * light.Specular;
    }
    return material.Emission + material.Ambient * ambientLight + material.Diffuse * diffuseLight +
      material.Specular * specularLight;
  }

  // The transforms VTK's camera defines, inverted in double precision.
  void SetCamera(vtkCamera* camera, double aspect)
  {
    this->WorldToView = ToGLM(camera->GetModelViewTransformMatrix());
    this->ViewToWorld = glm::inverse(this->WorldToView);
    const dmat4 projection = ToGLM(camera->GetProjectionTransformMatrix(aspect, -1.0, 1.0));
    this->ClipToWorld = glm::inverse(projection * this->WorldToView);
    this->Parallel = camera->GetParallelProjection() != 0;
    this->EyeWC = Transform(this->ViewToWorld, dvec3(0.0));
    this->ToEyeParallelWC = glm::normalize(dmat3(this->ViewToWorld) * dvec3(0.0, 0.0, 1.0));
  }

  // The lobe and its options come from the front property (a plain vtkProperty is Phong).
  void SetMaterials(vtkProperty* front, vtkProperty* back, vtkRenderer* renderer)
  {
    auto* phongFront = vtkPhongProperty::SafeDownCast(front);
    const int model = phongFront ? phongFront->GetLightingModel() : vtkPhongProperty::Phong;
    this->BlinnLobe =
      model == vtkPhongProperty::BlinnPhong || model == vtkPhongProperty::NormalizedBlinnPhong;
    this->SmoothTerminator = phongFront && phongFront->GetSmoothTerminator();
    this->SoftSpotEdge = phongFront && phongFront->GetSoftSpotEdge();
    this->SpotEdgeWidth = phongFront ? phongFront->GetSpotEdgeWidth() : 0.0;
    this->Front = MaterialOf(front, model);
    const bool twoSided = renderer->GetTwoSidedLighting() != 0;
    this->Back = (twoSided && back) ? MaterialOf(back, model) : this->Front;
    this->GlobalAmbient = FiniteNonNegativeColor(renderer->GetAmbient());
  }

  // The switched-on lights, in world coordinates; after SetCamera and SetMaterials (a light
  // without a direction takes the view direction, spots take the spot edge width).
  void SetLights(vtkRenderer* renderer, vtkCamera* camera)
  {
    const dvec3 viewDirectionWC = -this->ToEyeParallelWC;
    const bool follow = renderer->GetLightFollowCamera() != 0;
    const dmat4 cameraLightToWorld = CameraLightToWorld(camera);
    this->Lights.clear();
    vtkCollectionSimpleIterator it;
    vtkLightCollection* lights = renderer->GetLights();
    vtkLight* light;
    for (lights->InitTraversal(it); (light = lights->GetNextLight(it));)
    {
      if (!light->GetSwitch())
      {
        continue;
      }
      dvec3 position, focalPoint;
      PlaceLight(light, camera, follow, cameraLightToWorld, position, focalPoint);
      this->Lights.push_back(
        ToReferenceLight(light, position, focalPoint, viewDirectionWC, this->SpotEdgeWidth));
    }
  }

  void TracePixel(int surface, const double* parameters, bool twoSided, double x, double y,
    double* pixel, double* position, double* normal) const;

  // A G-buffer pixel: its view-coordinate position and shading normal, alpha telling the
  // front face (1), the back face (0.5) and the background (0).
  void ShadeGBufferPixel(const double position[4], const double normal[4],
    const dmat3& normalViewToWorld, double* pixel) const
  {
    if (!(position[3] > 0.0))
    {
      std::fill(pixel, pixel + 4, 0.0);
      return;
    }
    const bool backFace = position[3] < 0.75; // 1 on front faces, 0.5 on back faces
    const dvec3 P = Transform(this->ViewToWorld, ToDVec3(position));
    const dvec3 N = glm::normalize(normalViewToWorld * ToDVec3(normal));
    SetRGBA(pixel, this->Shade(P, N, backFace));
  }
};

vtkStandardNewMacro(vtkPhongReference);
vtkCxxSetObjectMacro(vtkPhongReference, Renderer, vtkRenderer);
vtkCxxSetObjectMacro(vtkPhongReference, Actor, vtkActor);

//------------------------------------------------------------------------------
vtkPhongReference::vtkPhongReference()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkPhongReference::~vtkPhongReference()
{
  this->SetRenderer(nullptr);
  this->SetActor(nullptr);
}

//------------------------------------------------------------------------------
void vtkPhongReference::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Renderer: " << this->Renderer << "\n";
  os << indent << "Actor: " << this->Actor << "\n";
  static const char* const names[] = { "NoSurface", "Sphere", "Plane", "Torus" };
  os << indent << "Surface: " << names[this->Surface] << "\n";
  os << indent << "SurfaceParameters:";
  for (double value : this->SurfaceParameters)
  {
    os << " " << value;
  }
  os << "\n";
  os << indent << "ImageSize: " << this->ImageSize[0] << " x " << this->ImageSize[1] << "\n";
}

//------------------------------------------------------------------------------
void vtkPhongReference::SetSurfaceToSphere(double cx, double cy, double cz, double radius)
{
  const double parameters[9] = { cx, cy, cz, radius, 0, 0, 0, 0, 0 };
  std::copy(parameters, parameters + 9, this->SurfaceParameters);
  this->Surface = Sphere;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPhongReference::SetSurfaceToPlane(
  const double origin[3], const double point1[3], const double point2[3])
{
  for (int i = 0; i < 3; ++i)
  {
    this->SurfaceParameters[i] = origin[i];
    this->SurfaceParameters[3 + i] = point1[i];
    this->SurfaceParameters[6 + i] = point2[i];
  }
  this->Surface = Plane;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPhongReference::SetSurfaceToTorus(
  double cx, double cy, double cz, double ringRadius, double crossSectionRadius)
{
  const double parameters[9] = { cx, cy, cz, ringRadius, crossSectionRadius, 0, 0, 0, 0 };
  std::copy(parameters, parameters + 9, this->SurfaceParameters);
  this->Surface = Torus;
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkPhongReference::ImageSizeFor(int size[2])
{
  size[0] = this->ImageSize[0];
  size[1] = this->ImageSize[1];
  if ((size[0] <= 0 || size[1] <= 0) && this->Renderer && this->Renderer->GetRenderWindow())
  {
    int x, y;
    this->Renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &x, &y);
  }
  if (size[0] <= 0 || size[1] <= 0)
  {
    vtkErrorMacro("No image size: set ImageSize or put the renderer in a window with a size.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkPhongReference::PrepareScene(int width, int height)
{
  if (!this->Renderer || !this->Actor)
  {
    vtkErrorMacro("The reference needs a renderer and an actor (SetRenderer, SetActor).");
    return false;
  }
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  vtkProperty* front = this->Actor->GetProperty();
  Internals& scene = *this->Internal;
  scene.SetCamera(camera, static_cast<double>(width) / height);

  // The actor's matrix places the analytic surface; normals take its inverse transpose.
  scene.ModelToWorld = ToGLM(this->Actor->GetMatrix());
  scene.WorldToModel = glm::inverse(scene.ModelToWorld);
  scene.ModelNormalToWorld = glm::transpose(dmat3(scene.WorldToModel));

  scene.SetMaterials(front, this->Actor->GetBackfaceProperty(), this->Renderer);
  scene.SetLights(this->Renderer, camera);
  return true;
}

//------------------------------------------------------------------------------
void vtkPhongReference::ShadePoint(
  const double positionWC[3], const double normalWC[3], bool backFace, double rgb[3])
{
  int size[2] = { 1, 1 };
  if (!this->ImageSizeFor(size) || !this->PrepareScene(size[0], size[1]))
  {
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    return;
  }
  const dvec3 color =
    this->Internal->Shade(ToDVec3(positionWC), glm::normalize(ToDVec3(normalWC)), backFace);
  rgb[0] = color.r;
  rgb[1] = color.g;
  rgb[2] = color.b;
}

namespace
{
// Ray-surface intersections in model coordinates for the ray origin + t * direction,
// t in [0, 1] (from the near to the far clipping plane, the GPU's clip volume). Each returns
// whether the surface is hit, with the first t and the outward unit normal there.
struct Hit
{
  double T = 0.0;
  dvec3 Normal{ 0.0 };
};

bool HitSphere(const double* p, const dvec3& origin, const dvec3& direction, Hit& hit)
{
  const dvec3 center(p[0], p[1], p[2]);
  const double radius = p[3];
  const dvec3 oc = origin - center;
  const double a = glm::dot(direction, direction);
  const double b = 2.0 * glm::dot(oc, direction);
  const double c = glm::dot(oc, oc) - radius * radius;
  const double discriminant = b * b - 4.0 * a * c;
  if (!(discriminant >= 0.0) || a == 0.0)
  {
    return false;
  }
  // The two roots without cancellation.
  const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
  double t0 = q / a;
  double t1 = q != 0.0 ? c / q : t0;
  if (t0 > t1)
  {
    std::swap(t0, t1);
  }
  const double t = t0 >= 0.0 ? t0 : t1;
  if (!(t >= 0.0 && t <= 1.0))
  {
    return false;
  }
  hit.T = t;
  hit.Normal = glm::normalize(origin + t * direction - center);
  return true;
}

bool HitPlane(const double* p, const dvec3& origin, const dvec3& direction, Hit& hit)
{
  const dvec3 corner(p[0], p[1], p[2]);
  const dvec3 u = dvec3(p[3], p[4], p[5]) - corner;
  const dvec3 w = dvec3(p[6], p[7], p[8]) - corner;
  const dvec3 normal = glm::cross(u, w);
  const double denominator = glm::dot(direction, normal);
  if (denominator == 0.0)
  {
    return false;
  }
  const double t = glm::dot(corner - origin, normal) / denominator;
  if (!(t >= 0.0 && t <= 1.0))
  {
    return false;
  }
  // Parallelogram coordinates of the hit point from the 2x2 Gram system.
  const dvec3 relative = origin + t * direction - corner;
  const double uu = glm::dot(u, u), uw = glm::dot(u, w), ww = glm::dot(w, w);
  const double ru = glm::dot(relative, u), rw = glm::dot(relative, w);
  const double determinant = uu * ww - uw * uw;
  const double s = (ru * ww - rw * uw) / determinant;
  const double r = (rw * uu - ru * uw) / determinant;
  if (!(s >= 0.0 && s <= 1.0 && r >= 0.0 && r <= 1.0))
  {
    return false;
  }
  hit.T = t;
  hit.Normal = glm::normalize(normal);
  return true;
}

// Torus around the z axis through its centre: sphere tracing with the torus' exact distance
// function, which never steps through the surface, inside the bounding sphere.
bool HitTorus(const double* p, const dvec3& origin, const dvec3& direction, Hit& hit)
{
  const dvec3 center(p[0], p[1], p[2]);
  const double ring = p[3];
  const double tube = p[4];
  const double length = glm::length(direction);
  if (!(length > 0.0))
  {
    return false;
  }
  const dvec3 unit = direction / length;
  const dvec3 o = origin - center;
  auto distance = [ring, tube](const dvec3& q)
  {
    const double radial = std::sqrt(q.x * q.x + q.y * q.y) - ring;
    return std::sqrt(radial * radial + q.z * q.z) - tube;
  };
  // Bounding sphere of radius ring + tube: the interval of the ray inside it.
  const double bound = ring + tube;
  const double b = glm::dot(o, unit);
  const double c = glm::dot(o, o) - bound * bound;
  const double discriminant = b * b - c;
  if (discriminant < 0.0)
  {
    return false;
  }
  const double root = std::sqrt(discriminant);
  double s = std::max(-b - root, 0.0);
  const double sEnd = std::min(-b + root, length);
  const double tolerance = 1.0e-13 * bound;
  for (int step = 0; step < 10000 && s <= sEnd; ++step)
  {
    const dvec3 q = o + s * unit;
    const double d = distance(q);
    if (d < tolerance)
    {
      const double radial = std::sqrt(q.x * q.x + q.y * q.y);
      const dvec3 ringPoint = radial > 0.0 ? dvec3(q.x, q.y, 0.0) * (ring / radial) : dvec3(0.0);
      hit.T = s / length;
      hit.Normal = glm::normalize(q - ringPoint);
      return true;
    }
    s += d;
  }
  return false;
}

bool HitSurface(int surface, const double* p, const dvec3& origin, const dvec3& direction, Hit& hit)
{
  switch (surface)
  {
    case vtkPhongReference::Sphere:
      return HitSphere(p, origin, direction, hit);
    case vtkPhongReference::Plane:
      return HitPlane(p, origin, direction, hit);
    default:
      return HitTorus(p, origin, direction, hit);
  }
}

// Why the surface cannot be ray-cast, or nullptr when it can.
const char* SurfaceProblem(int surface, const double* p)
{
  bool valid = true;
  switch (surface)
  {
    case vtkPhongReference::Sphere:
      valid = p[3] > 0.0 && std::isfinite(p[3]);
      break;
    case vtkPhongReference::Plane:
      valid = glm::length(glm::cross(dvec3(p[3] - p[0], p[4] - p[1], p[5] - p[2]),
                dvec3(p[6] - p[0], p[7] - p[1], p[8] - p[2]))) > 0.0;
      break;
    case vtkPhongReference::Torus:
      valid = p[3] > 0.0 && p[4] > 0.0 && std::isfinite(p[3] + p[4]);
      break;
    default:
      return "No analytic surface: call SetSurfaceToSphere, ToPlane or ToTorus first.";
  }
  return valid ? nullptr : "The analytic surface is degenerate (zero or non-finite size).";
}

vtkSmartPointer<vtkDoubleArray> NewImageArray(const char* name, int components, vtkIdType count)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(count);
  return array;
}

// Whether the images can be a G-buffer: 2D, of equal size, with 4-component scalars.
bool IsGBuffer(vtkImageData* positionVC, vtkImageData* normalVC)
{
  int dims[3], normalDims[3];
  positionVC->GetDimensions(dims);
  normalVC->GetDimensions(normalDims);
  vtkDataArray* positions = positionVC->GetPointData()->GetScalars();
  vtkDataArray* normals = normalVC->GetPointData()->GetScalars();
  return !(!positions || !normals || positions->GetNumberOfComponents() != 4 ||
    normals->GetNumberOfComponents() != 4 || dims[0] != normalDims[0] || dims[1] != normalDims[1] ||
    dims[2] != 1 || normalDims[2] != 1);
}
}

// The ray through the pixel centre (x, y in normalized device coordinates), from the near to
// the far clipping plane: the pixel's colour, the hit point and the outward unit normal, all
// zero where nothing is hit.
void vtkPhongReference::Internals::TracePixel(int surface, const double* parameters, bool twoSided,
  double x, double y, double* pixel, double* position, double* normal) const
{
  std::fill(pixel, pixel + 4, 0.0);
  std::fill(position, position + 3, 0.0);
  std::fill(normal, normal + 3, 0.0);
  const dvec3 nearWC = Transform(this->ClipToWorld, dvec3(x, y, -1.0));
  const dvec3 farWC = Transform(this->ClipToWorld, dvec3(x, y, 1.0));
  const dvec3 originMC = Transform(this->WorldToModel, nearWC);
  const dvec3 directionMC = dmat3(this->WorldToModel) * (farWC - nearWC);
  Hit hit;
  if (!HitSurface(surface, parameters, originMC, directionMC, hit))
  {
    return;
  }
  const dvec3 P = nearWC + hit.T * (farWC - nearWC);
  dvec3 N = glm::normalize(this->ModelNormalToWorld * hit.Normal);
  const dvec3 V = this->Parallel ? this->ToEyeParallelWC : glm::normalize(this->EyeWC - P);
  // A surface seen from behind is a back face; with two-sided lighting its normal turns to
  // the viewer.
  const bool backFace = glm::dot(N, V) < 0.0;
  const dvec3 shadingNormal = (backFace && twoSided) ? -N : N;
  SetRGBA(pixel, this->Shade(P, shadingNormal, backFace));
  for (int i = 0; i < 3; ++i)
  {
    position[i] = P[i];
    normal[i] = N[i];
  }
}

//------------------------------------------------------------------------------
int vtkPhongReference::RenderAnalytic(vtkImageData* output)
{
  if (!output)
  {
    vtkErrorMacro("No output image.");
    return 0;
  }
  int size[2];
  if (!this->ImageSizeFor(size) || !this->PrepareScene(size[0], size[1]))
  {
    return 0;
  }
  if (const char* problem = SurfaceProblem(this->Surface, this->SurfaceParameters))
  {
    vtkErrorMacro(<< problem);
    return 0;
  }

  const int width = size[0];
  const int height = size[1];
  const vtkIdType count = static_cast<vtkIdType>(width) * height;
  vtkSmartPointer<vtkDoubleArray> rgba = NewImageArray("RGBA", 4, count);
  vtkSmartPointer<vtkDoubleArray> positions = NewImageArray("PositionWC", 3, count);
  vtkSmartPointer<vtkDoubleArray> normals = NewImageArray("NormalWC", 3, count);

  const Internals& scene = *this->Internal;
  const bool twoSided = this->Renderer->GetTwoSidedLighting() != 0;
  vtkSMPTools::For(0, height,
    [&](int rowBegin, int rowEnd)
    {
      for (int row = rowBegin; row < rowEnd; ++row)
      {
        for (int column = 0; column < width; ++column)
        {
          const vtkIdType index = static_cast<vtkIdType>(row) * width + column;
          const double x = 2.0 * (column + 0.5) / width - 1.0;
          const double y = 2.0 * (row + 0.5) / height - 1.0;
          scene.TracePixel(this->Surface, this->SurfaceParameters, twoSided, x, y,
            rgba->GetPointer(4 * index), positions->GetPointer(3 * index),
            normals->GetPointer(3 * index));
        }
      }
    });

  output->Initialize();
  output->SetDimensions(width, height, 1);
  output->GetPointData()->SetScalars(rgba);
  output->GetPointData()->AddArray(positions);
  output->GetPointData()->AddArray(normals);
  return 1;
}

//------------------------------------------------------------------------------
int vtkPhongReference::ShadeGBuffer(
  vtkImageData* positionVC, vtkImageData* normalVC, vtkImageData* output)
{
  if (!positionVC || !normalVC || !output)
  {
    vtkErrorMacro("ShadeGBuffer needs a position image, a normal image and an output image.");
    return 0;
  }
  if (!IsGBuffer(positionVC, normalVC))
  {
    vtkErrorMacro("The G-buffer images must be 2D, of equal size, with 4-component scalars "
                  "(vtkPhongFloatRenderPass images of the PositionVC and NormalVC views).");
    return 0;
  }
  int dims[3];
  positionVC->GetDimensions(dims);
  const int width = dims[0];
  const int height = dims[1];
  if (!this->PrepareScene(width, height))
  {
    return 0;
  }
  vtkDataArray* positions = positionVC->GetPointData()->GetScalars();
  vtkDataArray* normals = normalVC->GetPointData()->GetScalars();
  const vtkIdType count = static_cast<vtkIdType>(width) * height;
  vtkSmartPointer<vtkDoubleArray> rgba = NewImageArray("RGBA", 4, count);
  const Internals& scene = *this->Internal;
  // Normals transform with the inverse transpose of the point transform; for view to world
  // that is the transpose of the world-to-view matrix's linear part.
  const dmat3 normalViewToWorld = glm::transpose(dmat3(scene.WorldToView));
  vtkSMPTools::For(0, count,
    [&](vtkIdType begin, vtkIdType end)
    {
      double position[4], normal[4];
      for (vtkIdType index = begin; index < end; ++index)
      {
        positions->GetTuple(index, position);
        normals->GetTuple(index, normal);
        scene.ShadeGBufferPixel(position, normal, normalViewToWorld, rgba->GetPointer(4 * index));
      }
    });
  output->Initialize();
  output->SetDimensions(width, height, 1);
  output->GetPointData()->SetScalars(rgba);
  return 1;
}
