#include "vtkPhongDepthPrePass.h"

#include "vtkPhongShaderPlanner.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"

namespace
{
// Measured on llvmpipe at 1280x1024 (vtkPhongBenchmark --only shells): under 8 lights the
// pre-pass took a folded shell to 0.6-0.7x and eight nested shells drawn inside out to
// 0.57x, and cost 1.07x when they were drawn front to back; under 1 light it cost 1.1-1.3x
// everywhere. On one sphere (no hidden layer to save) it cost 1.3-1.9x under 8 and 32 lights:
// llvmpipe runs the whole lighting shader in the colour-masked pass too, so the pre-pass is
// not the mapper's default (DepthPrePassAutomatic is asked for by users with deep scenes).
// The lighting of a fragment grows with the lights it evaluates: from this many lights on,
// Automatic uses it.
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
