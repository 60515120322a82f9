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

#include <algorithm>

#include "vtkPhongBlockMapper.h"
#if VTKPHONG_VTK_9_3
#include "vtkPhongCompositeDelegator.h"
#endif

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

struct vtkPhongCompositePolyDataMapper::Internals
{
  vtkPhongLightingSettingsHolder Settings;
  // The helpers made so far. The superclass deletes the helpers it no longer needs (and, on
  // VTK 9.3, keeps them out of reach): their entries then expire.
  std::vector<vtkWeakPointer<vtkPhongBlockMapper>> Helpers;
  std::string LastSignature;
  // The leaves as the bounds and the block mappers see them: collapsed copies of those with
  // invalid cells.
  vtkPhongValidBlocks ValidBlocks;

  // A helper lights with the composite mapper's settings and draws its valid blocks.
  void Own(vtkPhongBlockMapper* helper, vtkPhongCompositePolyDataMapper* owner)
  {
    helper->SetOwner(
      this->Settings.Get(), [owner](vtkPolyData* block) { return owner->GetValidBlock(block); });
  }

  void Add(vtkPhongBlockMapper* helper, vtkPhongCompositePolyDataMapper* owner)
  {
    this->Prune();
    this->Own(helper, owner);
    this->Helpers.emplace_back(helper);
  }

  void Prune()
  {
    auto expired = [](const vtkWeakPointer<vtkPhongBlockMapper>& helper)
    { return helper == nullptr; };
    this->Helpers.erase(
      std::remove_if(this->Helpers.begin(), this->Helpers.end(), expired), this->Helpers.end());
  }

  // Whether a helper's statement about its last draw holds for any helper.
  bool Any(bool (vtkPhongBlockMapper::*statement)() const)
  {
    this->Prune();
    for (const auto& helper : this->Helpers)
    {
      if ((helper.GetPointer()->*statement)())
      {
        return true;
      }
    }
    return false;
  }

  // A value of the helpers' cores, the largest.
  template <typename Value>
  Value Largest(Value (vtkPhongMapperCore::*value)() const)
  {
    this->Prune();
    Value largest = 0;
    for (const auto& helper : this->Helpers)
    {
      largest = std::max(largest, (helper->GetCore()->*value)());
    }
    return largest;
  }

  // A statistic of the helpers' cores, summed.
  int Sum(int (vtkPhongMapperCore::*statistic)() const)
  {
    this->Prune();
    int sum = 0;
    for (const auto& helper : this->Helpers)
    {
      sum += (helper->GetCore()->*statistic)();
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

//------------------------------------------------------------------------------
vtkPhongLightingSettings* vtkPhongCompositePolyDataMapper::GetLightingSettings()
{
  return this->Internal->Settings.Get();
}

//------------------------------------------------------------------------------
// The helpers made so far light with the new settings too.
void vtkPhongCompositePolyDataMapper::SetLightingSettings(vtkPhongLightingSettings* settings)
{
  if (!this->Internal->Settings.Set(settings, this))
  {
    return;
  }
  this->Internal->Prune();
  for (const auto& helper : this->Internal->Helpers)
  {
    this->Internal->Own(helper, this);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
vtkMTimeType vtkPhongCompositePolyDataMapper::GetMTime()
{
  return this->Internal->Settings.MTime(this->Superclass::GetMTime());
}

//------------------------------------------------------------------------------
void vtkPhongCompositePolyDataMapper::ShallowCopy(vtkAbstractMapper* mapper)
{
  if (auto* phong = vtkPhongCompositePolyDataMapper::SafeDownCast(mapper))
  {
    this->Internal->Settings.Get()->DeepCopy(phong->GetLightingSettings());
  }
  this->Superclass::ShallowCopy(mapper);
}

#if VTKPHONG_VTK_9_3
//------------------------------------------------------------------------------
vtkCompositePolyDataMapperDelegator* vtkPhongCompositePolyDataMapper::CreateADelegator()
{
  vtkPhongCompositeDelegator* delegator = vtkPhongCompositeDelegator::New();
  this->Internal->Add(
    static_cast<vtkPhongBlockMapper*>(delegator->GetDelegate().GetPointer()), this);
  return delegator;
}
#else
//------------------------------------------------------------------------------
vtkCompositeMapperHelper2* vtkPhongCompositePolyDataMapper::CreateHelper()
{
  auto* helper = vtkPhongBlockMapper::New();
  this->Internal->Add(helper, this);
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
double vtkPhongCompositePolyDataMapper::GetErrorBound()
{
  return this->Internal->Largest(&vtkPhongMapperCore::GetErrorBound);
}

//------------------------------------------------------------------------------
int vtkPhongCompositePolyDataMapper::GetBudgetMode()
{
  return this->Internal->Largest(&vtkPhongMapperCore::GetBudgetMode);
}

//------------------------------------------------------------------------------
const char* vtkPhongCompositePolyDataMapper::GetBudgetModeAsString()
{
  return vtkPhongLightingSettings::GetBudgetModeAsString(this->GetBudgetMode());
}

//------------------------------------------------------------------------------
int vtkPhongCompositePolyDataMapper::GetSquaredShininess()
{
  return this->Internal->Largest(&vtkPhongMapperCore::GetSquaredShininess);
}

//------------------------------------------------------------------------------
bool vtkPhongCompositePolyDataMapper::GetUsedClosedSurfaceCulling()
{
  return this->Internal->Any(&vtkPhongBlockMapper::GetUsedClosedSurfaceCulling);
}

//------------------------------------------------------------------------------
bool vtkPhongCompositePolyDataMapper::GetUsedDepthPrePass()
{
  return this->Internal->Any(&vtkPhongBlockMapper::GetUsedDepthPrePass);
}

//------------------------------------------------------------------------------
const char* vtkPhongCompositePolyDataMapper::GetLastShaderSignature()
{
  this->Internal->Prune();
  this->Internal->LastSignature.clear();
  for (const auto& helper : this->Internal->Helpers)
  {
    const std::string& signature = helper->GetCore()->GetLastShaderSignature();
    if (!signature.empty())
    {
      this->Internal->LastSignature = signature;
    }
  }
  return this->Internal->LastSignature.c_str();
}

//------------------------------------------------------------------------------
void vtkPhongCompositePolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UsedDepthPrePass: " << (this->GetUsedDepthPrePass() ? "yes" : "no") << "\n";
  os << indent
     << "UsedClosedSurfaceCulling: " << (this->GetUsedClosedSurfaceCulling() ? "yes" : "no")
     << "\n";
  os << indent << "LightingSettings:\n";
  this->Internal->Settings.Get()->PrintSelf(os, indent.GetNextIndent());
  os << indent << "NumberOfHelpers: " << this->GetNumberOfHelpers() << "\n";
  os << indent << "ShaderCompileCount: " << this->GetShaderCompileCount() << "\n";
  os << indent << "NumberOfShaderVariants: " << this->GetNumberOfShaderVariants() << "\n";
  os << indent << "LastShaderSignature: " << this->GetLastShaderSignature() << "\n";
  os << indent << "ErrorBound: " << this->GetErrorBound() << "\n";
  os << indent << "BudgetMode: " << this->GetBudgetModeAsString() << "\n";
  os << indent << "SquaredShininess: " << this->GetSquaredShininess() << "\n";
}
