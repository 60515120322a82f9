"""How far is a tessellated sphere from the exact one? Measure it.

Renders vtkSphereSource spheres of growing resolution into a float target
(vtkPhongFloatRenderPass), ray-casts the exact sphere with the
double-precision reference (vtkPhongReference) and prints OpenImageIO's error
statistics in 8-bit levels, for Gouraud (per vertex) and Phong interpolation.

    PYTHONPATH=<vtkphong>/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        measure_accuracy.py [--output-prefix sphere]
"""

import argparse

import vtkphong
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkRenderWindow, vtkRenderer

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--resolutions", type=int, nargs="+", default=[8, 16, 32, 64, 128])
parser.add_argument("--output-prefix", help="also write <prefix>-<resolution>-<mode>.exr")
args = parser.parse_args()

window = vtkRenderWindow()
window.SetOffScreenRendering(True)
window.SetMultiSamples(0)
window.SetSize(400, 400)
renderer = vtkRenderer()
window.AddRenderer(renderer)
renderer.AutomaticLightCreationOff()
light = vtkLight()
light.SetLightTypeToSceneLight()
light.SetPosition(1.0, 1.0, 2.0)
renderer.AddLight(light)
float_pass = vtkphong.vtkPhongFloatRenderPass()
renderer.SetPass(float_pass)

source = vtkSphereSource()
mapper = vtkphong.vtkPhongPolyDataMapper()
mapper.SetInputConnection(source.GetOutputPort())
material = vtkphong.vtkPhongProperty()
material.SetColor(0.8, 0.6, 0.4)
material.SetSpecularColor(1.0, 1.0, 1.0)
material.SetAmbient(0.1)
material.SetSpecular(0.5)
material.SetShininess(40.0)
actor = vtkActor()
actor.SetMapper(mapper)
actor.SetProperty(material)
renderer.AddActor(actor)
camera = renderer.GetActiveCamera()
camera.SetPosition(0.0, 0.0, 2.2)
renderer.ResetCameraClippingRange()

# The exact sphere vtkSphereSource approximates: centre 0, radius 0.5.
reference = vtkphong.vtkPhongReference()
reference.SetRenderer(renderer)
reference.SetActor(actor)
reference.SetSurfaceToSphere(0.0, 0.0, 0.0, 0.5)
exact = vtkImageData()
reference.RenderAnalytic(exact)

comparison = vtkphong.vtkPhongImageComparison()
comparison.SetReferenceImage(exact)
comparison.SetMaskErosion(1)  # silhouettes of a polygon and a circle differ

print("| resolution | interpolation | mean (levels) | p99 (levels) | max (levels) |")
print("|---|---|---|---|---|")
for resolution in args.resolutions:
    source.SetThetaResolution(resolution)
    source.SetPhiResolution(resolution)
    for mode in ("per-vertex Gouraud", "Phong"):
        if mode == "Phong":
            material.SetInterpolationToPhong()
        else:
            material.SetInterpolationToPerVertexGouraud()
        window.Render()
        image = vtkImageData()
        image.DeepCopy(float_pass.GetFloatImage())
        comparison.SetTestImage(image)
        comparison.Compare()
        print("| %d | %s | %.2f | %.2f | %.2f |" % (
            resolution, mode, 255 * comparison.GetMeanError(),
            255 * comparison.GetP99Error(), 255 * comparison.GetMaxError()))
        if args.output_prefix:
            name = "%s-%d-%s.exr" % (args.output_prefix, resolution, mode.split()[-1].lower())
            vtkphong.vtkPhongImageIO().WriteImage(image, name)
