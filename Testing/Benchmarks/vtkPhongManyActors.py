"""Frame times of many actors of distinct colours under an error budget.

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Testing/Benchmarks/vtkPhongManyActors.py [ACTORS ...] [--budget LEVELS]

For each count (default 5 and 50), spheres (32 x 32) of as many colours on a grid, each with
its own vtkPhongPolyDataMapper, 800 x 800, one process per line: the first six frames in ms,
without an error budget and with one (default 1 level). Under a budget the second frame is where the uniform
constants are compiled (docs/lighting-model.md, "Error budget", 4.): one program the actors
share, or, in renderers of at most four visible actors, one per actor. Prints numbers,
asserts nothing.
"""

import argparse
import subprocess
import sys
import time

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factory)
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkRenderWindow

import vtkphong


def frame_times(count, budget, frames=6):
    """The first `frames` frame times (ms) of `count` spheres of distinct colours."""
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(32)
    sphere.SetPhiResolution(32)
    sphere.Update()
    renderer = vtkRenderer()
    side = max(1, round(count ** 0.5 + 0.499))
    keep = []
    for i in range(count):
        mapper = vtkphong.vtkPhongPolyDataMapper()
        mapper.SetInputData(sphere.GetOutput())
        mapper.SetErrorBudget(budget)
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.SetPosition(i % side, i // side, 0.0)
        actor.GetProperty().SetColor((i * 37 % 255) / 255.0, (i * 91 % 255) / 255.0,
                                     (i * 53 % 255) / 255.0)
        actor.GetProperty().SetSpecular(0.4)
        actor.GetProperty().SetSpecularPower(30.0)
        renderer.AddActor(actor)
        keep.append(mapper)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(800, 800)
    renderer.ResetCamera()
    times = []
    for _ in range(frames):
        start = time.perf_counter()
        window.Render()
        times.append(1000.0 * (time.perf_counter() - start))
    return times


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("actors", nargs="*", type=int, default=[5, 50])
    parser.add_argument("--budget", type=float, default=1.0)
    parser.add_argument("--one", action="store_true", help="measure ACTORS[0] at --budget here")
    args = parser.parse_args()
    if args.one:
        times = frame_times(args.actors[0], args.budget)
        print("%6d  %6g  %s" % (args.actors[0], args.budget, "  ".join("%6.0f" % t for t in times)))
        return
    print("actors  budget  frames 1-6 (ms)", flush=True)
    for count in args.actors:
        for budget in (0.0, args.budget):
            subprocess.run([sys.executable, __file__, str(count), "--budget", str(budget), "--one"],
                           check=True)


if __name__ == "__main__":
    main()
