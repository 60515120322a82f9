#include "vtkPhongBlockMapper.h"

#include "vtkAbstractMapper.h"
#include "vtkPhongCompatibility.h"
#if VTKPHONG_VTK_9_3
#include "vtkCompositePolyDataMapper.h" // the Parent
#else
#include "vtkCompositePolyDataMapper2.h" // the Parent
#endif
#include "vtkObjectFactory.h"
#include "vtkPhongBufferBlocks.h"
#include "vtkPhongLightingMapper.txx"
#include "vtkPolyData.h"
#include "vtkSelection.h"

template class vtkPhongLightingMapper<vtkPhongStockBlockMapper>;

vtkStandardNewMacro(vtkPhongBlockMapper);

namespace
{
// A block mapper made outside a vtkPhong composite mapper (the factory's, for VTK's own
// composite mapper) lights with a copy of the factory's defaults.
vtkSmartPointer<vtkPhongLightingSettings> CopyOfFactoryDefaults()
{
  auto settings = vtkSmartPointer<vtkPhongLightingSettings>::New();
  settings->DeepCopy(vtkPhongLightingSettings::GetFactoryDefaults());
  return settings;
}

// Points a block pointer at another polydata (the block's valid copy) for as long as it
// lives.
class ValidBlockScope
{
public:
  ValidBlockScope(vtkPolyData*& block, vtkPolyData* valid)
    : Block(block)
    , Original(block)
  {
    block = valid;
  }
  ~ValidBlockScope() { this->Block = this->Original; }
  ValidBlockScope(const ValidBlockScope&) = delete;
  void operator=(const ValidBlockScope&) = delete;

private:
  vtkPolyData*& Block;
  vtkPolyData* Original;
};
}

//------------------------------------------------------------------------------
vtkPhongBlockMapper::vtkPhongBlockMapper()
  : Settings(CopyOfFactoryDefaults())
{
}

//------------------------------------------------------------------------------
void vtkPhongBlockMapper::SetOwner(
  vtkPhongLightingSettings* settings, std::function<vtkPolyData*(vtkPolyData*)> validBlock)
{
  this->Settings =
    settings ? vtkSmartPointer<vtkPhongLightingSettings>(settings) : CopyOfFactoryDefaults();
  this->ValidBlockOf = std::move(validBlock);
}

//------------------------------------------------------------------------------
vtkPhongBlockMapper::~vtkPhongBlockMapper() = default;

//------------------------------------------------------------------------------
vtkPhongLightingSettings* vtkPhongBlockMapper::LightingSettings()
{
  return this->Settings;
}

//------------------------------------------------------------------------------
std::vector<vtkPolyData*> vtkPhongBlockMapper::LitBlocks()
{
  return this->GetRenderedList();
}

//------------------------------------------------------------------------------
// Every block in the vertex buffer, with the points each uploaded (its valid copy's, from its
// first vertex on), or none when the buffer does not hold what the blocks say; true when
// every one is visible and opaque.
bool vtkPhongBlockMapper::BlocksInBuffer(std::vector<vtkPhongBufferBlock>& blocks)
{
  bool everyBlock = true;
  auto add = [&](vtkPolyData* data, bool visibleAndOpaque, vtkIdType start, vtkIdType next)
  {
    vtkPolyData* uploaded = this->ValidBlock(data);
    if (!uploaded || next - start != uploaded->GetNumberOfPoints())
    {
      return false;
    }
    everyBlock = everyBlock && visibleAndOpaque;
    blocks.push_back({ uploaded, start });
    return true;
  };
#if VTKPHONG_VTK_9_3
  for (const auto& entry : this->VTKPolyDataToGLBatchElement)
  {
    const auto& element = *entry.second;
    if (!add(element.Parent.PolyData, element.Parent.Visibility && element.Parent.IsOpaque,
          element.StartVertex, element.NextVertex))
#else
  for (const auto& entry : this->Data)
  {
    const vtkCompositeMapperHelperData& element = *entry.second;
    if (!add(element.Data, element.Visibility && element.IsOpaque, element.StartVertex,
          element.NextVertex))
#endif
    {
      blocks.clear();
      return false;
    }
  }
  return everyBlock && !blocks.empty();
}

//------------------------------------------------------------------------------
bool vtkPhongBlockMapper::VisibilityWorkAllowed()
{
  return !this->MixesPointAndCellScalars();
}

//------------------------------------------------------------------------------
// VTK 9.1 groups blocks by whether they have scalars, not by whether these are point or
// cell scalars, then colours the whole group as its last block says: the others read
// colours they do not have, some with an alpha of 0 that the shader discards. A plain draw
// then shows what lies behind; the lit draw after a depth pass would show holes, and culled
// back faces would hide what stock VTK shows. Neither is used for such groups.
bool vtkPhongBlockMapper::MixesPointAndCellScalars()
{
  bool point = false, cell = false;
  for (vtkPolyData* block : this->GetRenderedList())
  {
    int cellFlag = 0;
    if (this->ScalarVisibility &&
      vtkAbstractMapper::GetAbstractScalars(
        block, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag))
    {
      point = point || cellFlag == 0;
      cell = cell || cellFlag != 0;
    }
  }
  return point && cell;
}

//------------------------------------------------------------------------------
int vtkPhongBlockMapper::ClippingPlanesSeen()
{
  return this->GetNumberOfClippingPlanes() +
    (this->Parent ? this->Parent->GetNumberOfClippingPlanes() : 0);
}

//------------------------------------------------------------------------------
// Without a composite mapper nothing says what the blocks close: no culling then.
bool vtkPhongBlockMapper::HasSelection()
{
  vtkSelection* selection = this->Parent ? this->Parent->GetSelection() : nullptr;
  return !this->Parent || (selection && selection->GetNumberOfNodes() > 0);
}

//------------------------------------------------------------------------------
void vtkPhongBlockMapper::SurfaceBounds(double bounds[6])
{
  this->Parent->GetBounds(bounds);
}

//------------------------------------------------------------------------------
// Errors name the mapper the user made, not the block mapper.
vtkObject* vtkPhongBlockMapper::Reporter()
{
  return this->Parent ? static_cast<vtkObject*>(this->Parent) : this;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkPhongBlockMapper::ValidBlock(vtkPolyData* block)
{
  return this->ValidBlockOf ? this->ValidBlockOf(block) : block;
}

#if VTKPHONG_VTK_9_3
//------------------------------------------------------------------------------
void vtkPhongBlockMapper::AppendOneBufferObject(vtkRenderer* ren, vtkActor* act,
  GLBatchElement* element, vtkIdType& offset, std::vector<unsigned char>& colors,
  std::vector<float>& norms)
{
  ValidBlockScope scope(element->Parent.PolyData, this->ValidBlock(element->Parent.PolyData));
  this->Superclass::AppendOneBufferObject(ren, act, element, offset, colors, norms);
}
#else
//------------------------------------------------------------------------------
void vtkPhongBlockMapper::AppendOneBufferObject(vtkRenderer* ren, vtkActor* act,
  vtkCompositeMapperHelperData* element, vtkIdType& offset, std::vector<unsigned char>& colors,
  std::vector<float>& norms)
{
  ValidBlockScope scope(element->Data, this->ValidBlock(element->Data));
  this->Superclass::AppendOneBufferObject(ren, act, element, offset, colors, norms);
}
#endif

//------------------------------------------------------------------------------
void vtkPhongBlockMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Settings: " << this->Settings << "\n";
  os << indent << "ValidBlockOf: " << (this->ValidBlockOf ? "set" : "none") << "\n";
  os << indent << "Lighting:\n";
  this->GetCore()->PrintSelf(os, indent.GetNextIndent());
}
