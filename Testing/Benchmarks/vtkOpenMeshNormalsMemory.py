"""vtkOpenMeshNormals' memory and time, point by point against the kept topology.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \\
        Testing/Benchmarks/vtkOpenMeshNormalsMemory.py [SPHERE_RESOLUTION ...]

For each resolution (default 1000 and 2000: 2M and 8M triangles), a vtkSphereSource sphere
without normals (theta = 2 x resolution), and each path (PointByPoint on, the default, and
off), one child process: the first execution's time and peak resident memory above the
data (VmHWM less the data's VmRSS), then two positions-only updates (an animation: the
default path builds the topology at the first and reuses it at the second). Prints
numbers, asserts nothing.
"""

import subprocess
import sys
import time


def megabytes(field):
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith(field):
                return int(line.split()[1]) / 1024.0
    return 0.0


def child(resolution, point_by_point):
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkphong.vtkFiltersOpenMesh import vtkOpenMeshNormals

    source = vtkSphereSource()
    source.SetThetaResolution(2 * resolution)
    source.SetPhiResolution(resolution // 2 + 1)
    source.Update()
    mesh = source.GetOutput()
    mesh.GetPointData().SetNormals(None)
    data = megabytes("VmRSS:")
    normals = vtkOpenMeshNormals()
    normals.SetInputData(mesh)
    normals.SetPointByPoint(point_by_point)
    start = time.perf_counter()
    normals.Update()
    first = time.perf_counter() - start
    peak = megabytes("VmHWM:") - data
    path = "point by point" if normals.GetComputedPointByPoint() else "topology"
    updates = []
    points = mesh.GetPoints()
    for step in range(2):
        x = points.GetPoint(step)
        points.SetPoint(step, x[0] * 1.001, x[1], x[2])
        points.Modified()
        start = time.perf_counter()
        normals.Update()
        updates.append(time.perf_counter() - start)
    print("| %.1fM | %s | %s | %.2f s | %.0f MB | %.2f / %.2f s |" % (
        mesh.GetNumberOfPolys() / 1e6, "on" if point_by_point else "off", path, first, peak,
        updates[0], updates[1]))


if len(sys.argv) == 4 and sys.argv[1] == "--child":
    child(int(sys.argv[2]), sys.argv[3] == "on")
    sys.exit(0)

resolutions = [int(r) for r in sys.argv[1:]] or [1000, 2000]
print("| triangles | PointByPoint | path | first execution | peak above data | "
      "positions-only updates, first / second |")
print("|---|---|---|---|---|---|")
for resolution in resolutions:
    for setting in ("on", "off"):
        sys.stdout.flush()
        subprocess.run([sys.executable, __file__, "--child", str(resolution), setting], check=True)
