#include "vtkPhongSeamNormalsPatch.h"

#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPhongSeamFacesExchange.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkPhongSeamNormalsPatch);

namespace
{
// Per point: whether the normals filter gave it copies (output points whose original id, in
// the array named originalIdsName, is another point's).
std::vector<char> SplitPoints(vtkPolyData* mesh, const char* originalIdsName)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::vector<char> split(static_cast<size_t>(n), 0);
  vtkDataArray* original = mesh->GetPointData()->GetArray(originalIdsName);
  for (vtkIdType i = 0; original && i < original->GetNumberOfTuples() && i < n; ++i)
  {
    const auto o = static_cast<vtkIdType>(original->GetComponent(i, 0));
    if (o != i && o >= 0 && o < n)
    {
      split[o] = 1;
    }
  }
  return split;
}
}

//------------------------------------------------------------------------------
vtkPhongSeamNormalsPatch::vtkPhongSeamNormalsPatch()
{
  this->SetNumberOfInputPorts(2);
  this->SetOriginalPointIdsArrayName("vtkOriginalPointIds");
}

//------------------------------------------------------------------------------
vtkPhongSeamNormalsPatch::~vtkPhongSeamNormalsPatch()
{
  this->SetOriginalPointIdsArrayName(nullptr);
}

//------------------------------------------------------------------------------
int vtkPhongSeamNormalsPatch::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkPhongSeamNormalsPatch::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* piece = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* seam = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfPatchedPoints = this->NumberOfSplitSeamPoints = 0;
  output->ShallowCopy(piece);
  vtkDataArray* normals = piece ? piece->GetPointData()->GetNormals() : nullptr;
  vtkDataArray* seamNormals = seam ? seam->GetPointData()->GetNormals() : nullptr;
  auto* pieceIds = seam ? vtkIdTypeArray::SafeDownCast(seam->GetPointData()->GetArray(
                            vtkPhongSeamFacesExchange::PiecePointIdsArrayName()))
                        : nullptr;
  if (!normals || !seamNormals || !pieceIds || normals->GetNumberOfComponents() != 3 ||
    seamNormals->GetNumberOfComponents() != 3)
  {
    return 1;
  }
  const vtkIdType n = piece->GetNumberOfPoints();
  const std::vector<char> split = SplitPoints(piece, this->OriginalPointIdsArrayName);
  // A piece point the seam mesh's normals split appears there more than once.
  std::unordered_map<vtkIdType, int> copies;
  for (vtkIdType i = 0; i < pieceIds->GetNumberOfTuples(); ++i)
  {
    const vtkIdType p = pieceIds->GetValue(i);
    if (p >= 0 && p < n)
    {
      ++copies[p];
    }
  }
  auto patched = vtkSmartPointer<vtkDataArray>::Take(normals->NewInstance());
  patched->DeepCopy(normals);
  for (vtkIdType i = 0; i < pieceIds->GetNumberOfTuples(); ++i)
  {
    const vtkIdType p = pieceIds->GetValue(i);
    if (p >= 0 && p < n && copies[p] == 1 && !split[p])
    {
      patched->SetTuple(p, seamNormals->GetTuple(i));
      ++this->NumberOfPatchedPoints;
    }
  }
  for (const auto& point : copies)
  {
    this->NumberOfSplitSeamPoints += point.second > 1 || (point.second == 1 && split[point.first]);
  }
  output->GetPointData()->SetNormals(patched);
  return 1;
}

//------------------------------------------------------------------------------
void vtkPhongSeamNormalsPatch::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OriginalPointIdsArrayName: "
     << (this->OriginalPointIdsArrayName ? this->OriginalPointIdsArrayName : "(none)") << "\n";
  os << indent << "NumberOfPatchedPoints: " << this->NumberOfPatchedPoints << "\n";
  os << indent << "NumberOfSplitSeamPoints: " << this->NumberOfSplitSeamPoints << "\n";
}
