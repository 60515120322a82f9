/**
 * @class   vtkPhongImageIO
 * @brief   reads and writes images with OpenImageIO: EXR for float pictures, PNG for 8-bit
 *
 * The float pictures of vtkPhongFloatRenderPass and vtkPhongReference keep values above 1,
 * NaN and Inf; PNG cannot hold them. vtkPhongImageIO writes any 2D vtkImageData of 1 to 4
 * components to any format OpenImageIO knows, chosen by the file name's extension: float and
 * double images to OpenEXR as 32-bit float (nothing lost), 8-bit images to PNG as they are; a
 * float image written to an 8-bit format is clamped to [0, 1] and rounded, an 8-bit image
 * written to EXR becomes value / 255. Reading gives float scalars for float files and
 * unsigned char scalars for 8-bit files. Rows are flipped so that a file's top row is the
 * picture's top, as VTK's own readers and writers do.
 *
 * @sa vtkPhongImageComparison vtkPhongFloatRenderPass
 */

#ifndef vtkPhongImageIO_h
#define vtkPhongImageIO_h

#include "vtkImagingPhongModule.h" // for export macro
#include "vtkObject.h"

class vtkImageData;

class VTKIMAGINGPHONG_EXPORT vtkPhongImageIO : public vtkObject
{
public:
  static vtkPhongImageIO* New();
  vtkTypeMacro(vtkPhongImageIO, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Write the image; the format follows the extension (.exr, .png, .tif, ...). Returns 1 on
   * success, 0 with an error naming the file and OpenImageIO's reason.
   */
  int WriteImage(vtkImageData* image, const char* fileName);

  /**
   * Read a file into the output image (float or unsigned char scalars named "RGBA", "RGB",
   * ...). Returns 1 on success, 0 with an error.
   */
  int ReadImage(const char* fileName, vtkImageData* output);

protected:
  vtkPhongImageIO();
  ~vtkPhongImageIO() override;

private:
  vtkPhongImageIO(const vtkPhongImageIO&) = delete;
  void operator=(const vtkPhongImageIO&) = delete;
};

#endif
