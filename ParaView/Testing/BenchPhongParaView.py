"""Frame time of "Phong Surface" (with and without culling the back faces) against
ParaView's "Surface" on a sphere of several million triangles, then on 8 nested contours
(with and without the depth pre-pass), at two image sizes, for however many ranks pvbatch
runs on:

    pvbatch --disable-xdisplay-test BenchPhongParaView.py --plugin PhongLighting.so
    mpiexec -np 2 pvbatch --disable-xdisplay-test BenchPhongParaView.py --plugin ...

(./vtkphong.sh paraview-bench runs both.) Prints two tables; asserts nothing. The
representations take turns, batch after batch, in one view; a frame is Render() of a
still (non-LOD) frame, composited by IceT when there are several ranks.
"""

import argparse
import statistics
import time

from phong_paraview_testing import prefer_pythonpath, still_view

prefer_pythonpath()

from paraview import servermanager  # noqa: E402
from paraview.simple import (AddLight, Contour, LoadPlugin, Render, Show, Sphere,  # noqa: E402
                             Wavelet)

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--resolution", type=int, default=1414, help="sphere theta/phi resolution")
parser.add_argument("--batches", type=int, default=5)
parser.add_argument("--frames", type=int, default=3)
args = parser.parse_args()

LoadPlugin(args.plugin, remote=False, ns=globals())
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
view = still_view()
view.UseLight = 0
for index, (kind, position) in enumerate((("Directional", [1, 1, 2]), ("Positional", [-2, 0, 1]),
                                           ("Positional", [0, 2, 1]))):
    light = AddLight(view=view)
    light.Coords = "Scene"
    light.Type = kind
    light.Position = position
    light.FocalPoint = [0, 0, 0]
    light.ConeAngle = 90.0 if index == 1 else 25.0
    light.Intensity = 0.6


def contenders(make_source, third, setting, plain_colour=False):
    """ParaView's Surface, Phong Surface, and Phong Surface with `setting` (a property name
    and value) as `third`, each showing a source of its own (Show() of one source twice
    returns the same display)."""
    displays = {}
    for name in ("Surface", "Phong Surface", third):
        display = Show(make_source(), view)
        display.SetRepresentationType("Surface" if name == "Surface" else "Phong Surface")
        if plain_colour:
            display.ColorArrayName = [None, ""]
        display.Specular = 0.5
        if name == third:
            setattr(display, *setting)
        displays[name] = display
    return displays


UNCULLED = "Phong, back faces drawn"
displays = contenders(
    lambda: Sphere(ThetaResolution=args.resolution, PhiResolution=args.resolution),
    UNCULLED, ("CullHiddenBackFaces", 0))

camera = view.GetActiveCamera()
triangles = 2 * args.resolution * (args.resolution - 2)


def time_displays(displays, sizes):
    """Median frame time (ms) of each display shown alone, per image size: the displays
    take turns, batch after batch."""
    rows = []
    for size in sizes:
        view.ViewSize = list(size)
        view.ResetCamera()
        times = {name: [] for name in displays}
        for name in displays:  # build buffers and shaders first
            for other, display in displays.items():
                display.Visibility = int(other == name)
            Render(view)
            Render(view)  # Automatic's probe of the depth pre-pass
        for _ in range(args.batches):
            for name in displays:
                for other, display in displays.items():
                    display.Visibility = int(other == name)
                Render(view)
                start = time.perf_counter()
                for frame in range(args.frames):
                    # A camera that moves makes every Render() draw (an unchanged scene may
                    # not).
                    camera.Azimuth(0.05 if frame % 2 else -0.05)
                    Render(view)
                times[name].append((time.perf_counter() - start) / args.frames)
        rows.append((size, [1e3 * statistics.median(times[name]) for name in displays]))
    for display in displays.values():
        display.Visibility = 0
    return rows


rows = time_displays(displays, ((800, 600), (1600, 1200)))

# Serially the sphere is closed and Phong Surface culls its back faces; split between ranks
# each piece is open and drawn whole (the third column: culling off).
print("ranks %d, sphere %d x %d (%d triangles), 3 lights (directional, point, spot)"
      % (ranks, args.resolution, args.resolution, triangles))
print("%-10s %14s %18s %24s %8s %8s" % ("image", "Surface (ms)", "Phong Surface (ms)",
                                        UNCULLED + " (ms)", "ratio", "unculled"))
for size, (stock, ours, unculled) in rows:
    print("%-10s %14.1f %18.1f %24.1f %7.2fx %7.2fx"
          % ("%dx%d" % size, stock, ours, unculled, ours / stock, unculled / stock))

# Deep scenes: 8 nested contours of the Wavelet (81^3 samples), under the same lights:
# ParaView's Surface, Phong Surface (its depth pre-pass automatic) and Phong Surface with
# the pre-pass off.
NO_PRE_PASS = "Phong, no pre-pass"
contours = contenders(
    lambda: Contour(Input=Wavelet(WholeExtent=[-40, 40, -40, 40, -40, 40]),
                    ContourBy=["POINTS", "RTData"],
                    Isosurfaces=[200.0 + 9.0 * i for i in range(8)]),
    NO_PRE_PASS, ("DepthPrePass", "Off"), plain_colour=True)
print("ranks %d, 8 nested contours of the Wavelet (81^3 samples), same lights" % ranks)
print("%-10s %14s %18s %24s %8s %8s" % ("image", "Surface (ms)", "Phong Surface (ms)",
                                        NO_PRE_PASS + " (ms)", "ratio", "no pre"))
for size, (stock, ours, plain) in time_displays(contours, ((800, 600), (1600, 1200))):
    print("%-10s %14.1f %18.1f %24.1f %7.2fx %7.2fx"
          % ("%dx%d" % size, stock, ours, plain, ours / stock, plain / stock))
