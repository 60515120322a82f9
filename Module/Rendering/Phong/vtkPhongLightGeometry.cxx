#include "vtkPhongLightGeometry.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPhongProblemLog.h"
#include "vtkTransform.h"

#include <algorithm>
#include <cmath>

namespace
{
vtkTransform* UserLightTransform(vtkRenderer* ren)
{
  vtkOpenGLRenderer* oglRenderer = vtkOpenGLRenderer::SafeDownCast(ren);
  return oglRenderer ? oglRenderer->GetUserLightTransform() : nullptr;
}
}

//------------------------------------------------------------------------------
double vtkPhongLightGeometry::UploadedColor(double color, double intensity)
{
  auto sanitized = [](double value)
  { return (value >= 0.0 && std::isfinite(value)) ? value : 0.0; };
  return std::min(sanitized(color) * sanitized(intensity), vtkPhongProblemLog::LargestValue);
}

//------------------------------------------------------------------------------
bool vtkPhongLightGeometry::IsUserTransformed(vtkLight* light, vtkRenderer* ren)
{
  return !light->LightTypeIsSceneLight() && UserLightTransform(ren) != nullptr;
}

//------------------------------------------------------------------------------
// A headlight or camera light follows the camera: VTK places it in world coordinates every
// frame, from the camera. Its view coordinates follow from its own definition, and stay the
// same bits however the camera turns (through world coordinates they would move in the last
// bits): a headlight at the eye looking along -z; a camera light's frame has the eye at (0, 0,
// 1) looking at the origin, scaled by the camera's distance (vtkCamera's light transform).
// Only without a camera model transform or a user light transform, where that is all.
bool vtkPhongLightGeometry::InCameraFrame(
  vtkLight* light, vtkRenderer* ren, double positionVC[4], double directionVC[3])
{
  vtkCamera* camera = ren->GetActiveCamera();
  if (light->LightTypeIsSceneLight() || IsUserTransformed(light, ren) ||
    !camera->GetModelTransformMatrix()->IsIdentity())
  {
    return false;
  }
  positionVC[3] = 1.0;
  if (light->LightTypeIsHeadlight())
  {
    positionVC[0] = positionVC[1] = positionVC[2] = 0.0;
    directionVC[0] = directionVC[1] = 0.0;
    directionVC[2] = -1.0;
    return true;
  }
  const double* position = light->GetPosition();
  const double* focalPoint = light->GetFocalPoint();
  const double distance = camera->GetDistance();
  for (int i = 0; i < 3; ++i)
  {
    positionVC[i] = distance * (position[i] - (i == 2 ? 1.0 : 0.0));
    directionVC[i] = focalPoint[i] - position[i];
  }
  return true;
}

//------------------------------------------------------------------------------
vtkPhongLightGeometry vtkPhongLightGeometry::InView(vtkLight* light, vtkRenderer* ren)
{
  double positionVC[4];
  double directionVC[3];
  if (!InCameraFrame(light, ren, positionVC, directionVC))
  {
    InWorld(light, ren, positionVC, directionVC);
  }
  if (IsUserTransformed(light, ren))
  {
    vtkTransform* user = UserLightTransform(ren);
    user->TransformPoint(positionVC, positionVC);
    user->TransformVector(directionVC, directionVC);
  }
  vtkPhongLightGeometry geometry;
  for (int i = 0; i < 3; ++i)
  {
    geometry.PositionVC[i] = positionVC[i] / (positionVC[3] != 0.0 ? positionVC[3] : 1.0);
  }
  const double length = vtkMath::Norm(directionVC);
  geometry.HasDirection = length > 0.0 && std::isfinite(length);
  if (geometry.HasDirection)
  {
    for (int i = 0; i < 3; ++i)
    {
      geometry.DirectionVC[i] = directionVC[i] / length;
    }
  }
  return geometry;
}

//------------------------------------------------------------------------------
// Any light, from its position and focal point in world coordinates.
void vtkPhongLightGeometry::InWorld(
  vtkLight* light, vtkRenderer* ren, double positionVC[4], double directionVC[3])
{
  vtkMatrix4x4* worldToView = ren->GetActiveCamera()->GetModelViewTransformMatrix();
  double position[4] = { 0.0, 0.0, 0.0, 1.0 };
  double focalPoint[4] = { 0.0, 0.0, 0.0, 1.0 };
  light->GetTransformedPosition(position);
  light->GetTransformedFocalPoint(focalPoint);
  worldToView->MultiplyPoint(position, positionVC);
  double direction[3];
  vtkMath::Subtract(focalPoint, position, direction);
  for (int row = 0; row < 3; ++row)
  {
    directionVC[row] = worldToView->GetElement(row, 0) * direction[0] +
      worldToView->GetElement(row, 1) * direction[1] +
      worldToView->GetElement(row, 2) * direction[2];
  }
}

//------------------------------------------------------------------------------
std::vector<vtkLight*> vtkPhongLightGeometry::SwitchedOn(vtkRenderer* ren)
{
  std::vector<vtkLight*> switchedOn;
  vtkLightCollection* lights = ren->GetLights();
  vtkCollectionSimpleIterator it;
  vtkLight* light;
  for (lights->InitTraversal(it); (light = lights->GetNextLight(it));)
  {
    if (light->GetSwitch())
    {
      switchedOn.push_back(light);
    }
  }
  return switchedOn;
}
