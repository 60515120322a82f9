/**
 * @class   vtkPhongImageComparison
 * @brief   compares a rendered image with a reference, numerically, with OpenImageIO
 *
 * vtkPhongImageComparison measures how far a test image (typically a float GPU render from
 * vtkPhongFloatRenderPass) lies from a reference image (typically vtkPhongReference's
 * double-precision picture) over the RGB channels, with OpenImageIO's image algorithms:
 *
 * - absolute error: mean, RMS, maximum (and where), 99th percentile, PSNR (peak 1.0);
 * - relative error |test - reference| / max(|reference|, RelativeErrorFloor): mean, maximum,
 *   99th percentile, for pictures whose values are far from [0, 1];
 * - the number of NaN and of infinite pixels of the test image (any channel, anywhere);
 * - the number of failed pixels: those with a channel whose absolute error exceeds Threshold
 *   and, when RelativeThreshold > 0, whose error relative to the mean magnitude of the two
 *   values also exceeds RelativeThreshold (OpenImageIO's compare rule).
 *
 * Values are compared in 32-bit float (OpenImageIO's arithmetic): differences below about
 * 1e-7 of the values are not resolved. 8-bit images count as value / 255. Errors in 8-bit
 * levels are the float errors times 255.
 *
 * Which pixels count: with UseCoverage on, only pixels both images cover (alpha > 0 where an
 * image has 4 components), further limited by an optional mask image (first component
 * non-zero) and shrunk by MaskErosion pixels, which drops the silhouette pixels where a
 * tessellated surface and its analytic reference legitimately differ.
 *
 * Compare() fails when the test image has a NaN or infinite pixel, when more than
 * MaximumFailedPixels pixels fail, or when no pixel is compared. On failure, if
 * ErrorMapFileName is set, it writes an error map there: an .exr file holds the raw
 * per-channel absolute error; any other format (.png) a picture of it, black for no error,
 * mid grey at Threshold, white at twice Threshold and above, magenta for non-finite test
 * pixels and dark blue where nothing was compared.
 *
 * @sa vtkPhongReference vtkPhongFloatRenderPass vtkPhongImageIO
 */

#ifndef vtkPhongImageComparison_h
#define vtkPhongImageComparison_h

#include "vtkImagingPhongModule.h" // for export macro
#include "vtkObject.h"

class vtkImageData;

class VTKIMAGINGPHONG_EXPORT vtkPhongImageComparison : public vtkObject
{
public:
  static vtkPhongImageComparison* New();
  vtkTypeMacro(vtkPhongImageComparison, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The images: 2D, equal size, 3 or 4 components (any scalar type; 8-bit as value / 255).
   * The optional mask: same size, pixels whose first component is 0 are not compared.
   */
  virtual void SetTestImage(vtkImageData* image);
  vtkGetObjectMacro(TestImage, vtkImageData);
  virtual void SetReferenceImage(vtkImageData* image);
  vtkGetObjectMacro(ReferenceImage, vtkImageData);
  virtual void SetMaskImage(vtkImageData* image);
  vtkGetObjectMacro(MaskImage, vtkImageData);
  ///@}

  ///@{
  /**
   * Compare only pixels both images cover (alpha > 0). Default on.
   */
  vtkSetMacro(UseCoverage, bool);
  vtkGetMacro(UseCoverage, bool);
  vtkBooleanMacro(UseCoverage, bool);
  ///@}

  ///@{
  /**
   * Pixels within this distance (in pixels, square neighbourhood) of a pixel that is not
   * compared are not compared either. Default 0, range [0, 16].
   */
  vtkSetClampMacro(MaskErosion, int, 0, 16);
  vtkGetMacro(MaskErosion, int);
  ///@}

  ///@{
  /**
   * A channel fails when its absolute error exceeds Threshold (default 1/255, one 8-bit
   * level; range [0, VTK_DOUBLE_MAX]) and, if RelativeThreshold > 0 (default 0, range
   * [0, VTK_DOUBLE_MAX]), its error relative to the mean magnitude of the two values exceeds
   * RelativeThreshold too. NaN is refused with an error (a NaN threshold would pass every
   * pixel).
   */
  virtual void SetThreshold(double threshold);
  vtkGetMacro(Threshold, double);
  virtual void SetRelativeThreshold(double threshold);
  vtkGetMacro(RelativeThreshold, double);
  ///@}

  ///@{
  /**
   * The smallest reference magnitude relative errors divide by. Default 1e-6, range
   * [VTK_DOUBLE_MIN, VTK_DOUBLE_MAX]; NaN is refused with an error.
   */
  virtual void SetRelativeErrorFloor(double floor);
  vtkGetMacro(RelativeErrorFloor, double);
  ///@}

  ///@{
  /**
   * How many pixels may fail before the comparison does. Default 0, range [0, VTK_ID_MAX].
   */
  vtkSetClampMacro(MaximumFailedPixels, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MaximumFailedPixels, vtkIdType);
  ///@}

  ///@{
  /**
   * Where Compare() writes the error map when it fails; empty (the default): nowhere.
   */
  vtkSetStringMacro(ErrorMapFileName);
  vtkGetStringMacro(ErrorMapFileName);
  ///@}

  /**
   * Compare the images. Returns 1 when they agree (see the class description), 0 when they
   * do not or cannot be compared (with an error then). The results below describe the last
   * call.
   */
  int Compare();

  /**
   * Write the error map of the current images and settings (see the class description) to a
   * file, whether or not they agree: for callers that judge the result themselves. Returns 1
   * on success, 0 with an error.
   */
  int WriteErrorMap(const char* fileName);

  ///@{
  /**
   * Results of the last Compare(), over the compared pixels and the RGB channels.
   */
  vtkGetMacro(NumberOfComparedPixels, vtkIdType);
  vtkGetMacro(NumberOfFailedPixels, vtkIdType);
  vtkGetMacro(NumberOfNaNPixels, vtkIdType);
  vtkGetMacro(NumberOfInfPixels, vtkIdType);
  vtkGetMacro(MeanError, double);
  vtkGetMacro(RMSError, double);
  vtkGetMacro(MaxError, double);
  vtkGetMacro(P99Error, double);
  vtkGetMacro(PSNR, double);
  vtkGetMacro(MeanRelativeError, double);
  vtkGetMacro(MaxRelativeError, double);
  vtkGetMacro(P99RelativeError, double);
  vtkGetVector2Macro(MaxErrorPixel, int);
  vtkGetMacro(ErrorMapWritten, bool);
  ///@}

protected:
  vtkPhongImageComparison();
  ~vtkPhongImageComparison() override;

  void ResetResults();

  // The images as OpenImageIO buffers and the pixels that count (defined in the .cxx file).
  struct Buffers;
  bool Prepare(Buffers& buffers);

  vtkImageData* TestImage = nullptr;
  vtkImageData* ReferenceImage = nullptr;
  vtkImageData* MaskImage = nullptr;
  bool UseCoverage = true;
  int MaskErosion = 0;
  double Threshold = 1.0 / 255.0;
  double RelativeThreshold = 0.0;
  double RelativeErrorFloor = 1.0e-6;
  vtkIdType MaximumFailedPixels = 0;
  char* ErrorMapFileName = nullptr;

  vtkIdType NumberOfComparedPixels = 0;
  vtkIdType NumberOfFailedPixels = 0;
  vtkIdType NumberOfNaNPixels = 0;
  vtkIdType NumberOfInfPixels = 0;
  double MeanError = 0.0;
  double RMSError = 0.0;
  double MaxError = 0.0;
  double P99Error = 0.0;
  double PSNR = 0.0;
  double MeanRelativeError = 0.0;
  double MaxRelativeError = 0.0;
  double P99RelativeError = 0.0;
  int MaxErrorPixel[2] = { -1, -1 };
  bool ErrorMapWritten = false;

private:
  vtkPhongImageComparison(const vtkPhongImageComparison&) = delete;
  void operator=(const vtkPhongImageComparison&) = delete;
};

#endif
