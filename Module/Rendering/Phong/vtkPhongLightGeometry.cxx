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
vtkPhongLightGeometry vtkPhongLightGeometry::InView(vtkLight* light, vtkRenderer* ren)
{
  vtkMatrix4x4* worldToView = ren->GetActiveCamera()->GetModelViewTransformMatrix();
  double position[4] = { 0.0, 0.0, 0.0, 1.0 };
  double focalPoint[4] = { 0.0, 0.0, 0.0, 1.0 };
  light->GetTransformedPosition(position);
  light->GetTransformedFocalPoint(focalPoint);
  double positionVC[4];
  worldToView->MultiplyPoint(position, positionVC);
  double direction[3];
  vtkMath::Subtract(focalPoint, position, direction);
  double directionVC[3];
  for (int row = 0; row < 3; ++row)
  {
    directionVC[row] = worldToView->GetElement(row, 0) * direction[0] +
      worldToView->GetElement(row, 1) * direction[1] +
      worldToView->GetElement(row, 2) * direction[2];
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
