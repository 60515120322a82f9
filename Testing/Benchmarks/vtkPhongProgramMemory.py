"""Memory of the lighting shader programs over a light-count sweep.

Raises the number of directional lights of one sphere from 1 to N (default 200): every
count is a shader variant of its own. Prints the process's resident memory after the
sweep with the mapper's program limit off (0: every program kept) and at its default (32),
each in a fresh process so that one does not inherit the other's programs, side by side
(Mesa's on-disk shader cache off, so both compile every program).

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Testing/Benchmarks/vtkPhongProgramMemory.py [--lights N]
"""

import argparse
import os
import subprocess
import sys


def resident_megabytes():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


def sweep(limit, lights):
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkRenderer, vtkRenderWindow
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factory)
    import vtkphong

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(256, 256)
    renderer = vtkRenderer()
    renderer.AutomaticLightCreationOff()
    window.AddRenderer(renderer)
    sphere = vtkSphereSource()
    mapper = vtkphong.vtkPhongPolyDataMapper()
    mapper.SetInputConnection(sphere.GetOutputPort())
    mapper.SetMaximumNumberOfShaderPrograms(limit)
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    renderer.ResetCamera()
    window.Render()
    start = resident_megabytes()
    for count in range(1, lights + 1):
        light = vtkLight()
        light.SetPosition(count % 7 - 3.0, 1.0, 2.0)
        light.SetIntensity(1.0 / lights)
        renderer.AddLight(light)
        window.Render()
    print(f"{limit:>5} {mapper.GetShaderCompileCount():>8} "
          f"{mapper.GetNumberOfCompiledShaderPrograms():>9} "
          f"{resident_megabytes() - start:>10.1f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lights", type=int, default=200)
    parser.add_argument("--limit", type=int, help=argparse.SUPPRESS)  # one child's sweep
    args = parser.parse_args()
    if args.limit is not None:
        sweep(args.limit, args.lights)
        return
    # Mesa's on-disk shader cache would make a second run cheaper than the first.
    os.environ["MESA_SHADER_CACHE_DISABLE"] = "true"
    print(f"{args.lights} variants (1..{args.lights} directional lights), one sphere")
    print("limit compiles  compiled  +RSS (MB)")
    sys.stdout.flush()
    for limit in (0, 32):
        subprocess.run([sys.executable, __file__, "--lights", str(args.lights),
                        "--limit", str(limit)], check=True)


if __name__ == "__main__":
    main()
