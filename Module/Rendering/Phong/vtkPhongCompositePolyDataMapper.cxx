#include "vtkPhongCompositePolyDataMapper.h"

#include "vtkBoundingBox.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPhongCompatibility.h"
#include "vtkPhongMapperCore.h"
#include "vtkPhongValidBlocks.h"
#include "vtkPolyData.h"
#include "vtkWeakPointer.h"

#if VTKPHONG_VTK_9_3
#include "vtkOpenGLBatchedPolyDataMapper.h"
#include "vtkPhongBlockMapper.h"
#include "vtkPhongCompositeDelegator.h"
using vtkPhongHelper = vtkPhongBlockMapper<vtkOpenGLBatchedPolyDataMapper>;
#else
// VTK 9.1's vtkCompositeMapperHelper2.h uses these without including them.
#include "vtkColor.h"
#include "vtkHardwareSelector.h"
#include "vtk_glew.h"

#include "vtkCompositeMapperHelper2.h"
#include "vtkPhongBlockMapper.h"
using vtkPhongHelper = vtkPhongBlockMapper<vtkCompositeMapperHelper2>;
#endif

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

struct vtkPhongCompositePolyDataMapper::Internals
{
  // The helpers made so far, with their cores. The superclass deletes the helpers it no
  // longer needs (and, on VTK 9.3, keeps them out of reach): their entries then expire.
  std::vector<std::pair<vtkWeakPointer<vtkObject>, vtkPhongMapperCore*>> Helpers;
  std::string LastSignature;
  // The leaves as the bounds and the block mappers see them: collapsed copies of those with
  // invalid cells.
  vtkPhongValidBlocks ValidBlocks;

  void Add(vtkObject* helper, vtkPhongMapperCore* core)
  {
    this->Prune();
    this->Helpers.emplace_back(helper, core);
  }

  void Prune()
  {
    auto expired = [](const std::pair<vtkWeakPointer<vtkObject>, vtkPhongMapperCore*>& helper)
    { return helper.first == nullptr; };
    this->Helpers.erase(
      std::remove_if(this->Helpers.begin(), this->Helpers.end(), expired), this->Helpers.end());
  }

  // Whether a helper's statement about its last draw holds for any helper.
  bool Any(bool (vtkPhongHelper::*statement)() const)
  {
    this->Prune();
    for (const auto& helper : this->Helpers)
    {
      if ((static_cast<vtkPhongHelper*>(helper.first.GetPointer())->*statement)())
      {
        return true;
      }
    }
    return false;
  }

  // A statistic of the helpers' cores, summed.
  int Sum(int (vtkPhongMapperCore::*statistic)() const)
  {
    this->Prune();
    int sum = 0;
    for (const auto& helper : this->Helpers)
    {
      sum += (helper.second->*statistic)();
    }
    return sum;
  }
};

//------------------------------------------------------------------------------
vtkStandardNewMacro(vtkPhongCompositePolyDataMapper);

//------------------------------------------------------------------------------
vtkPhongCompositePolyDataMapper::vtkPhongCompositePolyDataMapper()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkPhongCompositePolyDataMapper::~vtkPhongCompositePolyDataMapper() = default;

#if VTKPHONG_VTK_9_3
//------------------------------------------------------------------------------
vtkCompositePolyDataMapperDelegator* vtkPhongCompositePolyDataMapper::CreateADelegator()
{
  vtkPhongCompositeDelegator* delegator = vtkPhongCompositeDelegator::New();
  this->Internal->Add(delegator->GetDelegate(), delegator->GetCore());
  return delegator;
}
#else
//------------------------------------------------------------------------------
vtkCompositeMapperHelper2* vtkPhongCompositePolyDataMapper::CreateHelper()
{
  auto* helper = vtkPhongHelper::New();
  this->Internal->Add(helper, helper->GetCore());
  return helper;
}
#endif

//------------------------------------------------------------------------------
namespace
{
// The bounds of the visible polydata leaves under `node`, as VTK's composite mappers decide
// visibility: a block's own setting, else its parent's.
void AddVisibleBounds(vtkDataObject* node, bool parentVisible,
  vtkCompositeDataDisplayAttributes* attributes, vtkPhongValidBlocks& blocks, vtkBoundingBox& box)
{
  const bool visible = (attributes && attributes->HasBlockVisibility(node))
    ? attributes->GetBlockVisibility(node)
    : parentVisible;
  if (auto* tree = vtkDataObjectTree::SafeDownCast(node))
  {
    vtkSmartPointer<vtkDataObjectTreeIterator> children;
    children.TakeReference(tree->NewTreeIterator());
    children->VisitOnlyLeavesOff();
    children->TraverseSubTreeOff();
    for (children->InitTraversal(); !children->IsDoneWithTraversal(); children->GoToNextItem())
    {
      AddVisibleBounds(children->GetCurrentDataObject(), visible, attributes, blocks, box);
    }
  }
  else if (auto* block = vtkPolyData::SafeDownCast(node))
  {
    vtkPolyData* valid = blocks.Get(block, nullptr);
    if (visible && valid->GetNumberOfPoints() > 0)
    {
      box.AddBounds(valid->GetBounds());
    }
  }
}
}

//------------------------------------------------------------------------------
void vtkPhongCompositePolyDataMapper::ComputeBounds()
{
  auto* input = vtkCompositeDataSet::SafeDownCast(this->GetInputDataObject(0, 0));
  vtkPhongValidBlocks& blocks = this->Internal->ValidBlocks;
  if (!blocks.AnyInvalid(input, this))
  {
    this->Superclass::ComputeBounds();
    return;
  }
  vtkBoundingBox box;
  AddVisibleBounds(input, true, this->GetCompositeDataDisplayAttributes(), blocks, box);
  if (box.IsValid())
  {
    box.GetBounds(this->Bounds);
  }
  else
  {
    vtkMath::UninitializeBounds(this->Bounds);
  }
  this->BoundsMTime.Modified();
}

//------------------------------------------------------------------------------
vtkPolyData* vtkPhongCompositePolyDataMapper::GetValidBlock(vtkPolyData* block)
{
  return this->Internal->ValidBlocks.Get(block, this);
}

//------------------------------------------------------------------------------
int vtkPhongCompositePolyDataMapper::GetNumberOfHelpers()
{
  this->Internal->Prune();
  return static_cast<int>(this->Internal->Helpers.size());
}

//------------------------------------------------------------------------------
int vtkPhongCompositePolyDataMapper::GetShaderCompileCount()
{
  return this->Internal->Sum(&vtkPhongMapperCore::GetShaderCompileCount);
}

//------------------------------------------------------------------------------
int vtkPhongCompositePolyDataMapper::GetNumberOfShaderVariants()
{
  return this->Internal->Sum(&vtkPhongMapperCore::GetNumberOfShaderVariants);
}

//------------------------------------------------------------------------------
bool vtkPhongCompositePolyDataMapper::GetUsedClosedSurfaceCulling()
{
  return this->Internal->Any(&vtkPhongHelper::GetUsedClosedSurfaceCulling);
}

//------------------------------------------------------------------------------
bool vtkPhongCompositePolyDataMapper::GetUsedDepthPrePass()
{
  return this->Internal->Any(&vtkPhongHelper::GetUsedDepthPrePass);
}

//------------------------------------------------------------------------------
const char* vtkPhongCompositePolyDataMapper::GetLastShaderSignature()
{
  this->Internal->Prune();
  this->Internal->LastSignature.clear();
  for (const auto& helper : this->Internal->Helpers)
  {
    if (!helper.second->GetLastShaderSignature().empty())
    {
      this->Internal->LastSignature = helper.second->GetLastShaderSignature();
    }
  }
  return this->Internal->LastSignature.c_str();
}

//------------------------------------------------------------------------------
void vtkPhongCompositePolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DebugView: " << this->DebugView << "\n";
  os << indent << "DebugLightIndex: " << this->DebugLightIndex << "\n";
  os << indent << "ShaderSpecialization: " << (this->ShaderSpecialization ? "On" : "Off") << "\n";
  os << indent << "InterpolatedDotProducts: " << (this->InterpolatedDotProducts ? "On" : "Off")
     << "\n";
  os << indent << "LightCullingBound: " << this->LightCullingBound << "\n";
  os << indent << "DepthPrePass: " << this->DepthPrePass << "\n";
  os << indent << "UsedDepthPrePass: " << (this->GetUsedDepthPrePass() ? "yes" : "no") << "\n";
  os << indent
     << "DepthPrePassOcclusionCulling: " << (this->DepthPrePassOcclusionCulling ? "On" : "Off")
     << "\n";
  os << indent << "ClosedSurfaceCulling: " << (this->ClosedSurfaceCulling ? "On" : "Off") << "\n";
  os << indent
     << "UsedClosedSurfaceCulling: " << (this->GetUsedClosedSurfaceCulling() ? "yes" : "no")
     << "\n";
  os << indent << "NumberOfHelpers: " << this->GetNumberOfHelpers() << "\n";
  os << indent << "ShaderCompileCount: " << this->GetShaderCompileCount() << "\n";
  os << indent << "NumberOfShaderVariants: " << this->GetNumberOfShaderVariants() << "\n";
  os << indent << "LastShaderSignature: " << this->GetLastShaderSignature() << "\n";
}
