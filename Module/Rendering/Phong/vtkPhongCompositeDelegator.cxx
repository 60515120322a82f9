#include "vtkPhongCompositeDelegator.h"

#include "vtkObjectFactory.h"
#include "vtkPhongBlockMapper.h"

vtkStandardNewMacro(vtkPhongCompositeDelegator);

//------------------------------------------------------------------------------
vtkPhongCompositeDelegator::vtkPhongCompositeDelegator()
{
  // The superclass made a stock delegate; nothing has seen it yet. Delegate owns the
  // replacement, GLDelegate is the superclass' typed view of it.
  auto* delegate = vtkPhongBlockMapper::New();
  this->GLDelegate = delegate;
  this->Delegate = vtk::TakeSmartPointer<vtkPolyDataMapper>(delegate);
}

//------------------------------------------------------------------------------
vtkPhongCompositeDelegator::~vtkPhongCompositeDelegator() = default;

//------------------------------------------------------------------------------
void vtkPhongCompositeDelegator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Delegate: " << this->GLDelegate->GetClassName() << "\n";
}
