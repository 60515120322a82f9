"""First frame, steady frame and peak memory of "Phong Surface" against ParaView's "Surface"
on one big dataset (ParaView's Sphere source, 16M triangles by default, without its normals
unless --normals), one pvbatch process per measurement, serially and under MPI (issue 29):

    python3 BenchPhongParaViewGrowth.py --plugin PhongLighting.so [--ranks 1,2] \\
        [--resolution 2829] [--frames 3] [--normals] [--set PROPERTY=VALUE ...]

runs, for each number of ranks and each representation, `mpiexec -np N pvbatch --symmetric
BenchPhongParaViewGrowth.py --measure ...` and prints one table (stock "Surface" beside
"Phong Surface", ratios). Asserts nothing. A measuring process makes the data
(UpdatePipeline), notes each rank's resident memory, then times the first frame (Show and
Render: the geometry filter, vtkPhong's normals and analyses, the upload, IceT), then the
median of --frames still frames with the camera turned a degree each; each rank's peak
resident memory above what it held once the data was made closes its line. --set gives a
property of Phong Surface's (an integer or a number), to see what a part costs, e.g.
--set CullHiddenBackFaces=0.
"""

import argparse
import os
import re
import statistics
import subprocess
import sys
import time

REPRESENTATIONS = ("Surface", "Phong Surface")


def memory_mb(field):
    with open("/proc/self/status") as stream:
        for line in stream:
            if line.startswith(field + ":"):
                return int(line.split()[1]) / 1024.0
    return 0.0


def measure(args):
    """One process per rank (--symmetric): every rank runs this."""
    from phong_paraview_testing import bare_sphere, prefer_pythonpath, still_view
    prefer_pythonpath()
    from paraview.simple import GetActiveCamera, LoadPlugin, Render, Show
    from vtkmodules.vtkParallelCore import vtkMultiProcessController
    LoadPlugin(args.plugin, remote=False, ns=globals())
    rank = vtkMultiProcessController.GetGlobalController().GetLocalProcessId()
    view = still_view([800, 800])
    sphere, bare = bare_sphere(args.resolution)
    data = sphere if args.normals else bare
    data.UpdatePipeline()
    data_mb = memory_mb("VmRSS")
    start = time.perf_counter()
    display = Show(data, view)
    display.SetRepresentationType(args.measure)
    display.Specular = 0.4
    if args.measure == "Phong Surface":
        for setting in args.set:
            name, value = setting.split("=", 1)
            setattr(display, name, float(value) if "." in value else int(value))
    view.ResetCamera()
    Render(view)
    first = time.perf_counter() - start
    camera = GetActiveCamera()
    frames = []
    for _ in range(args.frames):
        camera.Azimuth(1.0)
        start = time.perf_counter()
        Render(view)
        frames.append(time.perf_counter() - start)
    peak = memory_mb("VmHWM") - data_mb
    print("RESULT rank=%d representation=%s first_s=%.3f steady_ms=%.1f data_mb=%.0f "
          "peak_above_data_mb=%.0f" % (rank, args.measure.replace(" ", "_"), first,
                                       1000 * statistics.median(frames), data_mb, peak),
          flush=True)


def run_one(args, ranks, representation):
    command = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks),
               "pvbatch", "--symmetric", "--disable-xdisplay-test", os.path.abspath(__file__),
               "--plugin", args.plugin, "--resolution", str(args.resolution),
               "--frames", str(args.frames), "--measure", representation]
    command += ["--normals"] if args.normals else []
    command += [item for setting in args.set for item in ("--set", setting)]
    output = subprocess.run(command, capture_output=True, text=True, timeout=1800).stdout
    results = [dict(re.findall(r"(\w+)=(\S+)", line)) for line in output.splitlines()
               if line.startswith("RESULT")]
    if not results:
        sys.exit("no result from: " + " ".join(command))
    # Ranks render together: the slowest rank's times, the largest rank's memory.
    return {key: max(float(r[key]) for r in results)
            for key in ("first_s", "steady_ms", "peak_above_data_mb")}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--ranks", default="1,2")
    parser.add_argument("--resolution", type=int, default=2829,
                        help="the Sphere's theta and phi resolution: 2829 makes 16.0M triangles")
    parser.add_argument("--frames", type=int, default=3)
    parser.add_argument("--normals", action="store_true",
                        help="keep the Sphere's point normals (the input has normals)")
    parser.add_argument("--set", action="append", default=[], metavar="PROPERTY=VALUE",
                        help="a property of Phong Surface's (repeatable)")
    parser.add_argument("--measure", choices=REPRESENTATIONS,
                        help="(internal) measure this representation in this pvbatch")
    args = parser.parse_args()
    if args.measure:
        measure(args)
        return
    triangles = 2 * args.resolution * (args.resolution - 2)
    print("| ranks | triangles | input normals | first frame, Surface / Phong Surface (ratio) "
          "| steady frame, Surface / Phong Surface (ratio) | peak above data per rank, "
          "Surface / Phong Surface (ratio) |")
    print("|---|---|---|---|---|---|")
    for ranks in (int(r) for r in args.ranks.split(",")):
        stock, phong = (run_one(args, ranks, r) for r in REPRESENTATIONS)
        ratio = {key: phong[key] / stock[key] for key in stock}
        print("| %d | %.1fM | %s | %.2f / %.2f s (%.2fx) | %.0f / %.0f ms (%.2fx) | %.0f / %.0f "
              "MB (%.2fx) |" % (
                  ranks, triangles / 1e6, "yes" if args.normals else "no",
                  stock["first_s"], phong["first_s"], ratio["first_s"],
                  stock["steady_ms"], phong["steady_ms"], ratio["steady_ms"],
                  stock["peak_above_data_mb"], phong["peak_above_data_mb"],
                  ratio["peak_above_data_mb"]), flush=True)


if __name__ == "__main__":
    main()
