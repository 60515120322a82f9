#include "vtkPhongImageComparison.h"

#include "vtkImageData.h"
#include "vtkObjectFactory.h"

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
}

//------------------------------------------------------------------------------
vtkPhongImageComparison::vtkPhongImageComparison() = default;

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
  std::string why;
  OIIO::ImageBuf& test = buffers.Test;
  OIIO::ImageBuf reference;
  if (!vtkPhongImageBuffers::ToFloatBuffer(this->TestImage, test, why))
  {
    vtkErrorMacro("Cannot compare: test image: " << why << ".");
    return false;
  }
  if (!vtkPhongImageBuffers::ToFloatBuffer(this->ReferenceImage, reference, why))
  {
    vtkErrorMacro("Cannot compare: reference image: " << why << ".");
    return false;
  }
  const int width = test.spec().width;
  const int height = test.spec().height;
  if (reference.spec().width != width || reference.spec().height != height)
  {
    vtkErrorMacro("Cannot compare a " << width << "x" << height << " test image with a "
                                      << reference.spec().width << "x" << reference.spec().height
                                      << " reference.");
    return false;
  }
  if (test.nchannels() < 3 || reference.nchannels() < 3)
  {
    vtkErrorMacro("Cannot compare: both images need RGB (3 or 4 components).");
    return false;
  }
  const size_t pixelCount = static_cast<size_t>(width) * height;
  buffers.PixelCount = pixelCount;

  // The pixels that count.
  std::vector<unsigned char>& compared = buffers.Compared;
  compared.assign(pixelCount, 1);
  auto restrictToAlpha = [&](const OIIO::ImageBuf& image)
  {
    if (image.nchannels() == 4)
    {
      const auto* pixels = static_cast<const float*>(image.localpixels());
      for (size_t i = 0; i < pixelCount; ++i)
      {
        compared[i] = compared[i] && pixels[4 * i + 3] > 0.0f;
      }
    }
  };
  if (this->UseCoverage)
  {
    restrictToAlpha(test);
    restrictToAlpha(reference);
  }
  if (this->MaskImage)
  {
    OIIO::ImageBuf mask;
    if (!vtkPhongImageBuffers::ToFloatBuffer(this->MaskImage, mask, why) ||
      mask.spec().width != width || mask.spec().height != height)
    {
      vtkErrorMacro("Cannot compare: the mask image "
        << (why.empty() ? "does not have the images' size" : why) << ".");
      return false;
    }
    const auto* pixels = static_cast<const float*>(mask.localpixels());
    const int channels = mask.nchannels();
    for (size_t i = 0; i < pixelCount; ++i)
    {
      compared[i] = compared[i] && pixels[channels * i] != 0.0f;
    }
  }
  Erode(compared, width, height, this->MaskErosion);

  // Non-finite values count as 0 in the statistics (they are counted apart).
  OIIO::ImageBuf testFinite, referenceFinite;
  int nonFinite = 0;
  OIIO::ImageBufAlgo::fixNonFinite(
    testFinite, test, OIIO::ImageBufAlgo::NONFINITE_BLACK, &nonFinite);
  int referenceNonFinite = 0;
  OIIO::ImageBufAlgo::fixNonFinite(
    referenceFinite, reference, OIIO::ImageBufAlgo::NONFINITE_BLACK, &referenceNonFinite);
  if (referenceNonFinite > 0)
  {
    vtkWarningMacro("The reference image has " << referenceNonFinite
                                               << " non-finite pixels; they count as black.");
  }

  // RGB only, uncompared pixels zeroed in both so they add no error.
  const int rgb[3] = { 0, 1, 2 };
  buffers.TestRGB = OIIO::ImageBufAlgo::channels(testFinite, 3, rgb);
  buffers.ReferenceRGB = OIIO::ImageBufAlgo::channels(referenceFinite, 3, rgb);
  auto* a = static_cast<float*>(buffers.TestRGB.localpixels());
  auto* b = static_cast<float*>(buffers.ReferenceRGB.localpixels());
  for (size_t i = 0; i < pixelCount; ++i)
  {
    if (!compared[i])
    {
      std::fill(a + 3 * i, a + 3 * i + 3, 0.0f);
      std::fill(b + 3 * i, b + 3 * i + 3, 0.0f);
    }
  }
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

  // Non-finite pixels of the test image, anywhere and in any channel.
  {
    const auto* pixels = static_cast<const float*>(buffers.Test.localpixels());
    const int channels = buffers.Test.nchannels();
    for (size_t i = 0; i < pixelCount; ++i)
    {
      bool nan = false, inf = false;
      for (int c = 0; c < channels; ++c)
      {
        nan = nan || std::isnan(pixels[channels * i + c]);
        inf = inf || std::isinf(pixels[channels * i + c]);
      }
      this->NumberOfNaNPixels += nan ? 1 : 0;
      this->NumberOfInfPixels += (inf && !nan) ? 1 : 0;
    }
  }

  // OpenImageIO takes float thresholds; larger ones mean "never fails".
  const double floatMax = std::numeric_limits<float>::max();
  const auto failThreshold = static_cast<float>(std::min(this->Threshold, floatMax));
  const auto failRelative = static_cast<float>(std::min(this->RelativeThreshold, floatMax));
  // results.error only says that some pixel failed (OpenImageIO 2.4): not an error here.
  const OIIO::ImageBufAlgo::CompareResults results = OIIO::ImageBufAlgo::compare(buffers.TestRGB,
    buffers.ReferenceRGB, failThreshold, failThreshold, failRelative, failRelative);
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
    const OIIO::ImageBuf magnitude = OIIO::ImageBufAlgo::max(
      OIIO::ImageBufAlgo::abs(buffers.ReferenceRGB),
      static_cast<float>(std::min(
        std::max(this->RelativeErrorFloor, double(std::numeric_limits<float>::min())), floatMax)));
    const OIIO::ImageBuf relative = OIIO::ImageBufAlgo::div(difference, magnitude);
    const OIIO::ImageBufAlgo::PixelStats stats = OIIO::ImageBufAlgo::computePixelStats(relative);
    double channelMean = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      channelMean += stats.avg[c] / 3.0;
      this->MaxRelativeError = std::max(this->MaxRelativeError, static_cast<double>(stats.max[c]));
    }
    this->MeanRelativeError = channelMean * share;
    this->P99RelativeError = Percentile99(OIIO::ImageBufAlgo::maxchan(relative), compared);
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
  const bool raw = name.size() >= 4 &&
    (name.compare(name.size() - 4, 4, ".exr") == 0 ||
      name.compare(name.size() - 4, 4, ".EXR") == 0);
  const float threshold =
    static_cast<float>(std::min(this->Threshold, double(std::numeric_limits<float>::max())));
  OIIO::ImageBuf map = OIIO::ImageBufAlgo::absdiff(buffers.TestRGB, buffers.ReferenceRGB);
  auto* pixels = static_cast<float*>(map.localpixels());
  const auto* original = static_cast<const float*>(buffers.Test.localpixels());
  const int channels = buffers.Test.nchannels();
  for (size_t i = 0; i < buffers.PixelCount; ++i)
  {
    bool finite = true;
    for (int c = 0; c < channels; ++c)
    {
      finite = finite && std::isfinite(original[channels * i + c]);
    }
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
    else if (!buffers.Compared[i])
    {
      pixel[0] = 0.0f, pixel[1] = 0.0f, pixel[2] = 0.25f;
    }
    else
    {
      const float error = std::max({ pixel[0], pixel[1], pixel[2] });
      const float level =
        threshold > 0.0f ? std::min(0.5f * error / threshold, 1.0f) : (error > 0.0f ? 1.0f : 0.0f);
      pixel[0] = pixel[1] = pixel[2] = level;
    }
  }
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
