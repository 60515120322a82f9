"""What the error budget buys: frame time against budget, stock and exact beside it.

One window (1280x1024), one sphere (vtkSphereSource RES x RES, default 128 and 256) under
3 directional lights of total intensity 1 (Blinn-Phong, shininess 40, the material of
TestPhongErrorBudget). The contenders take turns, batch after batch of finished frames;
each row prints median frame times, the ratio to stock and to exact vtkPhong, whether the
mapper went per vertex, and the bound it used (levels).

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a -s "-noreset" /usr/bin/python3 \\
        Testing/Benchmarks/vtkPhongErrorBudget.py [--resolutions 128 256] [--quick]
"""

import argparse
import math
import statistics
import time


def make_scene(resolution, size, use_phong, budget):
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkRenderWindow, vtkRenderer
    from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLPolyDataMapper
    import vtkphong

    sphere = vtkSphereSource()
    sphere.SetThetaResolution(resolution)
    sphere.SetPhiResolution(resolution)
    sphere.Update()
    mapper = vtkphong.vtkPhongPolyDataMapper() if use_phong else vtkOpenGLPolyDataMapper()
    mapper.SetInputData(sphere.GetOutput())
    if use_phong:
        mapper.SetErrorBudget(budget)
    material = vtkphong.vtkPhongProperty()
    material.SetColor(0.8, 0.6, 0.4)
    material.SetAmbient(0.1)
    material.SetDiffuse(0.7)
    material.SetSpecular(0.5)
    material.SetSpecularPower(40.0)
    material.SetShininess(40.0)
    material.SetLightingModel(vtkphong.vtkPhongProperty.BlinnPhong)
    material.SetInterpolationToPhong()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.SetProperty(material)
    renderer = vtkRenderer()
    renderer.AutomaticLightCreationOff()
    renderer.AddActor(actor)
    for i in range(3):
        angle = 2.399963 * i
        light = vtkLight()
        light.SetLightTypeToSceneLight()
        light.SetPosition(math.cos(angle) * (0.3 + 0.1 * i), math.sin(angle) * 0.8, 1.0)
        light.SetFocalPoint(0, 0, 0)
        light.SetIntensity(1.0 / 3.0)
        renderer.AddLight(light)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, 0, 2.2)
    camera.SetFocalPoint(0, 0, 0)
    camera.SetViewAngle(30)
    renderer.ResetCameraClippingRange()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    return window, mapper


def frame_ms(window, frames):
    times = []
    for _ in range(frames):
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append((time.perf_counter() - start) * 1000.0)
    return times


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--resolutions", type=int, nargs="+", default=[128, 256])
    parser.add_argument("--budgets", type=float, nargs="+", default=[1.0, 3.0, 8.0])
    parser.add_argument("--size", type=int, nargs=2, default=[1280, 1024])
    parser.add_argument("--quick", action="store_true", help="few frames (a smoke run)")
    args = parser.parse_args()
    batches, frames = (2, 2) if args.quick else (5, 6)
    print("| sphere | contender | frame ms | / stock | / exact | per vertex | bound (levels) |")
    print("|---|---|---|---|---|---|---|")
    for resolution in args.resolutions:
        contenders = [("stock", False, 0.0), ("exact", True, 0.0)]
        contenders += [("budget %g" % b, True, b) for b in args.budgets]
        scenes = [(name,) + make_scene(resolution, args.size, phong, budget)
                  for name, phong, budget in contenders]
        times = {name: [] for name, _, _ in scenes}
        for window in (s[1] for s in scenes):
            window.Render()  # compile, upload, analyse
        for _ in range(batches):
            for name, window, _ in scenes:
                times[name] += frame_ms(window, frames)
        median = {name: statistics.median(values) for name, values in times.items()}
        for name, _, mapper in scenes:
            phong = name != "stock"
            vertex = "PER_VERTEX" in mapper.GetLastShaderSignature() if phong else False
            bound = "%.2f" % mapper.GetErrorBound() if phong else ""
            print("| %d | %s | %.1f | %.2f | %.2f | %s | %s |" % (
                resolution, name, median[name], median[name] / median["stock"],
                median[name] / median["exact"], "yes" if vertex else "no", bound))


if __name__ == "__main__":
    main()
