"""Big meshes, stock VTK beside vtkPhong, one process per measurement (issue 29's table).

    vtkPhongGrowth.py --program build/bin/vtkPhongBigMeshFrame [--quick] [--sizes 1e6,2e6,...]

For each mesh (a closed sphere, an open warped-plane terrain), size, and with and without
normals in the input, it runs vtkPhongBigMeshFrame once with VTK's mapper and once with
vtkPhong's, and prints the first frame, the steady frame (median of 5, after 5 s of untimed
frames in which vtkPhong's background analyses of a large mesh end) and the peak memory
above the data, with vtkPhong's ratio to stock beside each. Needs no VTK itself (any
python3): the program draws, under the display the caller gives it (xvfb-run, or a GPU's X).
"""

import argparse
import subprocess
import sys

parser = argparse.ArgumentParser()
parser.add_argument("--program", required=True)
parser.add_argument("--quick", action="store_true", help="small sizes, to keep it from rotting")
parser.add_argument("--sizes", default="1e6,2e6,8e6,16e6,32e6")
parser.add_argument("--meshes", default="sphere,terrain")
parser.add_argument("--timeout", type=float, default=900.0)
parser.add_argument("--settle", default="5",
                    help="seconds of untimed frames before the steady ones (background analyses)")
args = parser.parse_args()
sizes = [2e4, 1e5] if args.quick else [float(s) for s in args.sizes.split(",")]
window = ["--size", "200", "--frames", "2"] if args.quick else ["--settle", args.settle]


def measure(mesh, triangles, normals, mapper):
    command = [args.program, "--mesh", mesh, "--triangles", "%d" % triangles,
               "--normals", normals, "--mapper", mapper] + window
    try:
        result = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout)
    except subprocess.TimeoutExpired:
        return {"error": "timed out"}
    for line in result.stdout.splitlines():
        if line.startswith("RESULT "):
            return dict(field.split("=", 1) for field in line.split()[1:])
    return {"error": "status %d: %s" % (result.returncode, result.stderr.strip()[-200:])}


def ratio(phong, stock, key):
    a, b = float(phong[key]), float(stock[key])
    return "%.2fx" % (a / b) if b > 0 else "-"


print("| mesh | triangles | input normals | first frame, stock / vtkPhong (ratio) | "
      "steady frame, stock / vtkPhong (ratio) | peak above data, stock / vtkPhong (ratio) | "
      "culled | vtkPhong's normals | renderer |")
print("|---|---|---|---|---|---|---|---|---|")
failures = 0
for mesh in args.meshes.split(","):
    for triangles in sizes:
        for normals in ("yes", "no"):
            stock = measure(mesh, triangles, normals, "stock")
            phong = measure(mesh, triangles, normals, "phong")
            if "error" in stock or "error" in phong:
                failures += 1
                print("| %s | %.0f | %s | %s | | | | | |" % (
                    mesh, triangles, normals, stock.get("error") or phong.get("error")))
                continue
            print("| %s | %.1fM | %s | %s / %s s (%s) | %s / %s ms (%s) | %s / %s MB (%s) | %s | %s | %s |"
                  % (mesh, int(phong["triangles"]) / 1e6, normals,
                     stock["first_s"], phong["first_s"], ratio(phong, stock, "first_s"),
                     stock["steady_ms"], phong["steady_ms"], ratio(phong, stock, "steady_ms"),
                     stock["peak_above_data_mb"], phong["peak_above_data_mb"],
                     ratio(phong, stock, "peak_above_data_mb"),
                     "yes" if phong["culled"] == "1" else "no",
                     phong.get("normals_path", "-").replace("-", " "), phong["renderer"]))
            sys.stdout.flush()
sys.exit(1 if failures else 0)
