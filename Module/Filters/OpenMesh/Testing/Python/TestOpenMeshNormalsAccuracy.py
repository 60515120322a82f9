"""Accuracy of vtkOpenMeshNormals' vertex weightings against exact normals.

Surfaces: a unit sphere (latitude-longitude grid) and a torus (R = 1,
r = 0.35), at several resolutions, regular and irregular (every point moved
along the exact surface by up to 20 % of a grid step in each parameter,
which moves points without folding a triangle over).
Points are double precision and lie exactly on the surface; the exact normal
is the surface's. Errors in degrees: mean, 99th percentile and max over the
points. docs/normals.md quotes the table printed here.

The test asserts what the documentation claims: Max is exact on the sphere
(regular or not: its vertices' neighbours lie on a sphere), and Max is the
most accurate weighting (lowest mean error) in every row of the table.

    PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 \\
        TestOpenMeshNormalsAccuracy.py -B . -T /tmp
"""

import math

import numpy
import vtkphong
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkphong_testing import Checks, arguments

arguments()
checks = Checks()
WEIGHTINGS = ["Uniform", "Area", "Angle", "Max"]
RNG = numpy.random.default_rng(7)


def grid_triangles(nu, nv, wrap_u, wrap_v):
    """Triangles of an nu x nv grid of points (index u * nv + v)."""
    triangles = []
    for i in range(nu if wrap_u else nu - 1):
        for j in range(nv if wrap_v else nv - 1):
            a = i * nv + j
            b = ((i + 1) % nu) * nv + j
            c = ((i + 1) % nu) * nv + (j + 1) % nv
            d = i * nv + (j + 1) % nv
            triangles += [(a, b, c), (a, c, d)]
    return numpy.array(triangles, dtype=numpy.int64)


def sphere(resolution, irregular):
    """Unit sphere: poles plus (resolution - 1) latitude rings of 2*resolution points."""
    rings, around = resolution - 1, 2 * resolution
    theta = numpy.linspace(0, math.pi, resolution + 1)[1:-1]  # ring latitudes
    phi = numpy.arange(around) * 2 * math.pi / around
    t, p = numpy.meshgrid(theta, phi, indexing="ij")
    if irregular:
        t = t + RNG.uniform(-0.2, 0.2, t.shape) * (math.pi / resolution)
        p = p + RNG.uniform(-0.2, 0.2, p.shape) * (2 * math.pi / around)
    points = numpy.stack([numpy.sin(t) * numpy.cos(p), numpy.sin(t) * numpy.sin(p), numpy.cos(t)], -1)
    points = numpy.vstack([[0, 0, 1], points.reshape(-1, 3), [0, 0, -1]])
    body = grid_triangles(rings, around, False, True) + 1
    north, south = 0, 1 + rings * around
    caps = []
    for j in range(around):
        k = (j + 1) % around
        caps.append((north, 1 + k, 1 + j))
        caps.append((south, 1 + (rings - 1) * around + j, 1 + (rings - 1) * around + k))
    triangles = numpy.vstack([body, numpy.array(caps)])
    # Wind every triangle outward (the sphere is convex).
    a, b, c = points[triangles[:, 0]], points[triangles[:, 1]], points[triangles[:, 2]]
    inward = (numpy.cross(b - a, c - a) * (a + b + c)).sum(1) < 0
    triangles[inward] = triangles[inward][:, [0, 2, 1]]
    return points, triangles, points.copy()


def torus(resolution, irregular, R=1.0, r=0.35):
    nu, nv = 2 * resolution, resolution
    u = numpy.arange(nu) * 2 * math.pi / nu
    v = numpy.arange(nv) * 2 * math.pi / nv
    uu, vv = numpy.meshgrid(u, v, indexing="ij")
    if irregular:
        uu = uu + RNG.uniform(-0.2, 0.2, uu.shape) * (2 * math.pi / nu)
        vv = vv + RNG.uniform(-0.2, 0.2, vv.shape) * (2 * math.pi / nv)
    points = numpy.stack([(R + r * numpy.cos(vv)) * numpy.cos(uu),
                          (R + r * numpy.cos(vv)) * numpy.sin(uu), r * numpy.sin(vv)], -1).reshape(-1, 3)
    normals = numpy.stack([numpy.cos(vv) * numpy.cos(uu), numpy.cos(vv) * numpy.sin(uu),
                           numpy.sin(vv)], -1).reshape(-1, 3)
    return points, grid_triangles(nu, nv, True, True), normals


def to_polydata(points, triangles):
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(numpy.ascontiguousarray(points, dtype=numpy.float64), deep=True))
    cells = vtkCellArray()
    offsets = numpy.arange(0, 3 * len(triangles) + 1, 3, dtype=numpy.int64)
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(numpy.ascontiguousarray(triangles.ravel()), deep=True))
    mesh = vtkPolyData()
    mesh.SetPoints(vtk_points)
    mesh.SetPolys(cells)
    return mesh


def errors(mesh, exact, weighting):
    normals = vtkphong.vtkOpenMeshNormals()
    normals.SetInputData(mesh)
    normals.SplittingOff()  # a smooth surface: one normal per point
    getattr(normals, "SetWeightingTo" + weighting)()
    normals.Update()
    computed = vtk_to_numpy(normals.GetOutput().GetPointData().GetNormals()).astype(float)
    # The angle by atan2(|a x b|, a . b) on renormalized vectors: arccos of a
    # dot product cannot resolve the float output's tiny errors.
    computed /= numpy.linalg.norm(computed, axis=1)[:, None]
    exact = exact / numpy.linalg.norm(exact, axis=1)[:, None]
    sine = numpy.linalg.norm(numpy.cross(computed, exact), axis=1)
    degrees = numpy.degrees(numpy.arctan2(sine, (computed * exact).sum(1)))
    return degrees.mean(), numpy.percentile(degrees, 99), degrees.max()


print("| surface | resolution | sampling | triangles | " +
      " | ".join("%s mean / max" % w for w in WEIGHTINGS) + " |")
# (errors in degrees)
print("|---" * (4 + len(WEIGHTINGS)) + "|")
for surface, make in (("sphere", sphere), ("torus", torus)):
    for resolution in (8, 16, 32, 64):
        for irregular in (False, True):
            points, triangles, exact = make(resolution, irregular)
            mesh = to_polydata(points, triangles)
            results = {w: errors(mesh, exact, w) for w in WEIGHTINGS}
            cells = " | ".join("%.2g / %.2g" % (results[w][0], results[w][2]) for w in WEIGHTINGS)
            sampling = "irregular" if irregular else "regular"
            print("| %s | %d | %s | %d | %s |" % (surface, resolution, sampling, len(triangles), cells))
            best = min(WEIGHTINGS, key=lambda w: results[w][0])
            checks.expect(best == "Max", "%s %d %s: Max is the most accurate (best: %s)"
                          % (surface, resolution, sampling, best))
            if surface == "sphere":
                checks.expect(results["Max"][2] < 1e-5, "Max is exact on the %s sphere (%d): max %.2e"
                              % (sampling, resolution, results["Max"][2]))
checks.exit()
