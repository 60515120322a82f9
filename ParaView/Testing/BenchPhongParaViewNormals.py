"""What the normals of "Phong Surface" cost when the data changes: the time of an update and
a frame, for ParaView's "Surface" (no normals computed), "Phong Surface" with
NormalsAcrossPieces off (each piece's normals alone) and on (one level of ghost cells made,
kept through the geometry filter, dropped after the normals):

    pvbatch --disable-xdisplay-test BenchPhongParaViewNormals.py --plugin PhongLighting.so
    mpiexec -np 2 pvbatch --disable-xdisplay-test BenchPhongParaViewNormals.py --plugin ...

Prints one table; asserts nothing. The three take turns, batch after batch; each step changes
the sphere's radius a little, so that the whole pipeline runs again (the Sphere source makes
one piece per rank; PassArrays removes its normals), then renders one still frame.
"""

import argparse
import statistics
import time

from phong_paraview_testing import bare_sphere, prefer_pythonpath, still_view

prefer_pythonpath()

from paraview import servermanager  # noqa: E402
from paraview.simple import LoadPlugin, Render, Show  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--resolution", type=int, default=708, help="sphere theta/phi resolution")
parser.add_argument("--batches", type=int, default=5)
parser.add_argument("--steps", type=int, default=3)
args = parser.parse_args()

LoadPlugin(args.plugin, remote=False, ns=globals())
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
view = still_view([800, 600])
sphere, bare = bare_sphere(args.resolution)
display = Show(bare, view)
Render(view)

setups = [("Surface", "Surface", None), ("Phong, pieces alone", "Phong Surface", 0),
          ("Phong, across pieces", "Phong Surface", 1)]
times = {name: [] for name, _, _ in setups}
radius = 0.5
for batch in range(args.batches):
    for name, representation, across in setups:
        display.SetRepresentationType(representation)
        if across is not None:
            display.NormalsAcrossPieces = across
        Render(view)  # the switch itself is not timed
        for _ in range(args.steps):
            radius += 1e-4
            sphere.Radius = radius
            start = time.perf_counter()
            Render(view)
            times[name].append(time.perf_counter() - start)

triangles = 2 * args.resolution * (args.resolution - 2)
print("%d rank(s), sphere of %d triangles, update + frame, medians of %d:"
      % (ranks, triangles, args.batches * args.steps))
base = statistics.median(times["Surface"])
for name, _, _ in setups:
    median = statistics.median(times[name])
    print("  %-22s %8.1f ms  %5.2fx Surface" % (name, 1000.0 * median, median / base))
