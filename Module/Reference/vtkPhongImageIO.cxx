#include "vtkPhongImageIO.h"

#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include "vtkPhongImageBuffers.h"

#include <OpenImageIO/imagebufalgo.h>

vtkStandardNewMacro(vtkPhongImageIO);

//------------------------------------------------------------------------------
vtkPhongImageIO::vtkPhongImageIO() = default;

//------------------------------------------------------------------------------
vtkPhongImageIO::~vtkPhongImageIO() = default;

//------------------------------------------------------------------------------
void vtkPhongImageIO::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
int vtkPhongImageIO::WriteImage(vtkImageData* image, const char* fileName)
{
  if (!fileName || !*fileName)
  {
    vtkErrorMacro("WriteImage needs a file name.");
    return 0;
  }
  std::string why;
  vtkDataArray* scalars = vtkPhongImageBuffers::ScalarsOf(image, why);
  if (!scalars)
  {
    vtkErrorMacro("Cannot write " << fileName << ": " << why << ".");
    return 0;
  }
  OIIO::ImageBuf picture;
  if (scalars->GetDataType() == VTK_UNSIGNED_CHAR)
  {
    int dims[3];
    image->GetDimensions(dims);
    OIIO::ImageSpec spec(dims[0], dims[1], scalars->GetNumberOfComponents(), OIIO::TypeDesc::UINT8);
    picture.reset(spec, OIIO::InitializePixels::No);
    picture.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, scalars->GetVoidPointer(0));
  }
  else if (!vtkPhongImageBuffers::ToFloatBuffer(image, picture, why))
  {
    vtkErrorMacro("Cannot write " << fileName << ": " << why << ".");
    return 0;
  }
  OIIO::ImageBuf flipped = OIIO::ImageBufAlgo::flip(picture);
  // Keep float pictures float where the format can (EXR, TIFF); 8-bit formats convert.
  flipped.set_write_format(picture.spec().format);
  if (!flipped.write(fileName))
  {
    vtkErrorMacro("Cannot write " << fileName << ": " << flipped.geterror() << ".");
    return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkPhongImageIO::ReadImage(const char* fileName, vtkImageData* output)
{
  if (!fileName || !*fileName || !output)
  {
    vtkErrorMacro("ReadImage needs a file name and an output image.");
    return 0;
  }
  OIIO::ImageBuf file(fileName);
  if (!file.read(0, 0, true))
  {
    vtkErrorMacro("Cannot read " << fileName << ": " << file.geterror() << ".");
    return 0;
  }
  const OIIO::ImageSpec& spec = file.spec();
  if (spec.nchannels < 1 || spec.nchannels > 4 || spec.depth > 1)
  {
    vtkErrorMacro("Cannot read " << fileName << ": " << spec.nchannels << " channels, depth "
                                 << spec.depth << " (2D images of 1 to 4 channels supported).");
    return 0;
  }
  OIIO::ImageBuf flipped = OIIO::ImageBufAlgo::flip(file);
  if (spec.format == OIIO::TypeDesc::UINT8)
  {
    static const char* const names[] = { "Luminance", "LuminanceAlpha", "RGB", "RGBA" };
    vtkNew<vtkUnsignedCharArray> scalars;
    scalars->SetName(names[spec.nchannels - 1]);
    scalars->SetNumberOfComponents(spec.nchannels);
    scalars->SetNumberOfTuples(static_cast<vtkIdType>(spec.width) * spec.height);
    flipped.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, scalars->GetPointer(0));
    output->Initialize();
    output->SetDimensions(spec.width, spec.height, 1);
    output->GetPointData()->SetScalars(scalars);
  }
  else
  {
    vtkPhongImageBuffers::FromFloatBuffer(flipped, output);
  }
  return 1;
}
