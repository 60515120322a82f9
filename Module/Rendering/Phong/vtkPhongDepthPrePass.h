/**
 * @file   vtkPhongDepthPrePass.h
 * @brief  when vtkPhongPolyDataMapper's automatic depth pre-pass pays (private)
 *
 * The pre-pass draws the geometry a second time (depth only) so that the lit draw shades
 * each pixel once. It saves the lighting of every hidden layer; on llvmpipe its
 * colour-masked draw costs nearly a lit one, so it pays only with hidden layers to save.
 * The break-even was measured on llvmpipe (docs/results/performance.md, "Depth
 * complexity").
 */

#ifndef vtkPhongDepthPrePass_h
#define vtkPhongDepthPrePass_h

class vtkPolyData;
class vtkRenderer;

/**
 * Whether the automatic mode uses the pre-pass for this input under the renderer's lights
 * (culledLights of them left out by light culling).
 */
bool vtkPhongDepthPrePassPays(vtkRenderer* ren, vtkPolyData* input, int culledLights);

#endif
// VTK-HeaderTest-Exclude: vtkPhongDepthPrePass.h
