#include "vtkPhongVisibleClusters.h"

#include "vtkActor.h"
#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPhongBackgroundTask.h"
#include "vtkPhongBufferBlocks.h"
#include "vtkPhongDepthPrePass.h"
#include "vtkPhongOpenGL.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace
{
bool IsFinite(const double p[3])
{
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

// The least view depth of the corners of a box, `row` the model-to-view matrix's z row.
double NearestDepth(const vtkBoundingBox& box, const double row[4])
{
  if (!box.IsValid())
  {
    return VTK_DOUBLE_MAX; // no finite point
  }
  double nearest = VTK_DOUBLE_MAX;
  for (int c = 0; c < 8; ++c)
  {
    double p[3];
    box.GetCorner(c, p);
    nearest = std::min(nearest, -(row[0] * p[0] + row[1] * p[1] + row[2] * p[2] + row[3]));
  }
  return nearest;
}
}

//------------------------------------------------------------------------------
// Large meshes' clusters, arranged on a thread of their own from copies of the indices and
// points (vtkPhongBackgroundTask); uploaded by the first Update after they are in.
struct vtkPhongVisibleClusters::Background
{
  vtkPhongVisibleClusters Arranged;
  std::unique_ptr<vtkPhongBackgroundTask> Task;
};

//------------------------------------------------------------------------------
vtkPhongVisibleClusters::vtkPhongVisibleClusters() = default;

//------------------------------------------------------------------------------
vtkPhongVisibleClusters::~vtkPhongVisibleClusters() = default; // GL objects die with the context

//------------------------------------------------------------------------------
bool vtkPhongVisibleClusters::IsCurrent(
  vtkWindow* window, vtkOpenGLIndexBufferObject* triangles, vtkMTimeType builtAt) const
{
  return window == this->Window && builtAt == this->BuiltAt &&
    triangles->IndexCount == this->IndexCount;
}

//------------------------------------------------------------------------------
bool vtkPhongVisibleClusters::Update(vtkWindow* window, vtkOpenGLIndexBufferObject* triangles,
  vtkPolyData* input, vtkMTimeType builtAt)
{
  if (window != this->Window)
  {
    this->Reset(); // a new context: the old one's objects went with it
    this->Window = window;
  }
  if (this->IsCurrent(window, triangles, builtAt))
  {
    this->CollectBackground();
    return !this->Clusters.empty();
  }
  this->Pending.reset(); // waits for an arrangement of an older upload: one at a time
  this->BuiltAt = builtAt;
  this->IndexCount = triangles->IndexCount;
  this->Clusters.clear();
  this->GroupBoxes.clear();
  this->Counting = false;
  this->Triangles = this->TrianglesDrawn = 0.0;
  std::vector<unsigned int> indices;
  if (!input || !input->GetPoints() || !this->ReadIndices(triangles, indices))
  {
    return false;
  }
  const vtkIdType points = input->GetNumberOfPoints();
  if (std::any_of(indices.begin(), indices.end(),
        [points](unsigned int index) { return static_cast<vtkIdType>(index) >= points; }))
  {
    return false; // the buffer's vertices are not the input's points
  }
  if (indices.size() / 3 >= vtkPhongBackgroundTask::LargeTriangles)
  {
    this->ArrangeInBackground(std::move(indices), input);
    return false; // the depth pass draws every triangle until the clusters are in
  }
  this->Arrange(indices, input);
  this->Install();
  return !this->Clusters.empty();
}

//------------------------------------------------------------------------------
void vtkPhongVisibleClusters::ArrangeInBackground(
  std::vector<unsigned int> indices, vtkPolyData* input)
{
  vtkSmartPointer<vtkPolyData> copy = vtkPhongBufferBlocks::CopyOfPoints(input);
  this->Pending = std::make_unique<Background>();
  Background* pending = this->Pending.get();
  pending->Task = std::make_unique<vtkPhongBackgroundTask>(
    [pending, copy, indices = std::move(indices)]() { pending->Arranged.Arrange(indices, copy); });
}

//------------------------------------------------------------------------------
void vtkPhongVisibleClusters::CollectBackground()
{
  if (!this->Pending || !this->Pending->Task->IsDone())
  {
    return;
  }
  this->Pending->Task->Wait();
  vtkPhongVisibleClusters& arranged = this->Pending->Arranged;
  this->Clusters = std::move(arranged.Clusters);
  this->GroupBoxes = std::move(arranged.GroupBoxes);
  this->Sorted = std::move(arranged.Sorted);
  this->Triangles = arranged.Triangles;
  this->Pending.reset();
  if (!this->Clusters.empty())
  {
    this->Install();
  }
}

//------------------------------------------------------------------------------
bool vtkPhongVisibleClusters::ReadIndices(
  vtkOpenGLIndexBufferObject* triangles, std::vector<unsigned int>& indices)
{
  if (!HoldsTriangles(triangles))
  {
    return false;
  }
  indices.resize(triangles->IndexCount);
  ReadIndices(triangles, 0, indices);
  return true;
}

//------------------------------------------------------------------------------
bool vtkPhongVisibleClusters::HoldsTriangles(vtkOpenGLIndexBufferObject* triangles)
{
  const size_t count = triangles->IndexCount;
  return count > 0 && count % 3 == 0 && triangles->GetHandle();
}

//------------------------------------------------------------------------------
void vtkPhongVisibleClusters::ReadIndices(
  vtkOpenGLIndexBufferObject* triangles, size_t first, std::vector<unsigned int>& indices)
{
  glBindBuffer(GL_COPY_READ_BUFFER, triangles->GetHandle());
  glGetBufferSubData(GL_COPY_READ_BUFFER, static_cast<GLintptr>(first * sizeof(unsigned int)),
    static_cast<GLsizeiptr>(indices.size() * sizeof(unsigned int)), indices.data());
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
}

//------------------------------------------------------------------------------
// Clusters never mix connected components that are large enough to fill one (nested
// contours are separate components, and a cluster holding parts of two shows as long as the
// outer part does). Within a component, or a run of small ones, the triangles are split at
// the median of their centroids along the longest axis until each part is one cluster.
void vtkPhongVisibleClusters::Arrange(const std::vector<unsigned int>& indices, vtkPolyData* input)
{
  const size_t triangles = indices.size() / 3;
  const std::vector<std::uint32_t> components = ConnectedComponents(indices, input);
  const std::vector<double> centroids = Centroids(indices, input);
  std::vector<std::uint32_t> order(triangles);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
    [&components](std::uint32_t a, std::uint32_t b) { return components[a] < components[b]; });
  const size_t target = std::max<size_t>(MinimumClusterTriangles,
    (triangles + MaximumClusters - 1) / static_cast<size_t>(MaximumClusters));
  for (size_t first = 0; first < triangles;)
  {
    size_t last = first;
    while (last < triangles &&
      (last == first || components[order[last]] == components[order[last - 1]] ||
        4 * (last - first) < target))
    {
      ++last;
    }
    this->Split(order, centroids, first, last, target);
    this->GroupBoxes.emplace_back();
    first = last;
  }
  std::vector<unsigned int> sorted(indices.size());
  for (size_t t = 0; t < triangles; ++t)
  {
    std::copy_n(&indices[3 * order[t]], 3, &sorted[3 * t]);
  }
  this->ComputeBounds(sorted, input);
  this->Sorted = std::move(sorted);
  this->Triangles = static_cast<double>(triangles);
}

//------------------------------------------------------------------------------
// The arranged triangles to the GPU, and a query per cluster.
void vtkPhongVisibleClusters::Install()
{
  this->SortedTriangles->Upload(this->Sorted, vtkOpenGLBufferObject::ElementArrayBuffer);
  this->SortedTriangles->IndexCount = this->Sorted.size();
  this->Sorted = std::vector<unsigned int>();
  this->CountAll = true;
  if (this->Queries.size() < this->Clusters.size())
  {
    const size_t had = this->Queries.size();
    this->Queries.resize(this->Clusters.size(), 0);
    glGenQueries(static_cast<GLsizei>(this->Queries.size() - had), this->Queries.data() + had);
  }
}

//------------------------------------------------------------------------------
// Triangles order[first, last) become clusters of at most `target`, halved at the median
// centroid along the longest axis of their centroids' bounds.
void vtkPhongVisibleClusters::Split(std::vector<std::uint32_t>& order,
  const std::vector<double>& centroids, size_t first, size_t last, size_t target)
{
  if (last - first <= target)
  {
    Cluster cluster;
    cluster.Group = this->GroupBoxes.size();
    cluster.FirstIndex = static_cast<vtkIdType>(3 * first);
    cluster.IndexCount = static_cast<vtkIdType>(3 * (last - first));
    this->Clusters.push_back(cluster);
    return;
  }
  vtkBoundingBox box;
  for (size_t t = first; t < last; ++t)
  {
    const double* centroid = &centroids[3 * order[t]];
    if (IsFinite(centroid))
    {
      box.AddPoint(centroid[0], centroid[1], centroid[2]);
    }
  }
  double lengths[3] = { 0.0, 0.0, 0.0 };
  if (box.IsValid())
  {
    box.GetLengths(lengths);
  }
  const int longest = static_cast<int>(std::max_element(lengths, lengths + 3) - lengths);
  const size_t middle = first + (last - first) / 2;
  // NaN centroids compare as the lowest, so the order stays strict and weak.
  auto key = [&centroids, longest](std::uint32_t t)
  {
    const double x = centroids[3 * t + longest];
    return std::isnan(x) ? -VTK_DOUBLE_MAX : x;
  };
  std::nth_element(order.begin() + first, order.begin() + middle, order.begin() + last,
    [&key](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
  this->Split(order, centroids, first, middle, target);
  this->Split(order, centroids, middle, last, target);
}

//------------------------------------------------------------------------------
// Each triangle's connected component (triangles sharing a point), numbered in order of
// first appearance.
std::vector<std::uint32_t> vtkPhongVisibleClusters::ConnectedComponents(
  const std::vector<unsigned int>& indices, vtkPolyData* input)
{
  std::vector<std::uint32_t> parent(input->GetNumberOfPoints()); // indices are 32-bit
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&parent](std::uint32_t p)
  {
    while (parent[p] != p)
    {
      parent[p] = parent[parent[p]];
      p = parent[p];
    }
    return p;
  };
  for (size_t i = 0; i < indices.size(); i += 3)
  {
    const std::uint32_t a = root(indices[i]);
    for (int k = 1; k < 3; ++k)
    {
      const std::uint32_t b = root(indices[i + k]);
      parent[b] = a;
    }
  }
  constexpr std::uint32_t unnumbered = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t>& numbers = parent; // each root's number, once the roots are found
  std::vector<std::uint32_t> components(indices.size() / 3);
  std::uint32_t count = 0;
  for (size_t t = 0; t < components.size(); ++t)
  {
    components[t] = root(indices[3 * t]);
  }
  std::fill(numbers.begin(), numbers.end(), unnumbered);
  for (std::uint32_t& component : components)
  {
    std::uint32_t& number = numbers[component];
    if (number == unnumbered)
    {
      number = count++;
    }
    component = number;
  }
  return components;
}

//------------------------------------------------------------------------------
// Each triangle's centroid (x, y, z, x, y, z, ...).
std::vector<double> vtkPhongVisibleClusters::Centroids(
  const std::vector<unsigned int>& indices, vtkPolyData* input)
{
  vtkPoints* points = input->GetPoints();
  std::vector<double> centroids(indices.size(), 0.0);
  for (size_t i = 0; i < indices.size(); ++i)
  {
    double corner[3];
    points->GetPoint(indices[i], corner);
    double* centroid = &centroids[3 * (i / 3)];
    for (int axis = 0; axis < 3; ++axis)
    {
      centroid[axis] += corner[axis] / 3.0;
    }
  }
  return centroids;
}

//------------------------------------------------------------------------------
// Each cluster's and group's box around their finite points, for the draw order, and the
// range of vertices each cluster uses, for the driver.
void vtkPhongVisibleClusters::ComputeBounds(
  const std::vector<unsigned int>& sorted, vtkPolyData* input)
{
  vtkPoints* points = input->GetPoints();
  for (Cluster& cluster : this->Clusters)
  {
    cluster.Box.Reset();
    const auto first = sorted.begin() + cluster.FirstIndex;
    const auto range = std::minmax_element(first, first + cluster.IndexCount);
    cluster.FirstVertex = *range.first;
    cluster.LastVertex = *range.second;
    for (vtkIdType i = cluster.FirstIndex; i < cluster.FirstIndex + cluster.IndexCount; ++i)
    {
      double p[3];
      points->GetPoint(sorted[i], p);
      if (IsFinite(p))
      {
        cluster.Box.AddPoint(p);
        this->GroupBoxes[cluster.Group].AddPoint(p);
      }
    }
  }
}

//------------------------------------------------------------------------------
double vtkPhongVisibleClusters::CollectVisibility()
{
  if (this->Counting)
  {
    std::vector<GLuint> samples(this->Clusters.size(), 0);
    for (size_t k = 0; k < this->Clusters.size(); ++k)
    {
      if (!this->Clusters[k].Counted)
      {
        continue;
      }
      GLuint available = 0;
      glGetQueryObjectuiv(this->Queries[k], GL_QUERY_RESULT_AVAILABLE, &available);
      if (!available)
      {
        return this->TrianglesDrawn; // not in yet: keep the last frame's choice
      }
      glGetQueryObjectuiv(this->Queries[k], GL_QUERY_RESULT, &samples[k]);
    }
    for (size_t k = 0; k < this->Clusters.size(); ++k)
    {
      Cluster& cluster = this->Clusters[k];
      if (cluster.Counted)
      {
        cluster.Seen = samples[k] > 0;
        cluster.Counted = false;
      }
    }
    this->Counting = false;
  }
  double seen = 0.0;
  for (const Cluster& cluster : this->Clusters)
  {
    seen += cluster.Seen ? cluster.IndexCount / 3 : 0;
  }
  return seen;
}

//------------------------------------------------------------------------------
// Seen clusters nearest first (what is drawn first hides what lies behind it, so a hidden
// cluster drawn after its occluders counts no fragment), then the hidden clusters' share of
// the round robin. Counting is skipped while another GL_SAMPLES_PASSED query runs.
void vtkPhongVisibleClusters::Draw(vtkRenderer* ren, vtkActor* act)
{
  GLint active = 0;
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &active);
  const bool counting = active == 0 && !this->Counting;
  // A query costs (llvmpipe marks its start and end in every tile of the window), and so does
  // a draw: a seen cluster is counted every RecountInterval frames, a hidden one each time it
  // is drawn, and the seen clusters not counted are drawn first, in runs.
  // The first draw after a build counts them all: Automatic decides from the next frame's
  // counts whether the pre-pass pays, and it pays only once the hidden clusters are known.
  std::vector<bool> counted(this->Clusters.size(), false);
  for (size_t k = 0; counting && k < counted.size(); ++k)
  {
    counted[k] =
      !this->Clusters[k].Seen || this->CountAll || (k + this->Frame) % RecountInterval == 0;
  }
  this->CountAll = this->CountAll && !counting;
  this->SortedTriangles->Bind();
  this->TrianglesDrawn = 0.0;
  this->DrawUncountedRuns(counted);
  for (size_t k : this->DrawOrder(ren, act))
  {
    if (counted[k])
    {
      this->DrawCluster(k);
    }
  }
  this->SortedTriangles->Release();
  this->Counting = this->Counting || counting;
  ++this->Frame;
}

//------------------------------------------------------------------------------
// Runs of consecutive seen clusters not counted this frame, a draw each: they hide what the
// counted ones may lie behind.
void vtkPhongVisibleClusters::DrawUncountedRuns(const std::vector<bool>& counted)
{
  const size_t count = this->Clusters.size();
  for (size_t k = 0; k < count;)
  {
    if (!this->Clusters[k].Seen || counted[k])
    {
      ++k;
      continue;
    }
    const vtkIdType firstIndex = this->Clusters[k].FirstIndex;
    vtkIdType indices = 0;
    unsigned int firstVertex = this->Clusters[k].FirstVertex, lastVertex = 0;
    for (; k < count && this->Clusters[k].Seen && !counted[k]; ++k)
    {
      indices += this->Clusters[k].IndexCount;
      firstVertex = std::min(firstVertex, this->Clusters[k].FirstVertex);
      lastVertex = std::max(lastVertex, this->Clusters[k].LastVertex);
    }
    glDrawRangeElements(GL_TRIANGLES, firstVertex, lastVertex, static_cast<GLsizei>(indices),
      GL_UNSIGNED_INT, reinterpret_cast<const void*>(firstIndex * sizeof(GLuint)));
    this->TrianglesDrawn += indices / 3;
  }
}

//------------------------------------------------------------------------------
// The seen clusters by the view depth of the nearest corner of their group's bounds (of
// nested contours, the outer one's bounds hold the inner ones': all of it is drawn first),
// then of their own; then the hidden ones to retest.
std::vector<size_t> vtkPhongVisibleClusters::DrawOrder(vtkRenderer* ren, vtkActor* act)
{
  vtkNew<vtkMatrix4x4> modelToView;
  vtkMatrix4x4::Multiply4x4(
    ren->GetActiveCamera()->GetModelViewTransformMatrix(), act->GetMatrix(), modelToView);
  const double* row = modelToView->GetData() + 8; // the view z row: depth is -z
  std::vector<double> groupDepths(this->GroupBoxes.size());
  for (size_t g = 0; g < this->GroupBoxes.size(); ++g)
  {
    groupDepths[g] = NearestDepth(this->GroupBoxes[g], row);
  }
  std::vector<std::pair<std::pair<double, double>, size_t>> seen;
  std::vector<size_t> hidden;
  for (size_t k = 0; k < this->Clusters.size(); ++k)
  {
    const Cluster& cluster = this->Clusters[k];
    if (cluster.Seen)
    {
      seen.push_back({ { groupDepths[cluster.Group], NearestDepth(cluster.Box, row) }, k });
    }
    else
    {
      hidden.push_back(k);
    }
  }
  std::sort(seen.begin(), seen.end());
  std::vector<size_t> order;
  for (const auto& cluster : seen)
  {
    order.push_back(cluster.second);
  }
  const size_t retests = (hidden.size() + RetestInterval - 1) / RetestInterval;
  for (size_t i = 0; i < retests; ++i)
  {
    order.push_back(hidden[(this->NextRetest + i) % hidden.size()]);
  }
  this->NextRetest = hidden.empty() ? 0 : (this->NextRetest + retests) % hidden.size();
  return order;
}

//------------------------------------------------------------------------------
void vtkPhongVisibleClusters::DrawCluster(size_t k)
{
  Cluster& cluster = this->Clusters[k];
  glBeginQuery(GL_SAMPLES_PASSED, this->Queries[k]);
  glDrawRangeElements(GL_TRIANGLES, cluster.FirstVertex, cluster.LastVertex,
    static_cast<GLsizei>(cluster.IndexCount), GL_UNSIGNED_INT,
    reinterpret_cast<const void*>(cluster.FirstIndex * sizeof(GLuint)));
  glEndQuery(GL_SAMPLES_PASSED);
  cluster.Counted = true;
  this->TrianglesDrawn += cluster.IndexCount / 3;
}

//------------------------------------------------------------------------------
void vtkPhongVisibleClusters::ReleaseGraphicsResources(vtkWindow* window)
{
  if (window && window == this->Window)
  {
    if (!this->Queries.empty())
    {
      glDeleteQueries(static_cast<GLsizei>(this->Queries.size()), this->Queries.data());
    }
    this->SortedTriangles->ReleaseGraphicsResources();
  }
  this->Reset();
}

//------------------------------------------------------------------------------
void vtkPhongVisibleClusters::Reset()
{
  this->Pending.reset();
  this->Clusters.clear();
  this->Sorted.clear();
  this->GroupBoxes.clear();
  this->Queries.clear();
  this->Counting = false;
  this->NextRetest = 0;
  this->Frame = 0;
  this->BuiltAt = 0;
  this->IndexCount = 0;
  this->Window = nullptr;
  this->Triangles = this->TrianglesDrawn = 0.0;
}

//------------------------------------------------------------------------------
bool vtkPhongVisibleClusters::CanCull(
  vtkRenderer* ren, vtkActor* act, vtkMapper* mapper, const vtkOpenGLHelper* primitives)
{
  using Mapper = vtkOpenGLPolyDataMapper;
  const bool onlyTriangles = primitives[Mapper::PrimitiveTris].IBO->IndexCount > 0 &&
    primitives[Mapper::PrimitivePoints].IBO->IndexCount == 0 &&
    primitives[Mapper::PrimitiveLines].IBO->IndexCount == 0 &&
    primitives[Mapper::PrimitiveTriStrips].IBO->IndexCount == 0;
  return onlyTriangles && !ren->GetSelector() && vtkPhongDepthPrePass::CanMeasure(mapper, act);
}
