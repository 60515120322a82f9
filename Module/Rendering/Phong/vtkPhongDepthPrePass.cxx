#include "vtkPhongDepthPrePass.h"

#include "vtk_glew.h"

#include <cmath>
#include <initializer_list>

namespace
{
// The cost model, in nanoseconds of frame time, measured on llvmpipe at 1280x1024 (2 cores)
// with nested contour shells and a sphere under 1 and 8 lights, the pre-pass on and off
// (docs/results/performance.md, "Depth complexity"). Without the pre-pass a draw lights every
// fragment it shades; with it, it pays a depth pass over the whole geometry and lights only
// the fragments left visible:
//   saving = (shaded - visible) * (HiddenFragment + lights * HiddenFragmentPerLight)
//   cost   = shaded * DepthFragment + triangles * DepthTriangle + PerFrame
// The depth pass costs mostly per triangle (llvmpipe's vertex processing and triangle setup
// run on one thread); PerFrame is the CPU side of switching programs twice per draw.
constexpr double HiddenFragment = 27.0;
constexpr double HiddenFragmentPerLight = 9.3;
constexpr double DepthFragment = 9.0;
constexpr double DepthTriangle = 250.0;
constexpr double PerFrame = 400000.0;

// A count of shaded fragments that moved by more than this share since the last probe means
// the view or the data changed enough to look again.
constexpr double ReprobeChange = 0.25;
}

//------------------------------------------------------------------------------
vtkPhongDepthPrePass::~vtkPhongDepthPrePass() = default; // queries die with their context

//------------------------------------------------------------------------------
bool vtkPhongDepthPrePass::Pays(
  double shaded, double visible, double triangles, int evaluatedLights)
{
  const int lights = evaluatedLights > 0 ? evaluatedLights : 0;
  const double saving = (shaded - visible) * (HiddenFragment + lights * HiddenFragmentPerLight);
  const double cost = shaded * DepthFragment + triangles * DepthTriangle + PerFrame;
  return saving > cost;
}

//------------------------------------------------------------------------------
bool vtkPhongDepthPrePass::Decide(int evaluatedLights, double triangles, vtkWindow* window)
{
  if (window != this->Window)
  {
    // A new context: the old queries are gone with the old one (ReleaseGraphicsResources).
    this->Reset();
    this->Window = window;
  }
  this->CollectCounts();
  if (this->Started[Shaded] || this->Started[Visible])
  {
    return this->LastWithPrePass; // the last counts are not in yet: keep going as before
  }
  bool usePrePass = false;
  if (this->ShadedCount <= 0.0 && !this->Probed)
  {
    usePrePass = false; // the first frame: a plain draw, counting what it shades
  }
  else if (!this->Probed)
  {
    usePrePass = true;
  }
  else if (this->LastWithPrePass)
  {
    usePrePass = Pays(this->ShadedCount, this->VisibleCount, triangles, evaluatedLights);
  }
  else
  {
    const double change = std::abs(this->ShadedCount - this->ShadedAtProbe);
    usePrePass =
      ++this->FramesSinceProbe >= ReprobeInterval || change > ReprobeChange * this->ShadedAtProbe;
  }
  this->LastWithPrePass = usePrePass;
  return usePrePass;
}

//------------------------------------------------------------------------------
void vtkPhongDepthPrePass::BeginCount(Count count)
{
  this->Running = -1;
  if (this->Started[count])
  {
    return; // its last count is still to be read
  }
  GLint active = 0;
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &active);
  if (active != 0)
  {
    return; // someone else is counting (VTK's depth peeling)
  }
  if (this->Queries[count] == 0)
  {
    glGenQueries(2, this->Queries);
  }
  glBeginQuery(GL_SAMPLES_PASSED, this->Queries[count]);
  this->Running = count;
}

//------------------------------------------------------------------------------
void vtkPhongDepthPrePass::EndCount()
{
  if (this->Running < 0)
  {
    return;
  }
  glEndQuery(GL_SAMPLES_PASSED);
  this->Started[this->Running] = true;
  this->Running = -1;
}

//------------------------------------------------------------------------------
// Read the counts of the last frame when the GPU has them: a frame with the pre-pass gives
// both counts (a probe), a plain one the shaded count only.
void vtkPhongDepthPrePass::CollectCounts()
{
  GLuint counts[2] = { 0, 0 };
  for (int count : { Shaded, Visible })
  {
    if (!this->Started[count])
    {
      continue;
    }
    GLuint available = 0;
    glGetQueryObjectuiv(this->Queries[count], GL_QUERY_RESULT_AVAILABLE, &available);
    if (!available)
    {
      return;
    }
    glGetQueryObjectuiv(this->Queries[count], GL_QUERY_RESULT, &counts[count]);
  }
  if (this->Started[Shaded])
  {
    this->ShadedCount = counts[Shaded];
  }
  if (this->Started[Shaded] && this->Started[Visible])
  {
    this->VisibleCount = counts[Visible];
    this->ShadedAtProbe = this->ShadedCount;
    this->FramesSinceProbe = 0;
    this->Probed = true;
  }
  this->Started[Shaded] = this->Started[Visible] = false;
}

//------------------------------------------------------------------------------
double vtkPhongDepthPrePass::GetDepthComplexity() const
{
  return (this->Probed && this->VisibleCount > 0.0) ? this->ShadedAtProbe / this->VisibleCount
                                                    : 0.0;
}

//------------------------------------------------------------------------------
void vtkPhongDepthPrePass::ReleaseGraphicsResources(vtkWindow* window)
{
  if (window && window == this->Window && this->Queries[0] != 0)
  {
    glDeleteQueries(2, this->Queries);
  }
  this->Reset();
}

//------------------------------------------------------------------------------
void vtkPhongDepthPrePass::Reset()
{
  this->Queries[0] = this->Queries[1] = 0;
  this->Window = nullptr;
  this->Started[0] = this->Started[1] = false;
  this->Running = -1;
  this->LastWithPrePass = false;
  this->Probed = false;
  this->ShadedCount = this->VisibleCount = this->ShadedAtProbe = 0.0;
  this->FramesSinceProbe = 0;
}
