// The torus the error-budget tests light: TestPhongGouraudBound's bounds and
// TestPhongErrorBudget's scene matrix.

#ifndef vtkPhongTestTorus_h
#define vtkPhongTestTorus_h

#include "vtkNew.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSmartPointer.h"

namespace vtkPhongTest
{
// A torus around z (ring and tube radii, `around` x `across` rows) with smooth point normals
// (vtkPolyDataNormals, no splitting).
inline vtkSmartPointer<vtkPolyData> MakeTorus(
  double ringRadius, double tubeRadius, int around, int across)
{
  vtkNew<vtkParametricTorus> torus;
  torus->SetRingRadius(ringRadius);
  torus->SetCrossSectionRadius(tubeRadius);
  vtkNew<vtkParametricFunctionSource> source;
  source->SetParametricFunction(torus);
  source->SetUResolution(around);
  source->SetVResolution(across);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(source->GetOutputPort());
  normals->SplittingOff();
  normals->Update();
  return normals->GetOutput();
}
} // namespace vtkPhongTest

#endif
