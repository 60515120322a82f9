/**
 * @class   vtkPhongShaderCode
 * @brief   whether an actor (or, before VTK 9.2, its mapper) carries shader code of the user's
 *
 * Shader code or replacements of the user's may move or discard fragments and may read or
 * write what vtkPhong's lighting replaces: the planner keeps the interpolated dot products
 * out of such shaders, and the visibility work (closed-surface culling) stays off.
 */

#ifndef vtkPhongShaderCode_h
#define vtkPhongShaderCode_h

class vtkActor;
class vtkShaderProperty;

class vtkPhongShaderCode
{
public:
  /**
   * Whether the actor's shader property, or `legacyShaders` (the mapper's own replacements
   * before VTK 9.2; nullptr otherwise), holds shader code or replacements of the user's.
   */
  static bool HasUserCode(vtkActor* act, vtkShaderProperty* legacyShaders);
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongShaderCode.h
