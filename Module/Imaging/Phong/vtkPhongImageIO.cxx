#include "vtkPhongImageIO.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include "vtkPhongImageBuffers.h"

#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

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
  // ImageInput rather than ImageBuf: ImageBuf goes through OpenImageIO's shared image
  // cache, which serves a file rewritten within the same second from memory.
  auto input = OIIO::ImageInput::open(fileName);
  if (!input)
  {
    vtkErrorMacro("Cannot read " << fileName << ": " << OIIO::geterror() << ".");
    return 0;
  }
  const OIIO::ImageSpec spec = input->spec();
  if (spec.nchannels < 1 || spec.nchannels > 4 || spec.depth > 1)
  {
    vtkErrorMacro("Cannot read " << fileName << ": " << spec.nchannels << " channels, depth "
                                 << spec.depth << " (2D images of 1 to 4 channels supported).");
    return 0;
  }
  const bool bytes = spec.format == OIIO::TypeDesc::UINT8;
  static const char* const names[] = { "Luminance", "LuminanceAlpha", "RGB", "RGBA" };
  vtkSmartPointer<vtkDataArray> scalars;
  if (bytes)
  {
    scalars = vtkSmartPointer<vtkUnsignedCharArray>::New();
  }
  else
  {
    scalars = vtkSmartPointer<vtkFloatArray>::New();
  }
  scalars->SetName(names[spec.nchannels - 1]);
  scalars->SetNumberOfComponents(spec.nchannels);
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(spec.width) * spec.height);
  // The file's first row is the picture's top; VTK's is the bottom: read the rows in
  // reverse with a negative stride.
  const OIIO::TypeDesc type = bytes ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
  const OIIO::stride_t pixelBytes = static_cast<OIIO::stride_t>(type.size()) * spec.nchannels;
  const OIIO::stride_t rowBytes = pixelBytes * spec.width;
  auto* last = static_cast<char*>(scalars->GetVoidPointer(0)) + rowBytes * (spec.height - 1);
  if (!input->read_image(0, 0, 0, spec.nchannels, type, last, pixelBytes, -rowBytes))
  {
    vtkErrorMacro("Cannot read " << fileName << ": " << input->geterror() << ".");
    return 0;
  }
  input->close();
  output->Initialize();
  output->SetDimensions(spec.width, spec.height, 1);
  output->GetPointData()->SetScalars(scalars);
  return 1;
}
