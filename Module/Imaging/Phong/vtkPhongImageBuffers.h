// Conversions between vtkImageData and OpenImageIO's ImageBuf, shared by vtkPhongImageIO and
// vtkPhongImageComparison. Private to the module: OpenImageIO types stay out of the public,
// wrapped headers.
//
// Orientation: a vtkImageData's first row is the bottom of the picture; an image file's first
// row is the top. The buffers made here keep VTK's row order (y = VTK row), so pixel
// coordinates agree with VTK's; only files are flipped, on the way out (vtkPhongImageIO
// flips on the way in as it reads).

#ifndef vtkPhongImageBuffers_h
#define vtkPhongImageBuffers_h

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <OpenImageIO/imagebuf.h>

#include <string>

namespace vtkPhongImageBuffers
{

// The scalars of a 2D image with 1 to 4 components, or nullptr.
inline vtkDataArray* ScalarsOf(vtkImageData* image, std::string& why)
{
  if (!image)
  {
    why = "no image";
    return nullptr;
  }
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (!scalars)
  {
    why = "the image has no scalars";
    return nullptr;
  }
  if (dims[2] != 1 || dims[0] < 1 || dims[1] < 1)
  {
    why = "the image is not a single 2D slice";
    return nullptr;
  }
  const int components = scalars->GetNumberOfComponents();
  if (components < 1 || components > 4)
  {
    why = "the image has " + std::to_string(components) + " components (1 to 4 supported)";
    return nullptr;
  }
  return scalars;
}

// A float buffer of the image's values; 8-bit values are normalized to [0, 1] (value / 255)
// as OpenImageIO reads 8-bit files, other types are taken as they are.
inline bool ToFloatBuffer(vtkImageData* image, OIIO::ImageBuf& buffer, std::string& why)
{
  vtkDataArray* scalars = ScalarsOf(image, why);
  if (!scalars)
  {
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  const int components = scalars->GetNumberOfComponents();
  OIIO::ImageSpec spec(dims[0], dims[1], components, OIIO::TypeDesc::FLOAT);
  buffer.reset(spec, OIIO::InitializePixels::No);
  auto* pixels = static_cast<float*>(buffer.localpixels());
  const vtkIdType count = scalars->GetNumberOfValues();
  auto convert = [&](const auto* values, double scale)
  {
    for (vtkIdType i = 0; i < count; ++i)
    {
      pixels[i] = static_cast<float>(values[i] * scale);
    }
  };
  switch (scalars->GetDataType())
  {
    case VTK_UNSIGNED_CHAR:
      convert(static_cast<const unsigned char*>(scalars->GetVoidPointer(0)), 1.0 / 255.0);
      break;
    case VTK_FLOAT:
      convert(static_cast<const float*>(scalars->GetVoidPointer(0)), 1.0);
      break;
    case VTK_DOUBLE:
      convert(static_cast<const double*>(scalars->GetVoidPointer(0)), 1.0);
      break;
    default:
      for (vtkIdType i = 0; i < count; ++i)
      {
        pixels[i] = static_cast<float>(scalars->GetComponent(i / components, i % components));
      }
  }
  return true;
}

} // namespace vtkPhongImageBuffers

#endif
