#include "vtkPhongBufferBlocks.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <limits>

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkPhongBufferBlocks::Points(
  const std::vector<vtkPhongBufferBlock>& blocks)
{
  if (blocks.size() == 1 && blocks[0].FirstPoint == 0)
  {
    return blocks[0].Data;
  }
  struct Range
  {
    vtkIdType First, Last; // [First, Last)
    vtkDataArray* Source;
    bool operator<(const Range& other) const { return this->First < other.First; }
  };
  std::vector<Range> ranges;
  vtkIdType count = 0;
  for (const vtkPhongBufferBlock& block : blocks)
  {
    const vtkIdType last = block.FirstPoint + block.Data->GetNumberOfPoints();
    if (last > block.FirstPoint)
    {
      ranges.push_back({ block.FirstPoint, last, block.Data->GetPoints()->GetData() });
      count = std::max(count, last);
    }
  }
  std::sort(ranges.begin(), ranges.end());
  for (size_t k = 1; k < ranges.size(); ++k)
  {
    const Range& previous = ranges[k - 1];
    const bool shared = ranges[k].First == previous.First && ranges[k].Source == previous.Source;
    if (ranges[k].First < previous.Last && !shared)
    {
      return nullptr;
    }
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(count);
  points->GetData()->Fill(std::numeric_limits<double>::quiet_NaN());
  for (const vtkPhongBufferBlock& block : blocks)
  {
    vtkDataArray* source = block.Data->GetPoints()->GetData();
    for (vtkIdType p = 0; p < source->GetNumberOfTuples(); ++p)
    {
      points->SetPoint(block.FirstPoint + p, source->GetTuple3(p));
    }
  }
  auto merged = vtkSmartPointer<vtkPolyData>::New();
  merged->SetPoints(points);
  return merged;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkPhongBufferBlocks::CopyOfPoints(vtkPolyData* input)
{
  vtkNew<vtkPoints> points;
  points->DeepCopy(input->GetPoints());
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->SetPoints(points);
  return copy;
}

//------------------------------------------------------------------------------
namespace
{
// The group lists its buffers only to subclasses: a pointer to the protected member, taken
// where it is accessible, reads it from any group.
struct vtkPhongBufferGroupAccess : vtkOpenGLVertexBufferObjectGroup
{
  static auto UsedBuffers() { return &vtkPhongBufferGroupAccess::UsedVBOs; }
};
}

void vtkPhongBufferBlocks::ReleasePackedCopies(vtkOpenGLVertexBufferObjectGroup* buffers)
{
  if (!buffers)
  {
    return;
  }
  for (auto& named : buffers->*vtkPhongBufferGroupAccess::UsedBuffers())
  {
    if (named.second && named.second->GetPackedVBO().empty())
    {
      std::vector<float>().swap(named.second->GetPackedVBO());
    }
  }
}
