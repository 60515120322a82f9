#include "vtkPhongShadowMaps.h"

#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

#include <map>
#include <vector>

//------------------------------------------------------------------------------
int vtkPhongShadowMaps::CountFactors(const std::string& fragmentSource)
{
  int count = 0;
  while (fragmentSource.find("vec2 factor" + std::to_string(count) + " = ") != std::string::npos)
  {
    ++count;
  }
  return count;
}

//------------------------------------------------------------------------------
std::string vtkPhongShadowMaps::CopyFactors(int count)
{
  std::string lines = "  // vtkShadowMapPass's factor of each light of the renderer\n";
  for (int i = 0; i < count; ++i)
  {
    const std::string index = std::to_string(i);
    lines += "  phongShadowFactors[" + index + "] = factor" + index + ".r;\n";
  }
  return lines;
}

//------------------------------------------------------------------------------
void vtkPhongShadowMaps::UploadLightIndices(
  vtkShaderProgram* program, vtkRenderer* ren, const vtkPhongShaderPlan& plan)
{
  // The plan the core keeps does not have SHADOW_MAPS (the shader source decides it): ask
  // the program.
  if (!program)
  {
    return;
  }
  // The pass numbers the factors as the renderer lists its lights, switched off ones too.
  std::map<vtkLight*, int> rendererIndex;
  vtkLightCollection* lights = ren->GetLights();
  vtkCollectionSimpleIterator it;
  vtkLight* light;
  int index = 0;
  for (lights->InitTraversal(it); (light = lights->GetNextLight(it)); ++index)
  {
    rendererIndex[light] = index;
  }
  auto upload = [&](const std::vector<vtkLight*>& kind, const char* name)
  {
    if (kind.empty() || !program->IsUniformUsed(name))
    {
      return;
    }
    std::vector<int> indices;
    for (vtkLight* each : kind)
    {
      auto found = rendererIndex.find(each);
      indices.push_back(found == rendererIndex.end() ? 0 : found->second);
    }
    program->SetUniform1iv(name, static_cast<int>(indices.size()), indices.data());
  };
  upload(plan.DirectionalLights, "phongDirectionalLightShadow");
  upload(plan.PointLights, "phongPointLightShadow");
  upload(plan.SpotLights, "phongSpotLightShadow");
}
