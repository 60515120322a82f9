#include "vtkPhongDepthPrePass.h"

#include "vtkPhongShaderPlanner.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"

namespace
{
// Measured on llvmpipe at 1280x1024 (vtkPhongBenchmark --only shells): under 8 lights the
// pre-pass took a folded shell to 0.6-0.7x and eight nested shells drawn inside out to
// 0.57x, and cost 1.07x when they were drawn front to back; under 1 light it cost 1.1-1.3x
// everywhere. The lighting of a fragment grows with the lights it evaluates, the pre-pass's
// cost does not: from this many lights on, it is used.
constexpr int MinimumLights = 4;
}

//------------------------------------------------------------------------------
bool vtkPhongDepthPrePassPays(vtkRenderer* ren, vtkPolyData* input, int culledLights)
{
  if (!input || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    return false;
  }
  const int lights =
    static_cast<int>(vtkPhongShaderPlanner::SwitchedOnLights(ren).size()) - culledLights;
  return lights >= MinimumLights;
}
