// vtkPhongImageComparison and vtkPhongImageIO on images whose answers are known: the error
// statistics of a known difference, NaN and Inf counts, coverage, masks and erosion, the error
// map written only on failure, 8-bit against float, and lossless EXR / PNG round trips
// (NaN, Inf and values above 1 included), with their error paths.

#include "vtkPhongImageComparison.h"
#include "vtkPhongTestUtilities.h"

#include "vtkPhongImageIO.h"

#include <limits>

namespace
{
constexpr int W = 20;
constexpr int H = 10;

vtkSmartPointer<vtkImageData> MakeImage(int type, int components, double value, double alpha = 1.0)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(W, H, 1);
  image->AllocateScalars(type, components);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < components; ++c)
    {
      scalars->SetComponent(i, c, c == 3 ? alpha : value);
    }
  }
  return image;
}

void SetPixel(vtkImageData* image, int x, int y, double r, double g, double b)
{
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const vtkIdType i = static_cast<vtkIdType>(y) * W + x;
  scalars->SetComponent(i, 0, r);
  scalars->SetComponent(i, 1, g);
  scalars->SetComponent(i, 2, b);
}

bool SameValues(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* x = a->GetPointData()->GetScalars();
  vtkDataArray* y = b->GetPointData()->GetScalars();
  if (x->GetNumberOfValues() != y->GetNumberOfValues())
  {
    return false;
  }
  for (vtkIdType i = 0; i < x->GetNumberOfValues(); ++i)
  {
    const double u = x->GetVariantValue(i).ToDouble();
    const double v = y->GetVariantValue(i).ToDouble();
    if (!(u == v || (std::isnan(u) && std::isnan(v))))
    {
      return false;
    }
  }
  return true;
}
}

int TestPhongImageComparison(int argc, char* argv[])
{
  vtkPhongTest::Checks checks;
  vtkNew<vtkTesting> testing;
  testing->AddArguments(argc, argv);
  const std::string temporary = testing->GetTempDirectory();

  { // A known difference: one pixel off by 0.1 in red, one by 0.05 in all channels.
    auto reference = MakeImage(VTK_FLOAT, 4, 0.5);
    auto test = MakeImage(VTK_FLOAT, 4, 0.5);
    SetPixel(test, 3, 7, 0.6, 0.5, 0.5);
    SetPixel(test, 15, 2, 0.55, 0.55, 0.55);
    vtkNew<vtkPhongImageComparison> comparison;
    comparison->SetTestImage(test);
    comparison->SetReferenceImage(reference);
    comparison->SetThreshold(0.07);
    { // NaN would let every pixel pass (no error exceeds NaN): it is refused.
      vtkPhongTest::ErrorCollector messages;
      messages.Observe(comparison);
      comparison->SetThreshold(std::numeric_limits<double>::quiet_NaN());
      comparison->SetRelativeErrorFloor(std::numeric_limits<double>::quiet_NaN());
      checks.Expect(comparison->GetThreshold() == 0.07 &&
          comparison->GetRelativeErrorFloor() == 1.0e-6 && messages.Contains("NaN refused"),
        "NaN thresholds are refused with an error");
    }
    checks.Expect(comparison->Compare() == 0, "one pixel over the threshold fails");
    const double values = 3.0 * W * H;
    checks.Near(comparison->GetMeanError(), (0.1 + 3 * 0.05) / values, 1e-8, "mean error");
    checks.Near(comparison->GetRMSError(), std::sqrt((0.01 + 3 * 0.0025) / values), 1e-8, "RMS");
    checks.Near(comparison->GetPSNR(),
      20.0 * std::log10(1.0 / std::sqrt((0.01 + 3 * 0.0025) / values)), 1e-4, "PSNR");
    checks.Near(comparison->GetMaxError(), 0.1, 1e-7, "max error");
    checks.Expect(comparison->GetMaxErrorPixel()[0] == 3 && comparison->GetMaxErrorPixel()[1] == 7,
      "the largest error's pixel, in VTK's orientation");
    checks.Expect(comparison->GetNumberOfFailedPixels() == 1, "one failed pixel");
    checks.Near(comparison->GetMaxRelativeError(), 0.2, 1e-6, "max relative error");
    checks.Near(comparison->GetP99Error(), 0.0, 0.0, "99th percentile: 198 of 200 pixels exact");
    comparison->SetMaximumFailedPixels(1);
    checks.Expect(comparison->Compare() == 1, "within the failed-pixel budget it passes");
    comparison->SetRelativeThreshold(0.5);
    comparison->SetMaximumFailedPixels(0);
    checks.Expect(
      comparison->Compare() == 1, "a relative threshold forgives small relative errors");

    // Coverage: the differing pixels transparent in the test are not compared.
    vtkDataArray* scalars = test->GetPointData()->GetScalars();
    scalars->SetComponent(7 * W + 3, 3, 0.0);
    scalars->SetComponent(2 * W + 15, 3, 0.0);
    comparison->SetRelativeThreshold(0.0);
    checks.Expect(comparison->Compare() == 1 && comparison->GetMaxError() == 0.0 &&
        comparison->GetNumberOfComparedPixels() == W * H - 2,
      "uncovered pixels are left out");
    comparison->UseCoverageOff();
    checks.Expect(comparison->Compare() == 0, "without coverage they count");
    comparison->UseCoverageOn();
    // Erosion by 1 drops the neighbours of the two holes and the image border.
    comparison->SetMaskErosion(1);
    comparison->Compare();
    checks.Expect(comparison->GetNumberOfComparedPixels() == (W - 2) * (H - 2) - 2 * 9,
      "erosion by one pixel (" + std::to_string(comparison->GetNumberOfComparedPixels()) + ")");
    comparison->SetMaskErosion(0);
    // A mask image.
    auto mask = MakeImage(VTK_UNSIGNED_CHAR, 1, 0.0);
    mask->GetPointData()->GetScalars()->SetComponent(0, 0, 1.0);
    comparison->SetMaskImage(mask);
    comparison->Compare();
    checks.Expect(comparison->GetNumberOfComparedPixels() == 1, "a mask limits the comparison");
  }

  { // NaN and Inf: counted, always a failure, and the error map is written only then.
    auto reference = MakeImage(VTK_FLOAT, 3, 0.25);
    auto test = MakeImage(VTK_FLOAT, 3, 0.25);
    const std::string errorMap = temporary + "/TestPhongImageComparison.error.png";
    const std::string rawErrorMap = temporary + "/TestPhongImageComparison.error.exr";
    vtksys::SystemTools::RemoveFile(errorMap);
    vtksys::SystemTools::RemoveFile(rawErrorMap);
    vtkNew<vtkPhongImageComparison> comparison;
    comparison->SetTestImage(test);
    comparison->SetReferenceImage(reference);
    comparison->SetErrorMapFileName(errorMap.c_str());
    checks.Expect(comparison->Compare() == 1 && !comparison->GetErrorMapWritten() &&
        !vtksys::SystemTools::FileExists(errorMap),
      "equal images pass and write no error map");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    SetPixel(test, 1, 1, nan, 0.25, 0.25);
    SetPixel(test, 2, 1, nan, inf, 0.25);
    SetPixel(test, 3, 1, 0.25, 0.25, inf);
    SetPixel(test, 4, 1, -inf, 0.25, 0.25);
    SetPixel(test, 5, 1, 0.25, 0.25, inf);
    checks.Expect(comparison->Compare() == 0, "NaN and Inf fail");
    checks.Expect(comparison->GetNumberOfNaNPixels() == 2, "2 NaN pixels");
    checks.Expect(comparison->GetNumberOfInfPixels() == 3, "3 Inf pixels");
    checks.Expect(comparison->GetErrorMapWritten() && vtksys::SystemTools::FileExists(errorMap),
      "the error map is written on failure");
    vtkNew<vtkPhongImageIO> io;
    vtkNew<vtkImageData> map;
    checks.Expect(io->ReadImage(errorMap.c_str(), map) == 1, "the error map reads back");
    const auto* magenta = static_cast<unsigned char*>(map->GetScalarPointer(1, 1, 0));
    checks.Expect(magenta[0] == 255 && magenta[1] == 0 && magenta[2] == 255,
      "non-finite pixels are magenta in the error map");
    comparison->SetErrorMapFileName(rawErrorMap.c_str());
    comparison->Compare();
    vtkNew<vtkImageData> raw;
    checks.Expect(io->ReadImage(rawErrorMap.c_str(), raw) == 1 &&
        raw->GetScalarType() == VTK_FLOAT &&
        std::isnan(raw->GetScalarComponentAsDouble(1, 1, 0, 0)),
      "the raw error map is float and keeps NaN");
  }

  { // 8-bit against float: value / 255.
    auto bytes = MakeImage(VTK_UNSIGNED_CHAR, 3, 128.0);
    auto floats = MakeImage(VTK_FLOAT, 3, 128.0 / 255.0);
    vtkNew<vtkPhongImageComparison> comparison;
    comparison->SetTestImage(bytes);
    comparison->SetReferenceImage(floats);
    comparison->SetThreshold(0.0);
    checks.Expect(comparison->Compare() == 1 && comparison->GetMaxError() < 1e-7,
      "8-bit 128 equals float 128/255");
  }

  { // Round trips: EXR keeps float exactly (above 1, negative, NaN, Inf), PNG keeps 8-bit.
    vtkNew<vtkPhongImageIO> io;
    auto floats = MakeImage(VTK_FLOAT, 4, 0.125, 1.0);
    SetPixel(floats, 0, 0, 3.5, -2.0, 1.0e6);
    SetPixel(floats, 19, 9, std::numeric_limits<double>::quiet_NaN(),
      std::numeric_limits<double>::infinity(), 1.0e-30);
    const std::string exr = temporary + "/TestPhongImageComparison.roundtrip.exr";
    vtkNew<vtkImageData> back;
    checks.Expect(io->WriteImage(floats, exr.c_str()) == 1 && io->ReadImage(exr.c_str(), back) == 1,
      "EXR written and read");
    checks.Expect(back->GetScalarType() == VTK_FLOAT && SameValues(floats, back),
      "EXR keeps every float value, in VTK's row order");

    auto bytes = MakeImage(VTK_UNSIGNED_CHAR, 3, 7.0);
    SetPixel(bytes, 0, 9, 255, 0, 128);
    const std::string png = temporary + "/TestPhongImageComparison.roundtrip.png";
    checks.Expect(io->WriteImage(bytes, png.c_str()) == 1 && io->ReadImage(png.c_str(), back) == 1,
      "PNG written and read");
    checks.Expect(back->GetScalarType() == VTK_UNSIGNED_CHAR && SameValues(bytes, back),
      "PNG keeps 8-bit values");
    // A float picture written to PNG is clamped and rounded.
    const std::string clamped = temporary + "/TestPhongImageComparison.clamped.png";
    io->WriteImage(floats, clamped.c_str());
    io->ReadImage(clamped.c_str(), back);
    const auto* corner = static_cast<unsigned char*>(back->GetScalarPointer(0, 0, 0));
    checks.Expect(
      corner[0] == 255 && corner[1] == 0 && corner[2] == 255, "float to PNG clamps to [0, 1]");

    // Errors: a file that is not there, a directory that is not there, an empty image.
    vtkPhongTest::ErrorCollector errors;
    errors.Observe(io);
    checks.Expect(io->ReadImage((temporary + "/no-such-image.exr").c_str(), back) == 0 &&
        errors.Contains("Cannot read"),
      "reading a missing file: an error");
    checks.Expect(
      io->WriteImage(floats, (temporary + "/no-such-directory/image.exr").c_str()) == 0 &&
        errors.Contains("Cannot write"),
      "writing where one cannot: an error");
    vtkNew<vtkImageData> empty;
    checks.Expect(io->WriteImage(empty, exr.c_str()) == 0 && errors.Contains("no scalars"),
      "an empty image: an error");
  }

  { // Comparisons that cannot be made: an error each.
    vtkPhongTest::ErrorCollector errors;
    vtkNew<vtkPhongImageComparison> comparison;
    errors.Observe(comparison);
    checks.Expect(comparison->Compare() == 0 && errors.Contains("test image"), "no images");
    auto small = MakeImage(VTK_FLOAT, 3, 0.0);
    vtkNew<vtkImageData> other;
    other->SetDimensions(3, 3, 1);
    other->AllocateScalars(VTK_FLOAT, 3);
    comparison->SetTestImage(small);
    comparison->SetReferenceImage(other);
    checks.Expect(
      comparison->Compare() == 0 && errors.Contains("Cannot compare a"), "different sizes");
    auto gray = MakeImage(VTK_FLOAT, 1, 0.0);
    comparison->SetReferenceImage(gray);
    checks.Expect(comparison->Compare() == 0 && errors.Contains("RGB"), "one component");
  }

  return checks.Passed ? EXIT_SUCCESS : EXIT_FAILURE;
}
