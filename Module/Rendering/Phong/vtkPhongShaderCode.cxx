#include "vtkPhongShaderCode.h"

#include "vtkActor.h"
#include "vtkShaderProperty.h"

//------------------------------------------------------------------------------
bool vtkPhongShaderCode::HasUserCode(vtkActor* act, vtkShaderProperty* legacyShaders)
{
  vtkShaderProperty* shaders = act->GetShaderProperty();
  const bool actorCode = shaders &&
    (shaders->GetNumberOfShaderReplacements() > 0 || shaders->HasVertexShaderCode() ||
      shaders->HasFragmentShaderCode() || shaders->HasGeometryShaderCode());
  return actorCode || (legacyShaders && legacyShaders->GetNumberOfShaderReplacements() > 0);
}
