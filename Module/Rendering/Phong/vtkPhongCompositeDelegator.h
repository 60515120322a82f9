/**
 * @class   vtkPhongCompositeDelegator
 * @brief   the delegator of vtkPhongCompositePolyDataMapper on VTK 9.3 and later
 *
 * From VTK 9.3 on, vtkCompositePolyDataMapper groups the blocks by what arrays they carry and
 * hands each group to a delegator made by CreateADelegator(); the delegator's delegate, a
 * vtkOpenGLBatchedPolyDataMapper, draws the group. This delegator is VTK's own
 * vtkOpenGLCompositePolyDataMapperDelegator with its delegate replaced by one that lights with
 * vtkPhong (vtkPhongBlockMapper), at construction, before the composite mapper uses it.
 *
 * Built for VTK 9.3 and later only (CMakeLists.txt); private to the rendering module.
 *
 * @sa vtkPhongCompositePolyDataMapper vtkPhongBlockMapper vtkPhongCompatibility.h
 */

#ifndef vtkPhongCompositeDelegator_h
#define vtkPhongCompositeDelegator_h

#include "vtkOpenGLCompositePolyDataMapperDelegator.h"

class vtkPhongCompositeDelegator : public vtkOpenGLCompositePolyDataMapperDelegator
{
public:
  static vtkPhongCompositeDelegator* New();
  vtkTypeMacro(vtkPhongCompositeDelegator, vtkOpenGLCompositePolyDataMapperDelegator);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkPhongCompositeDelegator();
  ~vtkPhongCompositeDelegator() override;

private:
  vtkPhongCompositeDelegator(const vtkPhongCompositeDelegator&) = delete;
  void operator=(const vtkPhongCompositeDelegator&) = delete;
};

#endif
