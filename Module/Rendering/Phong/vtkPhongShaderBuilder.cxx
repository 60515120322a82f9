#include "vtkPhongShaderBuilder.h"

#include "vtkObjectFactory.h"
#include "vtkPhongLightUniforms.h"
#include "vtkPhongMaterialUniforms.h"
#include "vtkPhongProblemLog.h"
#include "vtkPhongShaderPlanner.h"
#include "vtkPhongShaderTemplate.h"
#include "vtkPhongShadowMaps.h"

vtkStandardNewMacro(vtkPhongShaderBuilder);

//------------------------------------------------------------------------------
vtkPhongShaderBuilder::vtkPhongShaderBuilder()
  : Log(new vtkPhongProblemLog)
{
  this->PlaceholderDirectional->SetIntensity(0.0);
  this->PlaceholderPoint->SetIntensity(0.0);
  this->PlaceholderPoint->PositionalOn();
  this->PlaceholderPoint->SetConeAngle(180.0);
  this->PlaceholderSpot->SetIntensity(0.0);
  this->PlaceholderSpot->PositionalOn();
  this->PlaceholderSpot->SetConeAngle(45.0);
  this->PlaceholderSpot->SetExponent(2.0);
  this->PlaceholderSpot->SetAttenuationValues(1.0, 0.1, 0.1);
  this->PlaceholderPoint->SetAttenuationValues(1.0, 0.1, 0.1);
  this->PlaceholderPoint->SetAmbientColor(1.0, 1.0, 1.0);
}

//------------------------------------------------------------------------------
vtkPhongShaderBuilder::~vtkPhongShaderBuilder() = default;

//------------------------------------------------------------------------------
std::string vtkPhongShaderBuilder::TakeProblems()
{
  return this->Log->Take();
}

//------------------------------------------------------------------------------
vtkPhongShaderBuilder::Plan vtkPhongShaderBuilder::MakePlan(
  vtkRenderer* ren, vtkActor* actor, const PrimitiveState& state, const Options& options)
{
  vtkPhongShaderPlanner::PlaceholderLights placeholders;
  placeholders.Directional = this->PlaceholderDirectional;
  placeholders.Point = this->PlaceholderPoint;
  placeholders.Spot = this->PlaceholderSpot;
  return vtkPhongShaderPlanner(placeholders, *this->Log).MakePlan(ren, actor, state, options);
}

//------------------------------------------------------------------------------
std::string vtkPhongShaderBuilder::ResolveTemplate(
  const char* templateText, const char* section, const Plan& plan)
{
  return vtkPhongShaderTemplate(this).Resolve(templateText, section, plan);
}

//------------------------------------------------------------------------------
const char* vtkPhongShaderBuilder::GetTemplate(const char* name)
{
  return vtkPhongShaderTemplate::Get(name);
}

//------------------------------------------------------------------------------
void vtkPhongShaderBuilder::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, const Plan& plan)
{
  vtkPhongShaderTemplate(this).Substitute(shaders, plan);
}

//------------------------------------------------------------------------------
void vtkPhongShaderBuilder::SetLightUniforms(
  vtkShaderProgram* program, vtkRenderer* ren, const Plan& plan)
{
  vtkPhongLightUniforms(program, ren, plan, *this->Log).Upload();
  vtkPhongShadowMaps::UploadLightIndices(program, ren, plan);
}

//------------------------------------------------------------------------------
void vtkPhongShaderBuilder::SetMaterialUniforms(vtkShaderProgram* program, const Plan& plan)
{
  vtkPhongMaterialUniforms(program, plan, *this->Log).Upload();
}

//------------------------------------------------------------------------------
void vtkPhongShaderBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Pending problems: " << this->Log->GetNumberOfProblems() << "\n";
  os << indent << "PlaceholderDirectional: " << this->PlaceholderDirectional << "\n";
  os << indent << "PlaceholderPoint: " << this->PlaceholderPoint << "\n";
  os << indent << "PlaceholderSpot: " << this->PlaceholderSpot << "\n";
}
