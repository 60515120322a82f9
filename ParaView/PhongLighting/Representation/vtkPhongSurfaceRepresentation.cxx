#include "vtkPhongSurfaceRepresentation.h"

#include "vtkObjectFactory.h"
#include "vtkOpenMeshNormals.h"
#include "vtkPVLODActor.h"
#include "vtkPhongCompositePolyDataMapper.h"
#include "vtkPhongProperty.h"

vtkStandardNewMacro(vtkPhongSurfaceRepresentation);

//------------------------------------------------------------------------------
vtkPhongSurfaceRepresentation::vtkPhongSurfaceRepresentation()
{
  // The superclass made stock mappers and a plain vtkProperty: replace them, keeping the
  // array names its selection needs, then wire the pipeline again.
  auto* mapper = vtkPhongCompositePolyDataMapper::New();
  mapper->SetProcessIdArrayName("vtkProcessId");
  mapper->SetCompositeIdArrayName("vtkCompositeIndex");
  this->Mapper->Delete();
  this->Mapper = mapper;
  this->LODMapper->Delete();
  this->LODMapper = vtkPhongCompositePolyDataMapper::New();
  this->SetArrayIdNames(nullptr, nullptr);

  auto* material = vtkPhongProperty::New();
  material->DeepCopy(this->Property);
  material->SetLightingModelToBlinnPhong();
  material->SetShininess(100.0);
  this->Property->Delete();
  this->Property = material;

  this->Normals->SetWeighting(vtkOpenMeshNormals::Max);
  this->Normals->SetFeatureAngle(30.0);
  this->Normals->SplittingOn();
  this->SetupDefaults();
}

//------------------------------------------------------------------------------
vtkPhongSurfaceRepresentation::~vtkPhongSurfaceRepresentation() = default;

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetupDefaults()
{
  this->Superclass::SetupDefaults();
  this->ConnectNormals();
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::ConnectNormals()
{
  if (this->ComputeNormals)
  {
    this->Normals->SetInputConnection(this->GeometryFilter->GetOutputPort());
    this->MultiBlockMaker->SetInputConnection(this->Normals->GetOutputPort());
  }
  else
  {
    this->MultiBlockMaker->SetInputConnection(this->GeometryFilter->GetOutputPort());
  }
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetLightingModel(int model)
{
  vtkPhongProperty::SafeDownCast(this->Property)->SetLightingModel(model);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetShininess(double shininess)
{
  vtkPhongProperty::SafeDownCast(this->Property)->SetShininess(shininess);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetEmission(double red, double green, double blue)
{
  vtkPhongProperty::SafeDownCast(this->Property)->SetEmission(red, green, blue);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetPerVertexGouraud(int perVertex)
{
  vtkPhongProperty::SafeDownCast(this->Property)->SetPerVertexGouraud(perVertex != 0);
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetDebugView(int view)
{
  for (vtkMapper* mapper : { this->Mapper, this->LODMapper })
  {
    vtkPhongCompositePolyDataMapper::SafeDownCast(mapper)->SetDebugView(view);
  }
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetDebugLightIndex(int index)
{
  for (vtkMapper* mapper : { this->Mapper, this->LODMapper })
  {
    vtkPhongCompositePolyDataMapper::SafeDownCast(mapper)->SetDebugLightIndex(index);
  }
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetComputeNormals(int compute)
{
  if (this->ComputeNormals != (compute != 0))
  {
    this->ComputeNormals = compute != 0;
    // Only the one connection changes: SetupDefaults would also replace the mappers'
    // block attributes (colours, visibilities) and selection.
    this->ConnectNormals();
    this->MarkModified();
  }
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetNormalsWeighting(int weighting)
{
  if (this->Normals->GetWeighting() != weighting)
  {
    this->Normals->SetWeighting(weighting);
    this->MarkModified();
  }
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::SetNormalsFeatureAngle(double degrees)
{
  if (this->Normals->GetFeatureAngle() != degrees)
  {
    this->Normals->SetFeatureAngle(degrees);
    this->MarkModified();
  }
}

//------------------------------------------------------------------------------
void vtkPhongSurfaceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ComputeNormals: " << (this->ComputeNormals ? "On" : "Off") << "\n";
  os << indent << "Normals:\n";
  this->Normals->PrintSelf(os, indent.GetNextIndent());
}
