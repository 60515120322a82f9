#include "vtkPhongImageComparison.h"

#include "vtkImageData.h"
#include "vtkObjectFactory.h"

#include "vtkPhongClampedSetter.h"
#include "vtkPhongImageBuffers.h"

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkPhongImageComparison);
vtkCxxSetObjectMacro(vtkPhongImageComparison, TestImage, vtkImageData);
vtkCxxSetObjectMacro(vtkPhongImageComparison, ReferenceImage, vtkImageData);
vtkCxxSetObjectMacro(vtkPhongImageComparison, MaskImage, vtkImageData);

namespace
{
// Square erosion of a 0/1 mask by radius pixels, separably (rows, then columns).
void Erode(std::vector<unsigned char>& mask, int width, int height, int radius)
{
  if (radius <= 0)
  {
    return;
  }
  std::vector<unsigned char> rows(mask.size());
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      unsigned char keep = 1;
      for (int dx = -radius; dx <= radius && keep; ++dx)
      {
        const int nx = x + dx;
        keep = (nx >= 0 && nx < width) ? mask[static_cast<size_t>(y) * width + nx] : 0;
      }
      rows[static_cast<size_t>(y) * width + x] = keep;
    }
  }
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      unsigned char keep = 1;
      for (int dy = -radius; dy <= radius && keep; ++dy)
      {
        const int ny = y + dy;
        keep = (ny >= 0 && ny < height) ? rows[static_cast<size_t>(ny) * width + x] : 0;
      }
      mask[static_cast<size_t>(y) * width + x] = keep;
    }
  }
}

// The 99th percentile of the values at the compared pixels of a one-channel buffer.
double Percentile99(const OIIO::ImageBuf& values, const std::vector<unsigned char>& compared)
{
  const auto* data = static_cast<const float*>(values.localpixels());
  std::vector<float> selected;
  for (size_t i = 0; i < compared.size(); ++i)
  {
    if (compared[i])
    {
      selected.push_back(data[i]);
    }
  }
  if (selected.empty())
  {
    return 0.0;
  }
  const size_t rank =
    static_cast<size_t>(std::ceil(0.99 * static_cast<double>(selected.size()))) - 1;
  std::nth_element(selected.begin(), selected.begin() + rank, selected.end());
  return selected[rank];
}

// The steps of Prepare, Compare and WriteErrorMap. Those that can fail report with the
// comparison's own vtkErrorMacro text, self being the comparison.

// Both images as float buffers, of one size and with RGB; false, reported, otherwise.
bool ToComparableBuffers(vtkObject* self, vtkImageData* testImage, vtkImageData* referenceImage,
  OIIO::ImageBuf& test, OIIO::ImageBuf& reference)
{
  std::string why;
  if (!vtkPhongImageBuffers::ToFloatBuffer(testImage, test, why))
  {
    vtkErrorWithObjectMacro(self, "Cannot compare: test image: " << why << ".");
    return false;
  }
  if (!vtkPhongImageBuffers::ToFloatBuffer(referenceImage, reference, why))
  {
    vtkErrorWithObjectMacro(self, "Cannot compare: reference image: " << why << ".");
    return false;
  }
  const int width = test.spec().width;
  const int height = test.spec().height;
  if (reference.spec().width != width || reference.spec().height != height)
  {
    vtkErrorWithObjectMacro(self,
      "Cannot compare a " << width << "x" << height << " test image with a "
                          << reference.spec().width << "x" << reference.spec().height
                          << " reference.");
    return false;
  }
  if (test.nchannels() < 3 || reference.nchannels() < 3)
  {
    vtkErrorWithObjectMacro(self, "Cannot compare: both images need RGB (3 or 4 components).");
    return false;
  }
  return true;
}

// With coverage on, a pixel counts only where an image with alpha covers it.
void RestrictToAlpha(const OIIO::ImageBuf& image, std::vector<unsigned char>& compared)
{
  if (image.nchannels() == 4)
  {
    const auto* pixels = static_cast<const float*>(image.localpixels());
    for (size_t i = 0; i < compared.size(); ++i)
    {
      compared[i] = compared[i] && pixels[4 * i + 3] > 0.0f;
    }
  }
}

// A pixel counts only where the mask's first channel is not 0; false, reported, for a mask
// that is not an image of the images' size.
bool RestrictToMask(vtkObject* self, vtkImageData* maskImage, int width, int height,
  std::vector<unsigned char>& compared)
{
  std::string why;
  OIIO::ImageBuf mask;
  if (!vtkPhongImageBuffers::ToFloatBuffer(maskImage, mask, why) || mask.spec().width != width ||
    mask.spec().height != height)
  {
    vtkErrorWithObjectMacro(self,
      "Cannot compare: the mask image " << (why.empty() ? "does not have the images' size" : why)
                                        << ".");
    return false;
  }
  const auto* pixels = static_cast<const float*>(mask.localpixels());
  const int channels = mask.nchannels();
  for (size_t i = 0; i < compared.size(); ++i)
  {
    compared[i] = compared[i] && pixels[channels * i] != 0.0f;
  }
  return true;
}

// The RGB channels, non-finite values as 0: they count as 0 in the statistics (and are
// counted apart). nonFinite is the number of pixels changed.
OIIO::ImageBuf FiniteRGB(const OIIO::ImageBuf& image, int& nonFinite)
{
  OIIO::ImageBuf finite;
  OIIO::ImageBufAlgo::fixNonFinite(finite, image, OIIO::ImageBufAlgo::NONFINITE_BLACK, &nonFinite);
  const int rgb[3] = { 0, 1, 2 };
  return OIIO::ImageBufAlgo::channels(finite, 3, rgb);
}

// Uncompared pixels are zeroed in both images so that they add no error.
void ZeroUncompared(OIIO::ImageBuf& rgb, const std::vector<unsigned char>& compared)
{
  auto* pixels = static_cast<float*>(rgb.localpixels());
  for (size_t i = 0; i < compared.size(); ++i)
  {
    if (!compared[i])
    {
      std::fill(pixels + 3 * i, pixels + 3 * i + 3, 0.0f);
    }
  }
}

// Non-finite pixels of the test image, anywhere and in any channel: a pixel with a NaN
// counts as NaN, one with only infinities as Inf.
void CountNonFinitePixels(
  const OIIO::ImageBuf& test, size_t pixelCount, vtkIdType& nanPixels, vtkIdType& infPixels)
{
  const auto* pixels = static_cast<const float*>(test.localpixels());
  const int channels = test.nchannels();
  for (size_t i = 0; i < pixelCount; ++i)
  {
    bool nan = false, inf = false;
    for (int c = 0; c < channels; ++c)
    {
      nan = nan || std::isnan(pixels[channels * i + c]);
      inf = inf || std::isinf(pixels[channels * i + c]);
    }
    nanPixels += nan ? 1 : 0;
    infPixels += (inf && !nan) ? 1 : 0;
  }
}

OIIO::ImageBufAlgo::CompareResults CompareRGB(const OIIO::ImageBuf& test,
  const OIIO::ImageBuf& reference, double threshold, double relativeThreshold)
{
  // OpenImageIO takes float thresholds; larger ones mean "never fails".
  const double floatMax = std::numeric_limits<float>::max();
  const auto failThreshold = static_cast<float>(std::min(threshold, floatMax));
  const auto failRelative = static_cast<float>(std::min(relativeThreshold, floatMax));
  // results.error only says that some pixel failed (OpenImageIO 2.4): not an error here.
  return OIIO::ImageBufAlgo::compare(
    test, reference, failThreshold, failThreshold, failRelative, failRelative);
}

// The error relative to |reference| (no less than floor, so that black pixels do not
// divide by 0): channelMean gets its mean over the channels and every pixel (OpenImageIO's
// average), maximum its largest value and p99 its 99th percentile at the compared pixels.
void RelativeErrors(const OIIO::ImageBuf& difference, const OIIO::ImageBuf& reference, double floor,
  const std::vector<unsigned char>& compared, double& channelMean, double& maximum, double& p99)
{
  const double floatMax = std::numeric_limits<float>::max();
  const OIIO::ImageBuf magnitude = OIIO::ImageBufAlgo::max(OIIO::ImageBufAlgo::abs(reference),
    static_cast<float>(
      std::min(std::max(floor, double(std::numeric_limits<float>::min())), floatMax)));
  const OIIO::ImageBuf relative = OIIO::ImageBufAlgo::div(difference, magnitude);
  const OIIO::ImageBufAlgo::PixelStats stats = OIIO::ImageBufAlgo::computePixelStats(relative);
  for (int c = 0; c < 3; ++c)
  {
    channelMean += stats.avg[c] / 3.0;
    maximum = std::max(maximum, static_cast<double>(stats.max[c]));
  }
  p99 = Percentile99(OIIO::ImageBufAlgo::maxchan(relative), compared);
}

bool IsFinitePixel(const float* pixel, int channels)
{
  bool finite = true;
  for (int c = 0; c < channels; ++c)
  {
    finite = finite && std::isfinite(pixel[c]);
  }
  return finite;
}

// Grey levels that reach mid-grey at the threshold and white at twice it; without a
// threshold any error is white.
float ErrorLevel(const float* error3, float threshold)
{
  const float error = std::max({ error3[0], error3[1], error3[2] });
  return threshold > 0.0f ? std::min(0.5f * error / threshold, 1.0f) : (error > 0.0f ? 1.0f : 0.0f);
}

// An .exr map keeps the absolute errors as they are (and a non-finite test pixel as it is);
// any other is a picture: magenta where the test pixel is not finite, dark blue where nothing
// is compared, else the error's grey level.
void PaintErrorMap(OIIO::ImageBuf& map, const OIIO::ImageBuf& test,
  const std::vector<unsigned char>& compared, size_t pixelCount, bool raw, float threshold)
{
  auto* pixels = static_cast<float*>(map.localpixels());
  const auto* original = static_cast<const float*>(test.localpixels());
  const int channels = test.nchannels();
  for (size_t i = 0; i < pixelCount; ++i)
  {
    const bool finite = IsFinitePixel(original + channels * i, channels);
    float* pixel = pixels + 3 * i;
    if (raw)
    {
      if (!finite)
      {
        std::copy(original + channels * i, original + channels * i + 3, pixel);
      }
    }
    else if (!finite)
    {
      pixel[0] = 1.0f, pixel[1] = 0.0f, pixel[2] = 1.0f;
    }
    else if (!compared[i])
    {
      pixel[0] = 0.0f, pixel[1] = 0.0f, pixel[2] = 0.25f;
    }
    else
    {
      pixel[0] = pixel[1] = pixel[2] = ErrorLevel(pixel, threshold);
    }
  }
}

bool IsEXRName(const std::string& name)
{
  return name.size() >= 4 &&
    (name.compare(name.size() - 4, 4, ".exr") == 0 ||
      name.compare(name.size() - 4, 4, ".EXR") == 0);
}
}

//------------------------------------------------------------------------------
vtkPhongImageComparison::vtkPhongImageComparison() = default;

//------------------------------------------------------------------------------
void vtkPhongImageComparison::SetThreshold(double threshold)
{
  vtkPhongSetClamped(this, "Threshold", this->Threshold, threshold, 0.0, VTK_DOUBLE_MAX);
}

//------------------------------------------------------------------------------
void vtkPhongImageComparison::SetRelativeThreshold(double threshold)
{
  vtkPhongSetClamped(
    this, "RelativeThreshold", this->RelativeThreshold, threshold, 0.0, VTK_DOUBLE_MAX);
}

//------------------------------------------------------------------------------
void vtkPhongImageComparison::SetRelativeErrorFloor(double floor)
{
  vtkPhongSetClamped(
    this, "RelativeErrorFloor", this->RelativeErrorFloor, floor, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX);
}

//------------------------------------------------------------------------------
vtkPhongImageComparison::~vtkPhongImageComparison()
{
  this->SetTestImage(nullptr);
  this->SetReferenceImage(nullptr);
  this->SetMaskImage(nullptr);
  this->SetErrorMapFileName(nullptr);
}

//------------------------------------------------------------------------------
void vtkPhongImageComparison::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TestImage: " << this->TestImage << "\n";
  os << indent << "ReferenceImage: " << this->ReferenceImage << "\n";
  os << indent << "MaskImage: " << this->MaskImage << "\n";
  os << indent << "UseCoverage: " << (this->UseCoverage ? "On" : "Off") << "\n";
  os << indent << "MaskErosion: " << this->MaskErosion << "\n";
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "RelativeThreshold: " << this->RelativeThreshold << "\n";
  os << indent << "RelativeErrorFloor: " << this->RelativeErrorFloor << "\n";
  os << indent << "MaximumFailedPixels: " << this->MaximumFailedPixels << "\n";
  os << indent
     << "ErrorMapFileName: " << (this->ErrorMapFileName ? this->ErrorMapFileName : "(none)")
     << "\n";
  os << indent << "NumberOfComparedPixels: " << this->NumberOfComparedPixels << "\n";
  os << indent << "NumberOfFailedPixels: " << this->NumberOfFailedPixels << "\n";
  os << indent << "NumberOfNaNPixels: " << this->NumberOfNaNPixels << "\n";
  os << indent << "NumberOfInfPixels: " << this->NumberOfInfPixels << "\n";
  os << indent << "MeanError: " << this->MeanError << "\n";
  os << indent << "RMSError: " << this->RMSError << "\n";
  os << indent << "MaxError: " << this->MaxError << "\n";
  os << indent << "P99Error: " << this->P99Error << "\n";
  os << indent << "PSNR: " << this->PSNR << "\n";
  os << indent << "MeanRelativeError: " << this->MeanRelativeError << "\n";
  os << indent << "MaxRelativeError: " << this->MaxRelativeError << "\n";
  os << indent << "P99RelativeError: " << this->P99RelativeError << "\n";
  os << indent << "MaxErrorPixel: " << this->MaxErrorPixel[0] << ", " << this->MaxErrorPixel[1]
     << "\n";
  os << indent << "ErrorMapWritten: " << (this->ErrorMapWritten ? "true" : "false") << "\n";
}

//------------------------------------------------------------------------------
void vtkPhongImageComparison::ResetResults()
{
  this->NumberOfComparedPixels = 0;
  this->NumberOfFailedPixels = 0;
  this->NumberOfNaNPixels = 0;
  this->NumberOfInfPixels = 0;
  this->MeanError = this->RMSError = this->MaxError = this->P99Error = this->PSNR = 0.0;
  this->MeanRelativeError = this->MaxRelativeError = this->P99RelativeError = 0.0;
  this->MaxErrorPixel[0] = this->MaxErrorPixel[1] = -1;
  this->ErrorMapWritten = false;
}

//------------------------------------------------------------------------------
struct vtkPhongImageComparison::Buffers
{
  OIIO::ImageBuf Test;         // as given, all channels (for the non-finite pixels)
  OIIO::ImageBuf TestRGB;      // finite, uncompared pixels zeroed
  OIIO::ImageBuf ReferenceRGB; // finite, uncompared pixels zeroed
  std::vector<unsigned char> Compared;
  size_t PixelCount = 0;
};

//------------------------------------------------------------------------------
bool vtkPhongImageComparison::Prepare(Buffers& buffers)
{
  OIIO::ImageBuf reference;
  if (!ToComparableBuffers(this, this->TestImage, this->ReferenceImage, buffers.Test, reference))
  {
    return false;
  }
  const int width = buffers.Test.spec().width;
  const int height = buffers.Test.spec().height;
  buffers.PixelCount = static_cast<size_t>(width) * height;

  // The pixels that count.
  std::vector<unsigned char>& compared = buffers.Compared;
  compared.assign(buffers.PixelCount, 1);
  if (this->UseCoverage)
  {
    RestrictToAlpha(buffers.Test, compared);
    RestrictToAlpha(reference, compared);
  }
  if (this->MaskImage && !RestrictToMask(this, this->MaskImage, width, height, compared))
  {
    return false;
  }
  Erode(compared, width, height, this->MaskErosion);

  int testNonFinite = 0, referenceNonFinite = 0;
  buffers.TestRGB = FiniteRGB(buffers.Test, testNonFinite);
  buffers.ReferenceRGB = FiniteRGB(reference, referenceNonFinite);
  if (referenceNonFinite > 0)
  {
    vtkWarningMacro("The reference image has " << referenceNonFinite
                                               << " non-finite pixels; they count as black.");
  }
  ZeroUncompared(buffers.TestRGB, compared);
  ZeroUncompared(buffers.ReferenceRGB, compared);
  return true;
}

//------------------------------------------------------------------------------
int vtkPhongImageComparison::Compare()
{
  this->ResetResults();
  Buffers buffers;
  if (!this->Prepare(buffers))
  {
    return 0;
  }
  const size_t pixelCount = buffers.PixelCount;
  const std::vector<unsigned char>& compared = buffers.Compared;
  this->NumberOfComparedPixels = std::count(compared.begin(), compared.end(), 1);
  CountNonFinitePixels(buffers.Test, pixelCount, this->NumberOfNaNPixels, this->NumberOfInfPixels);

  const OIIO::ImageBufAlgo::CompareResults results =
    CompareRGB(buffers.TestRGB, buffers.ReferenceRGB, this->Threshold, this->RelativeThreshold);
  if (this->NumberOfComparedPixels > 0)
  {
    // OpenImageIO averages over every pixel; only the compared ones had any error.
    const double share = static_cast<double>(pixelCount) / this->NumberOfComparedPixels;
    this->MeanError = results.meanerror * share;
    this->RMSError = std::sqrt(results.rms_error * results.rms_error * share);
    this->PSNR = this->RMSError > 0.0 ? 20.0 * std::log10(1.0 / this->RMSError)
                                      : std::numeric_limits<double>::infinity();
    this->MaxError = results.maxerror;
    this->MaxErrorPixel[0] = results.maxx;
    this->MaxErrorPixel[1] = results.maxy;
    this->NumberOfFailedPixels = static_cast<vtkIdType>(results.nfail);

    const OIIO::ImageBuf difference =
      OIIO::ImageBufAlgo::absdiff(buffers.TestRGB, buffers.ReferenceRGB);
    this->P99Error = Percentile99(OIIO::ImageBufAlgo::maxchan(difference), compared);
    double channelMean = 0.0;
    RelativeErrors(difference, buffers.ReferenceRGB, this->RelativeErrorFloor, compared,
      channelMean, this->MaxRelativeError, this->P99RelativeError);
    this->MeanRelativeError = channelMean * share;
  }
  else
  {
    vtkWarningMacro("No pixel was compared (no coverage in common, or the mask is empty).");
  }

  const bool passed = this->NumberOfComparedPixels > 0 && this->NumberOfNaNPixels == 0 &&
    this->NumberOfInfPixels == 0 && this->NumberOfFailedPixels <= this->MaximumFailedPixels;
  if (!passed && this->ErrorMapFileName && *this->ErrorMapFileName)
  {
    this->ErrorMapWritten = this->WriteErrorMap(this->ErrorMapFileName) == 1;
  }
  return passed ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkPhongImageComparison::WriteErrorMap(const char* fileName)
{
  if (!fileName || !*fileName)
  {
    vtkErrorMacro("WriteErrorMap needs a file name.");
    return 0;
  }
  Buffers buffers;
  if (!this->Prepare(buffers))
  {
    return 0;
  }
  const std::string name = fileName;
  const bool raw = IsEXRName(name);
  const float threshold =
    static_cast<float>(std::min(this->Threshold, double(std::numeric_limits<float>::max())));
  OIIO::ImageBuf map = OIIO::ImageBufAlgo::absdiff(buffers.TestRGB, buffers.ReferenceRGB);
  PaintErrorMap(map, buffers.Test, buffers.Compared, buffers.PixelCount, raw, threshold);
  OIIO::ImageBuf flipped = OIIO::ImageBufAlgo::flip(map);
  if (!raw)
  {
    flipped.set_write_format(OIIO::TypeDesc::UINT8);
  }
  if (!flipped.write(name))
  {
    vtkErrorMacro("Cannot write the error map " << name << ": " << flipped.geterror());
    return 0;
  }
  return 1;
}
