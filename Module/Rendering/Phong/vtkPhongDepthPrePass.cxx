#include "vtkPhongDepthPrePass.h"

#include "vtkActor.h"
#include "vtkInformation.h"
#include "vtkMapper.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPhongLightGeometry.h"
#include "vtkPhongLightingSettings.h"
#include "vtkPhongOpenGL.h"
#include "vtkPhongScopedCulling.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"

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
//   cost   = visible * DepthFragment + triangles * DepthTriangle + PerFrame
// The depth pass (back faces culled) costs mostly per triangle (llvmpipe's vertex processing
// and triangle setup run on one thread); PerFrame is the CPU side of switching programs twice per
// draw.
constexpr double HiddenFragment = 3.5;
constexpr double HiddenFragmentPerLight = 6.4;
constexpr double DepthFragment = 3.4;
constexpr double DepthTriangle = 78.0;
constexpr double PerFrame = 400000.0;

// A count of shaded fragments that moved by more than this share since the last probe means
// the view or the data changed enough to look again.
constexpr double ReprobeChange = 0.25;
}

//------------------------------------------------------------------------------
vtkPhongDepthPrePass::~vtkPhongDepthPrePass() = default; // queries die with their context

//------------------------------------------------------------------------------
bool vtkPhongDepthPrePass::Draw(int mode, vtkRenderer* ren, vtkActor* act, vtkMapper* mapper,
  double triangles, double depthTriangles, int culledLights, bool backFacesCulled,
  const std::function<void(bool depthOnly)>& draw)
{
  using Mapper = vtkPhongLightingSettings;
  const bool possible = mode != Mapper::DepthPrePassOff && CanUse(ren, act, triangles);
  const bool counting =
    possible && mode == Mapper::DepthPrePassAutomatic && CanMeasure(mapper, act);
  bool used = possible && mode == Mapper::DepthPrePassOn;
  if (counting)
  {
    const int evaluatedLights =
      static_cast<int>(vtkPhongLightGeometry::SwitchedOn(ren).size()) - culledLights;
    used = this->Decide(
      evaluatedLights, triangles, depthTriangles, backFacesCulled, ren->GetRenderWindow());
  }
  if (used)
  {
    this->DrawWithPrePass(ren, counting, draw);
    return true;
  }
  if (counting)
  {
    this->BeginCount(Shaded);
    this->CullingOfStartedShaded = backFacesCulled;
  }
  draw(false);
  if (counting)
  {
    this->EndCount();
  }
  return false;
}

//------------------------------------------------------------------------------
// The depth pass draws every primitive with a program that computes no light and writes no
// colour; the lit draw, with the same vertex shader (so the same depths) and VTK's GL_LEQUAL
// test, then shades only the nearest surface of each pixel.
void vtkPhongDepthPrePass::DrawWithPrePass(
  vtkRenderer* ren, bool counting, const std::function<void(bool depthOnly)>& draw)
{
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
  {
    vtkOpenGLState::ScopedglColorMask colorMask(state);
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    // Back faces may be left out of the depth pass: the lit draw writes depth with GL_LEQUAL,
    // so a back face nearer than every front face still wins there, and any subset of the
    // surfaces gives the same picture. The depth pass then sets up half the triangles of a
    // closed surface. Culling already on (the actor's own, or the mapper's of a closed
    // surface's hidden faces) applies to both draws.
    const bool alreadyCulling = state->GetEnumState(GL_CULL_FACE);
    vtkPhongScopedCulling culling(ren, alreadyCulling ? 0 : GL_BACK);
    draw(true);
  }
  vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
  state->vtkglDepthFunc(GL_LEQUAL);
  if (counting)
  {
    this->BeginCount(Visible);
  }
  draw(false);
  if (counting)
  {
    this->EndCount();
  }
}

//------------------------------------------------------------------------------
bool vtkPhongDepthPrePass::CanUse(vtkRenderer* ren, vtkActor* act, double triangles)
{
  vtkProperty* property = act->GetProperty();
  return triangles > 0.0 && !act->IsRenderingTranslucentPolygonalGeometry() &&
    !ren->GetSelector() && property->GetLighting() && property->GetOpacity() >= 1.0 &&
    !property->GetEdgeVisibility() && !property->GetVertexVisibility() && ren->GetRenderWindow();
}

//------------------------------------------------------------------------------
bool vtkPhongDepthPrePass::CanMeasure(vtkMapper* mapper, vtkActor* act)
{
  vtkProperty* property = act->GetProperty();
  vtkInformation* keys = act->GetPropertyKeys();
  if (property->GetRepresentation() != VTK_SURFACE || property->GetRenderPointsAsSpheres() ||
    property->GetRenderLinesAsTubes() || (keys && keys->Has(vtkOpenGLRenderPass::RenderPasses())))
  {
    return false;
  }
  switch (vtkMapper::GetResolveCoincidentTopology())
  {
    case VTK_RESOLVE_SHIFT_ZBUFFER:
      return vtkMapper::GetResolveCoincidentTopologyZShift() == 0.0;
    case VTK_RESOLVE_POLYGON_OFFSET:
    {
      double factor = 0.0, units = 0.0;
      mapper->GetCoincidentTopologyPolygonOffsetParameters(factor, units);
      return factor == 0.0 && units == 0.0;
    }
    default:
      return true;
  }
}

//------------------------------------------------------------------------------
bool vtkPhongDepthPrePass::Pays(
  double shaded, double visible, double triangles, int evaluatedLights)
{
  const int lights = evaluatedLights > 0 ? evaluatedLights : 0;
  const double saving = (shaded - visible) * (HiddenFragment + lights * HiddenFragmentPerLight);
  const double cost = visible * DepthFragment + triangles * DepthTriangle + PerFrame;
  return saving > cost;
}

//------------------------------------------------------------------------------
// A probe of the pre-pass is not free (its depth pass of every triangle: on llvmpipe about
// 470 MB above the data at 8M triangles, besides its time): only where the pre-pass could
// pay even if no fragment stayed visible.
bool vtkPhongDepthPrePass::CouldPay(double depthTriangles, int evaluatedLights) const
{
  return Pays(this->ShadedCount, 0.0, depthTriangles, evaluatedLights);
}

//------------------------------------------------------------------------------
bool vtkPhongDepthPrePass::Decide(int evaluatedLights, double triangles, double depthTriangles,
  bool backFacesCulled, vtkWindow* window)
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
  if (this->ShadedCount > 0.0 && this->ShadedCulled != backFacesCulled)
  {
    // The culling started or stopped since the plain count: count a plain draw again, then
    // decide (the count with the pre-pass still holds: its lit draw shades what shows).
    this->ShadedCount = 0.0;
    this->Decided = false;
  }
  bool usePrePass = false;
  if (this->ShadedCount <= 0.0)
  {
    usePrePass = false; // measure a plain draw first
  }
  else if (this->VisibleCount <= 0.0)
  {
    usePrePass = this->CouldPay(depthTriangles, evaluatedLights); // then probe the pre-pass
  }
  else if (!this->Decided || this->Refreshing || evaluatedLights != this->LightsAtDecision ||
    triangles != this->TrianglesAtDecision ||
    std::abs(depthTriangles - this->DepthTrianglesAtDecision) >
      ReprobeChange * this->DepthTrianglesAtDecision)
  {
    // A new decision: the first, after a refresh, or the work per fragment changed (the
    // counts still hold: they depend on the view and the geometry, not on the lights), or
    // the depth pass's triangles did: the first decision, a frame after the probe, still
    // counts every triangle, before the occlusion counts of the clusters are in.
    this->DecidedPrePass =
      Pays(this->ShadedCount, this->VisibleCount, depthTriangles, evaluatedLights);
    this->Decided = true;
    this->Refreshing = false;
    this->LightsAtDecision = evaluatedLights;
    this->TrianglesAtDecision = triangles;
    this->DepthTrianglesAtDecision = depthTriangles;
    this->SeenAtDecision = this->DecidedPrePass ? this->VisibleCount : this->ShadedCount;
    this->FramesSinceDecision = 0;
    usePrePass = this->DecidedPrePass;
  }
  else
  {
    // Each mode counts one of the two numbers: the other is refreshed by one frame in the
    // other mode when the one counted moves (the view or the data changed) or at intervals.
    const double seen = this->DecidedPrePass ? this->VisibleCount : this->ShadedCount;
    this->Refreshing = ++this->FramesSinceDecision >= ReprobeInterval ||
      std::abs(seen - this->SeenAtDecision) > ReprobeChange * this->SeenAtDecision;
    usePrePass = this->Refreshing
      ? !this->DecidedPrePass && this->CouldPay(depthTriangles, evaluatedLights)
      : this->DecidedPrePass;
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
  for (int count : { Shaded, Visible })
  {
    if (this->Started[count])
    {
      if (count == Shaded)
      {
        this->ShadedCount = counts[count];
        this->ShadedCulled = this->CullingOfStartedShaded;
      }
      else
      {
        this->VisibleCount = counts[count];
      }
      this->Started[count] = false;
    }
  }
}

//------------------------------------------------------------------------------
double vtkPhongDepthPrePass::GetDepthComplexity() const
{
  return (this->ShadedCount > 0.0 && this->VisibleCount > 0.0)
    ? this->ShadedCount / this->VisibleCount
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
  this->ShadedCount = this->VisibleCount = 0.0;
  this->Decided = this->DecidedPrePass = this->Refreshing = false;
  this->SeenAtDecision = 0.0;
  this->FramesSinceDecision = 0;
  this->LightsAtDecision = 0;
  this->TrianglesAtDecision = 0.0;
  this->DepthTrianglesAtDecision = 0.0;
}
