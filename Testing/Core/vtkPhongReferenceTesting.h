// Helpers for the tests that measure the GPU against the double-precision reference: float
// renders through vtkPhongFloatRenderPass, the G-buffer views, and comparisons with
// vtkPhongImageComparison. Header-only, like vtkPhongTestUtilities.h.

#ifndef vtkPhongReferenceTesting_h
#define vtkPhongReferenceTesting_h

#include "vtkPhongTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkPhongFloatRenderPass.h"
#include "vtkPhongImageComparison.h"
#include "vtkPhongReference.h"

#include <algorithm>
#include <string>

namespace vtkPhongTest
{

// Renders the scene through a float pass and returns a copy of the float picture.
inline vtkSmartPointer<vtkImageData> RenderFloat(Scene& scene, vtkPhongFloatRenderPass* pass)
{
  scene.Renderer->SetPass(pass);
  scene.Window->Render();
  auto copy = vtkSmartPointer<vtkImageData>::New();
  copy->DeepCopy(pass->GetFloatImage());
  return copy;
}

// The G-buffer of the scene (every vtkPhong mapper's PositionVC and NormalVC views), shaded
// by the reference; the mappers are left on the Final view.
inline vtkSmartPointer<vtkImageData> ShadeGBuffer(
  Scene& scene, vtkPhongFloatRenderPass* pass, vtkPhongReference* reference)
{
  SetDebugView(scene, vtkPhongPolyDataMapper::PositionVC);
  auto positions = RenderFloat(scene, pass);
  SetDebugView(scene, vtkPhongPolyDataMapper::NormalVC);
  auto normals = RenderFloat(scene, pass);
  SetDebugView(scene, vtkPhongPolyDataMapper::Final);
  auto shaded = vtkSmartPointer<vtkImageData>::New();
  if (!reference->ShadeGBuffer(positions, normals, shaded))
  {
    return nullptr;
  }
  return shaded;
}

// The largest magnitude of an image's RGB values.
inline double LargestValue(vtkImageData* image)
{
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  double largest = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    const double* range = scalars->GetRange(c);
    largest = std::max({ largest, std::abs(range[0]), std::abs(range[1]) });
  }
  return largest;
}

// How far a float render lies from the reference.
struct Measurement
{
  vtkIdType ComparedPixels = 0;
  vtkIdType NaNPixels = 0;
  vtkIdType InfPixels = 0;
  double MaxAbsolute = 0.0;
  double MaxRelative = 0.0;
  double P99Relative = 0.0;
  double MeanRelative = 0.0;
  double Largest = 0.0; // the reference's largest value
  bool Valid = false;
  vtkSmartPointer<vtkPhongImageComparison> Comparison; // for an error map on demand
};

// Relative errors divide by max(|reference|, 1e-4 * the reference's largest value), so dark
// pixels of a bright picture count by their absolute error.
inline Measurement MeasureAgainst(vtkImageData* test, vtkImageData* reference, int erosion)
{
  Measurement result;
  if (!test || !reference)
  {
    return result;
  }
  result.Largest = LargestValue(reference);
  auto comparison = vtkSmartPointer<vtkPhongImageComparison>::New();
  result.Comparison = comparison;
  comparison->SetTestImage(test);
  comparison->SetReferenceImage(reference);
  comparison->SetMaskErosion(erosion);
  comparison->SetRelativeErrorFloor(std::max(1.0e-4 * result.Largest, 1.0e-300));
  comparison->SetThreshold(VTK_DOUBLE_MAX); // only NaN and Inf fail here; callers judge errors
  comparison->Compare();
  result.ComparedPixels = comparison->GetNumberOfComparedPixels();
  result.NaNPixels = comparison->GetNumberOfNaNPixels();
  result.InfPixels = comparison->GetNumberOfInfPixels();
  result.MaxAbsolute = comparison->GetMaxError();
  result.MaxRelative = comparison->GetMaxRelativeError();
  result.P99Relative = comparison->GetP99RelativeError();
  result.MeanRelative = comparison->GetMeanRelativeError();
  result.Valid = result.ComparedPixels > 0;
  return result;
}

} // namespace vtkPhongTest

#endif
