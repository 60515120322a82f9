//============================================================================
// vtkPhongFloatRenderPass: shows the float picture in the window. The window
// clamps to [0, 1] anyway; clamping here keeps Inf from turning into an
// implementation-defined value, and NaN or Inf pixels are painted magenta so
// they cannot pass unseen.
//============================================================================
//VTK::System::Dec
//VTK::Output::Dec
in vec2 texCoord;
uniform sampler2D floatImage;

void main()
{
  vec4 pixel = texture(floatImage, texCoord);
  bool finite = !(any(isnan(pixel)) || any(isinf(pixel)));
  gl_FragData[0] = finite ? clamp(pixel, 0.0, 1.0) : vec4(1.0, 0.0, 1.0, 1.0);
}
