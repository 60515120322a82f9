/**
 * @class   vtkPhongLightGeometry
 * @brief   where a renderer's lights are, in view coordinates, as the shader sees them (private)
 *
 * One answer for every part that places lights: the planner and the uniforms (which lights
 * are switched on, in which order), light culling and the light uniforms (a light's
 * view-coordinate position and direction, with VTK's user light transform applied as VTK
 * applies it, to all but scene lights).
 */

#ifndef vtkPhongLightGeometry_h
#define vtkPhongLightGeometry_h

#include <vector> // for std::vector

class vtkLight;
class vtkRenderer;

class vtkPhongLightGeometry
{
public:
  /**
   * The light's position and unit direction (from the light towards its focal point) in the
   * view coordinates of `ren`'s active camera. HasDirection is false when the focal point is
   * at the position (or not finite): DirectionVC is then the view direction (0, 0, -1).
   * Headlights and camera lights are placed from their own coordinates, the same bits for
   * every turn of the camera (vtkPhongMapperCore's light constants rely on it).
   */
  static vtkPhongLightGeometry InView(vtkLight* light, vtkRenderer* ren);

  /**
   * Whether VTK moves the light by its user light transform (VR) in view coordinates.
   */
  static bool IsUserTransformed(vtkLight* light, vtkRenderer* ren);

  /**
   * A component of a light colour times the light's intensity as vtkPhongLightUniforms
   * uploads it, before the float cast: each factor finite and >= 0 (else 0), the product at
   * most vtkPhongProblemLog::LargestValue. For the parts that compare or bound light values
   * without reporting them (the uniforms report what they substitute).
   */
  static double UploadedColor(double color, double intensity);

  /**
   * The renderer's lights that are switched on, in the renderer's order (the order of the
   * light indices in messages and of DebugLightIndex).
   */
  static std::vector<vtkLight*> SwitchedOn(vtkRenderer* ren);

  double PositionVC[3] = { 0.0, 0.0, 0.0 };
  double DirectionVC[3] = { 0.0, 0.0, -1.0 };
  bool HasDirection = true;

private:
  static bool InCameraFrame(
    vtkLight* light, vtkRenderer* ren, double positionVC[4], double directionVC[3]);
  static void InWorld(
    vtkLight* light, vtkRenderer* ren, double positionVC[4], double directionVC[3]);
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongLightGeometry.h
