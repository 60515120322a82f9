"""What directional lights cost per fragment, and what is left of it.

One window, one 130 000-triangle sphere (vtkSphereSource 256 x 256) at 1280x1024 under N
directional lights (default 8 and 32; Phong lobe, shininess 30). The contenders take turns,
batch after batch of finished frames, and each row prints medians:

- floor: the unlit sphere with its back faces culled (what any frame that culls them costs);
- stock: vtkOpenGLPolyDataMapper;
- vtkPhong: its defaults (interpolated dot products, docs/shaders.md);
- no dots: vtkPhong with InterpolatedDotProductsOff(), the dot products per fragment;
- free pow: vtkPhong's own generated shader with the lobe's pow(cos, 30) replaced by five
  multiplications, given back as the actor's shader code (not the model, which takes any
  exponent without a recompile): a bound on what any cheaper pow could buy.

"lighting" is a contender's frame time above the floor. The last two contenders cull the
back faces through the property, as vtkPhong does for a closed surface, so every vtkPhong
contender shades the same fragments.

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Testing/Benchmarks/vtkPhongDirectionalCost.py [--lights 8 32] [--quick]
"""

import argparse
import math
import re
import statistics
import time

POW = "pow(clamp(cosine, 0.0, 1.0), shininess)"
FREE_POW = """float phongPowThirty(float x)
{
  float x2 = x * x;
  float x4 = x2 * x2;
  float x8 = x4 * x4;
  return x8 * x8 * x8 * x4 * x2;
}
"""


def make_window(size):
    """One window for every row: Xvfb may refuse a new connection right after one closes."""
    from vtkmodules.vtkRenderingCore import vtkRenderWindow
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factory)

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(*size)
    return window


def make_scene(window, lights, resolution):
    """The sphere, and a renderer of its own under the lights, in place of the last one."""
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkRenderingCore import vtkLight, vtkRenderer

    sphere = vtkSphereSource()
    sphere.SetThetaResolution(resolution)
    sphere.SetPhiResolution(resolution)
    sphere.Update()
    renderer = vtkRenderer()
    renderer.AutomaticLightCreationOff()
    for i in range(lights):
        angle = 2.0 * math.pi * i / lights
        light = vtkLight()
        light.SetLightTypeToSceneLight()
        light.SetPositional(False)
        light.SetPosition(1.5 * math.cos(angle), 1.5 * math.sin(angle), 1.5)
        light.SetFocalPoint(0.0, 0.0, 0.0)
        light.SetColor(0.6 + 0.4 * math.cos(angle), 0.8, 0.6 + 0.4 * math.sin(angle))
        renderer.AddLight(light)
    window.GetRenderers().RemoveAllItems()
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 0.0, 1.6)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.SetViewAngle(40.0)
    return sphere.GetOutput(), renderer


def add_actor(renderer, mesh, mapper, lit=True, cull_back_faces=False):
    from vtkmodules.vtkRenderingCore import vtkActor

    mapper.SetInputData(mesh)
    actor = vtkActor()
    actor.SetMapper(mapper)
    material = actor.GetProperty()
    material.SetColor(0.8, 0.6, 0.4)
    material.SetSpecularColor(1.0, 1.0, 1.0)
    material.SetAmbient(0.1)
    material.SetDiffuse(0.8)
    material.SetSpecular(0.5)
    material.SetSpecularPower(30.0)
    material.SetInterpolationToPhong()
    material.SetLighting(lit)
    material.SetBackfaceCulling(cull_back_faces)
    renderer.AddActor(actor)
    return actor


def without_tags(source):
    # The mapper would substitute its tags again in code given back to it; the two the shader
    # cache fills (the version line, the fragment outputs) stay.
    return re.sub(r"//VTK::(?!System::Dec|Output::Dec)\w+::\w+", "", source)


def free_pow_actor(renderer, window, mesh):
    """vtkPhong's generated shader with a free pow, as the shader code of a new actor."""
    import vtkphong

    probe = add_actor(renderer, mesh, vtkphong.vtkPhongPolyDataMapper())
    window.Render()
    mapper = probe.GetMapper()
    fragment = without_tags(mapper.GetLastFragmentShaderSource())
    vertex = without_tags(mapper.GetLastVertexShaderSource())
    probe.VisibilityOff()
    renderer.RemoveActor(probe)
    if POW not in fragment:
        raise RuntimeError("the generated lobe no longer reads " + POW)
    fragment = fragment.replace(POW, "phongPowThirty(clamp(cosine, 0.0, 1.0))")
    fragment = fragment.replace("float phongGatedLobe(", FREE_POW + "float phongGatedLobe(", 1)
    actor = add_actor(renderer, mesh, vtkphong.vtkPhongPolyDataMapper(), cull_back_faces=True)
    actor.GetShaderProperty().SetVertexShaderCode(vertex)
    actor.GetShaderProperty().SetFragmentShaderCode(fragment)
    return actor


def race(window, actors, batches, frames):
    """Median seconds per frame of each actor shown alone, in turns."""
    times = [[] for _ in actors]
    for _ in range(batches):
        for k, actor in enumerate(actors):
            for other in actors:
                other.SetVisibility(other is actor)
            window.Render()
            window.WaitForCompletion()
            start = time.perf_counter()
            for _ in range(frames):
                window.Render()
                window.WaitForCompletion()
            times[k].append((time.perf_counter() - start) / frames)
    return [statistics.median(t) for t in times]


def measure(window, lights, quick):
    from vtkmodules.vtkRenderingCore import vtkPolyDataMapper
    import vtkphong

    mesh, renderer = make_scene(window, lights, 32 if quick else 256)
    free_pow = free_pow_actor(renderer, window, mesh)
    no_dots = vtkphong.vtkPhongPolyDataMapper()
    no_dots.InterpolatedDotProductsOff()
    actors = [
        add_actor(renderer, mesh, vtkPolyDataMapper(), lit=False, cull_back_faces=True),
        add_actor(renderer, mesh, vtkPolyDataMapper()),
        add_actor(renderer, mesh, vtkphong.vtkPhongPolyDataMapper()),
        add_actor(renderer, mesh, no_dots),
        free_pow,
    ]
    renderer.ResetCameraClippingRange()
    return race(window, actors, 2 if quick else 7, 1 if quick else 4)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lights", type=int, nargs="+", default=[8, 32])
    parser.add_argument("--quick", action="store_true", help="tiny window, for ctest")
    args = parser.parse_args()
    print("lights | floor | stock | vtkPhong | no dots | free pow | vtkPhong/stock | "
          "free pow/stock | lighting: vtkPhong / no dots | lighting: free pow / vtkPhong")
    print("|".join(["---"] * 10))
    window = make_window((320, 256) if args.quick else (1280, 1024))
    for lights in args.lights:
        times = measure(window, lights, args.quick)
        floor, stock, ours, no_dots, free_pow = (1e3 * t for t in times)
        print("%d | %.1f ms | %.1f ms | %.1f ms | %.1f ms | %.1f ms | %.2fx | %.2fx | %.2fx | %.2fx"
              % (lights, floor, stock, ours, no_dots, free_pow, ours / stock, free_pow / stock,
                 (ours - floor) / (no_dots - floor), (free_pow - floor) / (ours - floor)),
              flush=True)


if __name__ == "__main__":
    main()
