#include "vtkOpenMeshNormalsJoin.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkOpenMeshNormalsExecution.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"

#include <algorithm>
#include <map>
#include <unordered_map>
#include <utility>

namespace
{
// Which input point each polygon corner of the joined output stands for, and the copies
// that points need when their corners got different normals.
class NormalAssignment
{
public:
  explicit NormalAssignment(vtkIdType numberOfPoints)
    : NormalOf(numberOfPoints, -1)
  {
  }

  // The output point for input point p with the normal of joined output point o.
  vtkIdType Assign(vtkIdType p, vtkIdType o)
  {
    if (this->NormalOf[p] < 0 || this->NormalOf[p] == o)
    {
      this->NormalOf[p] = o;
      return p;
    }
    const auto inserted = this->Copies.emplace(std::make_pair(p, o),
      static_cast<vtkIdType>(this->NormalOf.size() + this->CopySource.size()));
    if (inserted.second)
    {
      this->CopySource.push_back(p);
      this->CopyNormal.push_back(o);
    }
    return inserted.first->second;
  }

  std::vector<vtkIdType> NormalOf; // per input point: the joined output point, or -1
  std::vector<vtkIdType> CopySource;
  std::vector<vtkIdType> CopyNormal;

private:
  std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> Copies;
};

// +1: the joined face has the input polygon's corners in order; -1: reversed (the first
// corner kept, as the normals filter writes a reversed face); 0: neither (repeats removed).
template <typename JoinedPointOf>
int CornerOrder(const std::vector<vtkIdType>& in, const vtkIdType* joined, vtkIdType size,
  const std::vector<vtkIdType>& representative, const JoinedPointOf& joinedPointOf)
{
  if (static_cast<vtkIdType>(in.size()) != size)
  {
    return 0;
  }
  bool kept = true, reversed = true;
  for (vtkIdType k = 0; k < size; ++k)
  {
    const vtkIdType j = joinedPointOf(joined[k]);
    kept = kept && representative[in[k]] == j;
    reversed = reversed && representative[in[k == 0 ? 0 : size - k]] == j;
  }
  return kept ? 1 : (reversed ? -1 : 0);
}
}

//------------------------------------------------------------------------------
std::vector<vtkIdType> vtkOpenMeshNormalsJoin::Representatives(vtkPolyData* input, double tolerance)
{
  vtkDataArray* ids = input->GetPointData()->GetGlobalIds();
  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<vtkIdType> representative(n);
  if (ids && ids->GetNumberOfTuples() == n && ids->GetNumberOfComponents() == 1)
  {
    std::unordered_map<long long, vtkIdType> first;
    first.reserve(static_cast<size_t>(n));
    for (vtkIdType p = 0; p < n; ++p)
    {
      representative[p] =
        first.emplace(static_cast<long long>(ids->GetComponent(p, 0)), p).first->second;
    }
  }
  else
  {
    vtkNew<vtkStaticPointLocator> locator;
    locator->SetDataSet(input);
    locator->BuildLocator();
    locator->MergePoints(tolerance * input->GetLength(), representative.data());
  }
  bool joined = false;
  for (vtkIdType p = 0; p < n; ++p)
  {
    // Each point onto its group's one representative, even where the merge map chains.
    vtkIdType r = representative[p];
    while (representative[r] != r)
    {
      r = representative[r];
    }
    representative[p] = r;
    joined = joined || r != p;
  }
  return joined ? representative : std::vector<vtkIdType>();
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkOpenMeshNormalsJoin::JoinedCopy(
  vtkPolyData* input, const std::vector<vtkIdType>& representative)
{
  vtkCellArray* inputPolys = input->GetPolys();
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(inputPolys->GetNumberOfCells(), inputPolys->GetNumberOfConnectivityIds());
  std::vector<vtkIdType> corners;
  auto iterator = vtk::TakeSmartPointer(inputPolys->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    corners.resize(size);
    for (vtkIdType k = 0; k < size; ++k)
    {
      corners[k] = representative[ids[k]];
    }
    polys->InsertNextCell(size, corners.data());
  }
  auto joined = vtkSmartPointer<vtkPolyData>::New();
  joined->ShallowCopy(input);
  joined->SetPolys(polys);
  return joined;
}

//------------------------------------------------------------------------------
void vtkOpenMeshNormalsJoin::GiveNormalsBack(vtkPolyData* input,
  const std::vector<vtkIdType>& representative, vtkPolyData* joined, vtkPolyData* output,
  const char* originalIdsName)
{
  output->ShallowCopy(joined);
  vtkDataArray* normals = joined->GetPointData()->GetNormals();
  if (!normals)
  {
    return;
  }
  vtkDataArray* original =
    originalIdsName ? joined->GetPointData()->GetArray(originalIdsName) : nullptr;
  auto joinedPointOf = [original](vtkIdType o)
  { return original ? static_cast<vtkIdType>(original->GetComponent(o, 0)) : o; };

  // The polygons again, each corner on its own input point (or a copy of it).
  const vtkIdType n = input->GetNumberOfPoints();
  NormalAssignment assignment(n);
  vtkCellArray* joinedPolys = joined->GetPolys();
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(joinedPolys->GetNumberOfCells(), joinedPolys->GetNumberOfConnectivityIds());
  auto inputCell = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  auto joinedCell = vtk::TakeSmartPointer(joinedPolys->NewIterator());
  std::vector<vtkIdType> in, out;
  inputCell->GoToFirstCell();
  for (joinedCell->GoToFirstCell(); !joinedCell->IsDoneWithTraversal(); joinedCell->GoToNextCell())
  {
    vtkIdType size, inSize = 0;
    const vtkIdType *ids, *inIds = nullptr;
    joinedCell->GetCurrentCell(size, ids);
    if (!inputCell->IsDoneWithTraversal()) // past the polygons: the strips' triangles
    {
      inputCell->GetCurrentCell(inSize, inIds);
      inputCell->GoToNextCell();
    }
    in.assign(inIds, inIds + inSize);
    const int order = CornerOrder(in, ids, size, representative, joinedPointOf);
    out.resize(size);
    for (vtkIdType k = 0; k < size; ++k)
    {
      const vtkIdType p =
        order == 0 ? joinedPointOf(ids[k]) : in[order > 0 || k == 0 ? k : size - k];
      out[k] = assignment.Assign(p, ids[k]);
    }
    polys->InsertNextCell(size, out.data());
  }
  output->SetPolys(polys);

  // The input's points and data, the copies, and each point's normal.
  const vtkIdType copies = static_cast<vtkIdType>(assignment.CopySource.size());
  vtkNew<vtkIdList> copied;
  copied->SetNumberOfIds(copies);
  std::copy(assignment.CopySource.begin(), assignment.CopySource.end(), copied->begin());
  vtkOpenMeshNormalsExecution::WritePointsWithCopies(input, copied, output);
  vtkNew<vtkFloatArray> pointNormals;
  pointNormals->SetName("Normals");
  pointNormals->SetNumberOfComponents(3);
  pointNormals->SetNumberOfTuples(n + copies);
  double normal[3];
  for (vtkIdType p = 0; p < n + copies; ++p)
  {
    // A point no polygon names keeps its representative's normal.
    const vtkIdType from = p < n
      ? (assignment.NormalOf[p] >= 0 ? assignment.NormalOf[p] : representative[p])
      : assignment.CopyNormal[p - n];
    normals->GetTuple(from, normal);
    pointNormals->SetTuple(p, normal);
  }
  output->GetPointData()->SetNormals(pointNormals);
  if (original)
  {
    vtkOpenMeshNormalsExecution::StoreOriginalPointIds(output, originalIdsName, n, copied);
  }
}
