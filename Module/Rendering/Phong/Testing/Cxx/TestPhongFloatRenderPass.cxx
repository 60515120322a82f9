// Float read-back: vtkPhongFloatRenderPass keeps what the shaders write. An emissive sphere
// has values above 1; a strip drawn by the stock mapper writes NaN, +Inf and 2.0 in three
// bands (a shader replacement divides by a zero uniform). The float image must hold them all,
// OpenImageIO's counts must find exactly the NaN and Inf pixels, and the window copy (the
// baseline) must show values above 1 clamped and the non-finite bands in magenta. The
// G-buffer views write view-coordinate positions and normals with the face side in alpha, the
// depth array marks coverage, the image follows the window's size, and a pass without a
// delegate reports an error instead of crashing.

#include "vtkPhongReferenceTesting.h"

#include "vtkOpenGLPolyDataMapper.h"
#include "vtkShaderProperty.h"
#include "vtkUniforms.h"

namespace
{
constexpr int Width = 200;
constexpr int Height = 150;

const float* FloatPixel(vtkImageData* image, int x, int y)
{
  return static_cast<float*>(image->GetScalarPointer(x, y, 0));
}

float DepthAt(vtkImageData* image, int x, int y)
{
  int dims[3];
  image->GetDimensions(dims);
  auto* depth = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("Depth"));
  return depth ? depth->GetValue(y * dims[0] + x) : -1.0f;
}
}

int TestPhongFloatRenderPass(int argc, char* argv[])
{
  vtkPhongTest::Checks checks;
  vtkPhongTest::Scene scene(Width, Height);

  // An emissive, shiny sphere: well above 1 in the middle.
  vtkNew<vtkPhongProperty> glowing;
  glowing->SetColor(0.9, 0.6, 0.3);
  glowing->SetEmission(0.8, 0.6, 0.4);
  glowing->SetSpecular(0.8);
  glowing->SetShininess(20.0);
  vtkActor* sphere = vtkPhongTest::AddActor(scene, vtkPhongTest::MakeSphere(64, 0.45));
  sphere->SetProperty(glowing);
  sphere->SetPosition(0.0, 0.2, 0.0);

  // The special values, from the stock mapper: NaN (0/0), +Inf (1/0) and 2.0 by window column.
  vtkNew<vtkPlaneSource> strip;
  strip->SetOrigin(-2.0, -0.75, 0.0);
  strip->SetPoint1(2.0, -0.75, 0.0);
  strip->SetPoint2(-2.0, -0.45, 0.0);
  vtkNew<vtkOpenGLPolyDataMapper> stockMapper;
  stockMapper->SetInputConnection(strip->GetOutputPort());
  vtkNew<vtkActor> special;
  special->SetMapper(stockMapper);
  vtkShaderProperty* shaders = special->GetShaderProperty();
  // VTK declares the custom uniform testZero itself.
  shaders->AddFragmentShaderReplacement("//VTK::Light::Impl", true,
    "//VTK::Light::Impl\n"
    "  float third = gl_FragCoord.x < 66.0 ? 0.0 : (gl_FragCoord.x < 133.0 ? 1.0 : 2.0);\n"
    "  vec3 specialValue = third == 0.0 ? vec3(testZero / testZero)\n"
    "    : (third == 1.0 ? vec3(1.0 / testZero) : vec3(2.0));\n"
    "  gl_FragData[0] = vec4(specialValue, 1.0);\n",
    false);
  shaders->GetFragmentCustomUniforms()->SetUniformf("testZero", 0.0f);
  scene.Renderer->AddActor(special);
  scene.LookFromZ(3.0);

  vtkNew<vtkPhongFloatRenderPass> pass;
  auto image = vtkPhongTest::RenderFloat(scene, pass);
  int dims[3];
  image->GetDimensions(dims);
  checks.Expect(dims[0] == Width && dims[1] == Height, "the float image has the window's size");
  checks.Expect(image->GetScalarType() == VTK_FLOAT && image->GetNumberOfScalarComponents() == 4,
    "the float image holds 4 float components");

  // Values above 1 survive.
  const float* centre = FloatPixel(image, Width / 2, Height / 2 + 20);
  checks.Expect(
    centre[0] > 1.2f, "the emissive sphere reads above 1 (" + std::to_string(centre[0]) + ")");

  // Count the special bands directly, then through OpenImageIO.
  vtkIdType nan = 0, inf = 0, two = 0;
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      const float* pixel = FloatPixel(image, x, y);
      nan += std::isnan(pixel[0]) ? 1 : 0;
      inf += std::isinf(pixel[0]) && pixel[0] > 0.0f ? 1 : 0;
      two += pixel[0] == 2.0f ? 1 : 0;
    }
  }
  const vtkIdType rows = two / (Width - 133);
  checks.Expect(rows > 5 && two == rows * (Width - 133), "the 2.0 band is whole rows");
  checks.Expect(nan == rows * 66, "NaN fills its band (" + std::to_string(nan) + " pixels)");
  checks.Expect(inf == rows * 67, "+Inf fills its band (" + std::to_string(inf) + " pixels)");

  vtkNew<vtkImageData> black;
  black->DeepCopy(image);
  black->GetPointData()->GetScalars()->Fill(0.0);
  vtkNew<vtkPhongImageComparison> comparison;
  comparison->SetTestImage(image);
  comparison->SetReferenceImage(black);
  comparison->UseCoverageOff(); // every pixel, the background included
  comparison->SetThreshold(VTK_DOUBLE_MAX);
  checks.Expect(comparison->Compare() == 0, "a comparison fails on NaN and Inf");
  checks.Expect(comparison->GetNumberOfNaNPixels() == nan, "OpenImageIO counts the NaN pixels");
  checks.Expect(comparison->GetNumberOfInfPixels() == inf, "OpenImageIO counts the Inf pixels");

  // The window copy: clamped, non-finite in magenta.
  auto shown = vtkPhongTest::Snapshot(scene.Window);
  int bandRow = -1;
  for (int y = 0; y < Height && bandRow < 0; ++y)
  {
    if (FloatPixel(image, Width - 10, y)[0] == 2.0f)
    {
      bandRow = y;
    }
  }
  auto expectShown = [&](int x, int y, int r, int g, int b, const std::string& what)
  {
    const unsigned char* pixel = vtkPhongTest::PixelAt(shown, x, y);
    checks.Expect(pixel[0] == r && pixel[1] == g && pixel[2] == b,
      "window shows " + what + " (got " + std::to_string(pixel[0]) + "," +
        std::to_string(pixel[1]) + "," + std::to_string(pixel[2]) + ")");
  };
  expectShown(20, bandRow + 1, 255, 0, 255, "NaN as magenta");
  expectShown(100, bandRow + 1, 255, 0, 255, "Inf as magenta");
  expectShown(180, bandRow + 1, 255, 255, 255, "2.0 clamped to white");
  expectShown(Width / 2, Height / 2 + 20, 255,
    static_cast<int>(std::lround(std::min(centre[1], 1.0f) * 255.0f)),
    static_cast<int>(std::lround(std::min(centre[2], 1.0f) * 255.0f)), "the sphere clamped");

  // Coverage in the depth array.
  checks.Expect(DepthAt(image, 2, Height - 3) == 1.0f, "the background has depth 1");
  checks.Expect(DepthAt(image, Width / 2, Height / 2 + 20) < 1.0f, "the sphere has depth < 1");

  const int result = vtkPhongTest::Finish(argc, argv, scene.Window, checks.Passed);

  // G-buffer views of a plane facing the camera, and of its back face (two-sided lighting).
  {
    vtkPhongTest::Scene view(64, 64);
    vtkActor* plane = vtkPhongTest::AddActor(view, vtkPhongTest::MakePlane(1.0, 4));
    vtkCamera* camera = view.Renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetParallelScale(0.5);
    view.LookFromZ(5.0);
    vtkNew<vtkPhongFloatRenderPass> gbufferPass;
    vtkPhongTest::SetDebugView(view, vtkPhongPolyDataMapper::PositionVC);
    auto positions = vtkPhongTest::RenderFloat(view, gbufferPass);
    vtkPhongTest::SetDebugView(view, vtkPhongPolyDataMapper::NormalVC);
    auto normals = vtkPhongTest::RenderFloat(view, gbufferPass);
    const float* p = FloatPixel(positions, 32, 32);
    const float* n = FloatPixel(normals, 32, 32);
    checks.Near(p[0], 1.0 / 128.0, 1e-6, "PositionVC x at the pixel centre");
    checks.Near(p[2], -5.0, 1e-5, "PositionVC z is minus the camera distance");
    checks.Near(p[3], 1.0, 0.0, "PositionVC alpha is 1 on a front face");
    checks.Near(n[2], 1.0, 1e-6, "NormalVC faces the viewer");
    checks.Near(n[3], 1.0, 0.0, "NormalVC alpha is 1 on a front face");
    plane->RotateY(180.0);
    auto backNormals = vtkPhongTest::RenderFloat(view, gbufferPass);
    const float* back = FloatPixel(backNormals, 32, 32);
    checks.Near(back[2], 1.0, 1e-6, "a back face's normal turns to the viewer (two-sided)");
    checks.Near(back[3], 0.5, 0.0, "NormalVC alpha is 0.5 on a back face");

    // The image follows the window's size.
    view.Window->SetSize(40, 30);
    auto resized = vtkPhongTest::RenderFloat(view, gbufferPass);
    resized->GetDimensions(dims);
    checks.Expect(dims[0] == 40 && dims[1] == 30, "the float image follows a resize");

    // A pass without a delegate reports an error and renders nothing.
    vtkPhongTest::ErrorCollector errors;
    errors.Observe(gbufferPass);
    gbufferPass->SetDelegatePass(nullptr);
    view.Window->Render();
    checks.Expect(errors.Contains("No delegate pass"), "a pass without delegate reports it");
    checks.Expect(vtkPhongTest::NoGLErrors(view.Window, "the G-buffer renders"), "no GL errors");
  }

  return (result == EXIT_SUCCESS && checks.Passed) ? EXIT_SUCCESS : EXIT_FAILURE;
}
