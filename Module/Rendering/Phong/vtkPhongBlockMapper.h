/**
 * @class   vtkPhongBlockMapper
 * @brief   the mapper that draws a group of blocks for vtkPhongCompositePolyDataMapper
 *
 * vtkPhongBlockMapper<BlockMapper> is VTK's own block mapper of the composite mapper, lit by
 * vtkPhongLightingMapper exactly as vtkPhongPolyDataMapper is. BlockMapper is the class VTK
 * draws a group of blocks with, which depends on the VTK version (vtkPhongCompatibility.h):
 * vtkCompositeMapperHelper2 (a helper of vtkCompositePolyDataMapper2) before VTK 9.3,
 * vtkOpenGLBatchedPolyDataMapper (the delegate of a vtkOpenGLCompositePolyDataMapperDelegator)
 * from VTK 9.3 on. Both keep the blocks in one vertex buffer, know their composite mapper as
 * Parent, list their blocks with GetRenderedList(), and write each block's colour and opacity
 * overrides into VTK's own uniforms (ambientColorUniform, diffuseColorUniform,
 * opacityUniform) between the draws, after the material uniforms set here; the lighting reads
 * those uniforms whenever VTK's colour code assigns the colours more than once
 * (vtkPhongShaderTemplate), so the overrides keep working.
 *
 * What it adds to the lighting mapper is what a buffer of several blocks means: the composite
 * mapper's settings, every block's normals, culling only while every block is drawn, visible
 * and opaque, and blocks uploaded from their valid copies.
 *
 * Private to the rendering module: the composite mapper is the API.
 *
 * @sa vtkPhongCompositePolyDataMapper vtkPhongLightingMapper
 */

#ifndef vtkPhongBlockMapper_h
#define vtkPhongBlockMapper_h

#include "vtkPhongCompatibility.h"
#include "vtkPhongLightingMapper.h"
#include "vtkSmartPointer.h"

#include <functional>
#include <vector>

#if VTKPHONG_VTK_9_3
#include "vtkOpenGLBatchedPolyDataMapper.h"
using vtkPhongStockBlockMapper = vtkOpenGLBatchedPolyDataMapper;
#else
// VTK 9.1's vtkCompositeMapperHelper2.h uses these without including them.
#include "vtkColor.h"
#include "vtkHardwareSelector.h"
#include "vtkPhongOpenGL.h"

#include "vtkCompositeMapperHelper2.h"
using vtkPhongStockBlockMapper = vtkCompositeMapperHelper2;
class vtkCompositeMapperHelperData;
#endif

class vtkPhongBlockMapper : public vtkPhongLightingMapper<vtkPhongStockBlockMapper>
{
public:
  static vtkPhongBlockMapper* New();
  vtkTypeMacro(vtkPhongBlockMapper, vtkPhongLightingMapper<vtkPhongStockBlockMapper>);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * What the composite mapper that made this block mapper lends it: its settings (shared,
   * replaced whenever the composite mapper's are), and the copy of a block that draws (the
   * block itself, or its copy with the cells that name missing points collapsed). Without
   * an owner the block mapper lights with default settings and draws blocks as they are.
   */
  void SetOwner(
    vtkPhongLightingSettings* settings, std::function<vtkPolyData*(vtkPolyData*)> validBlock);

protected:
  vtkPhongBlockMapper();
  ~vtkPhongBlockMapper() override;

  ///@{
  /// The blocks in the buffer, the composite mapper's settings (vtkPhongLightingMapper).
  vtkPhongLightingSettings* LightingSettings() override;
  std::vector<vtkPolyData*> LitBlocks() override;
  bool MaterialPerBlock() override { return true; }
  bool BlocksInBuffer(std::vector<vtkPhongBufferBlock>& blocks) override;
  bool VisibilityWorkAllowed() override;
  int ClippingPlanesSeen() override;
  bool HasSelection() override;
  void SurfaceBounds(double bounds[6]) override;
  vtkObject* Reporter() override;
  ///@}

  // VTK's upload reads the block's points through its cell ids unchecked: a block with cells
  // naming missing points is uploaded from its collapsed copy, which the composite mapper
  // keeps (and has already made for its bounds).
#if VTKPHONG_VTK_9_3
  void AppendOneBufferObject(vtkRenderer* ren, vtkActor* act, GLBatchElement* element,
    vtkIdType& offset, std::vector<unsigned char>& colors, std::vector<float>& norms) override;
#else
  void AppendOneBufferObject(vtkRenderer* ren, vtkActor* act, vtkCompositeMapperHelperData* element,
    vtkIdType& offset, std::vector<unsigned char>& colors, std::vector<float>& norms) override;
#endif

private:
  vtkPhongBlockMapper(const vtkPhongBlockMapper&) = delete;
  void operator=(const vtkPhongBlockMapper&) = delete;

  vtkPolyData* ValidBlock(vtkPolyData* block);
  bool MixesPointAndCellScalars();

  vtkSmartPointer<vtkPhongLightingSettings> Settings;
  std::function<vtkPolyData*(vtkPolyData*)> ValidBlockOf;
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongBlockMapper.h
