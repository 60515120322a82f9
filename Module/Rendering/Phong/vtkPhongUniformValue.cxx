#include "vtkPhongUniformValue.h"

#include "vtkShaderProgram.h"

//------------------------------------------------------------------------------
void vtkPhongUniformValue::Upload(
  vtkShaderProgram* program, const std::vector<vtkPhongUniformValue>& values)
{
  for (const vtkPhongUniformValue& value : values)
  {
    // VTK's IsUniformUsed does not know arrays: they go up whether or not the program reads
    // them (SetUniform*fv skips an absent one).
    const int count = static_cast<int>(value.Count());
    if (count == 0 || (!value.IsArray && !program->IsUniformUsed(value.Name.c_str())))
    {
      continue;
    }
    const char* name = value.Name.c_str();
    const float* data = value.Values.data();
    if (value.Components == 3)
    {
      program->SetUniform3fv(name, count, reinterpret_cast<const float(*)[3]>(data));
    }
    else
    {
      program->SetUniform1fv(name, count, data);
    }
  }
}
