"""Real clients' own code through the switch: PyVista's and vedo's scenes
(pyvista_scenes.py, vedo_scenes.py: the clients' API only, no vtkPhong name), each drawn in a
fresh process with stock VTK and again with `import vtkphong.overrides` run first, compared
pixel by pixel (8-bit levels, the largest channel difference of a pixel).

A scene either matches (at most MATCH_PERCENT % of its pixels more than 8 levels off) or
carries a named difference with an upper bound (and a lower one where the difference must
show). The test also fails when the switched run did not draw with vtkPhong's mappers, when the
stock run did, or when a picture is empty. A client that is not installed is skipped.

Each scene is drawn a third time, switched and under an error budget of BUDGET levels
(VTKPHONG_ERROR_BUDGET, as a user of the client would set it), and compared with the switched
exact picture: every pixel within the budget plus 1.5 levels (each picture's rounding to 8 bits
and the exact mode's own float error), but for a few pixels on a silhouette (SILHOUETTE_PERCENT
% at most, each next to the background): the clients draw with multisampling, which shades a
pixel that a triangle only partly covers at the pixel's centre, outside the triangle, where the
per-vertex sums are extrapolated and no bound holds. The scenes in BUDGET_PER_VERTEX must go
per vertex there. docs/compatibility.md ("Clients") has the measured tables.

    xvfb-run -a /usr/bin/python3 TestPhongClients.py -T OUT [--only SCENE...]
(PYTHONPATH: the build's lib/python3/dist-packages and Testing/Core)
"""

import argparse
import os
import subprocess
import sys

import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkVersion
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkphong_testing import Checks, read_png

HERE = os.path.dirname(os.path.abspath(__file__))
LEVELS = 8
MATCH_PERCENT = 0.5
VTK = (vtkVersion.GetVTKMajorVersion(), vtkVersion.GetVTKMinorVersion())
SWITCH = ("import runpy, sys, vtkphong.overrides; sys.argv = sys.argv[1:]; "
          "runpy.run_path(sys.argv[0], run_name='__main__')")
PHONG_DRAWERS = ("vtkPhongPolyDataMapper", "vtkPhongCompositePolyDataMapper",
                 "vtkPhongCompositeDelegator")

BUDGET = 8.0
BUDGET_SLACK = 1.5
SILHOUETTE_PERCENT = 0.05
# A fine sphere coloured by a scalar: its bound fits 8 levels, so its sums go per vertex.
BUDGET_PER_VERTEX = {("vedo", "scalars"), ("pyvista", "scalars")}

# (client, scene): (why the pictures differ, at most % of pixels > 8 levels, at least %).
# None: the scene must match. Bounds hold on VTK 9.1, 9.3 and 9.6 (measured, with a margin).
MATCH = None
# With one light, a headlight (vedo's Plotter makes no other), stock VTK evaluates a Blinn lobe
# with the viewer at infinity, pow(N.z, p); vtkPhong the property's Phong lobe pow(R.V, p), a
# highlight about half as wide (docs/compatibility.md, "lone headlight with specular").
LONE_HEADLIGHT = "lone headlight: stock VTK's Blinn lobe, vtkPhong's Phong lobe"
CONE_NORMALS = "cone without normals: vtkPhong's computed smooth normals, stock flat"
EXPECTATIONS = {
    ("vedo", "default_look"): (CONE_NORMALS, 1.0, 0.0),
    ("vedo", "glossy"): (LONE_HEADLIGHT, 3.0, 1.0),
    ("vedo", "shiny_phong"): (LONE_HEADLIGHT, 6.0, 2.5),
    ("vedo", "light"): MATCH,
    ("vedo", "point_cloud"): MATCH,
    ("vedo", "edges"): MATCH,
    ("vedo", "flat"): MATCH,
    ("vedo", "scalars"): MATCH,
    ("pyvista", "smooth_light_kit"): MATCH,
    ("pyvista", "airplane_flat"): MATCH,
    ("pyvista", "positional_spot_lights"): MATCH,
    ("pyvista", "multiblock"): MATCH,
    ("pyvista", "shadows"): MATCH,
    ("pyvista", "ssao"): MATCH,
    ("pyvista", "points_as_spheres"): MATCH,
    ("pyvista", "edges"): MATCH,
    ("pyvista", "lighting_off"): MATCH,
    ("pyvista", "no_lights"): MATCH,
    ("pyvista", "scalars"): MATCH,
}


def version_of(client):
    try:
        return __import__(client).__version__
    except Exception as error:  # not installed, or broken: the scenes are skipped
        print("%s: not importable (%s); its scenes are skipped" % (client, error))
        return None


def save_pair(stock, phong, path):
    """Both pictures side by side, stock left, for a reviewer."""
    pair = numpy.concatenate((stock, phong), axis=1).astype(numpy.uint8)
    height, width, _ = pair.shape
    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    image.GetPointData().SetScalars(numpy_to_vtk(pair.reshape(-1, 3)))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def run_scene(script, scene, png, switched, budget=0.0):
    """Draw one scene in a fresh process; (mapper lines, delegator lines, budget modes) or
    None."""
    if os.path.exists(png):
        os.remove(png)
    command = [sys.executable] + (["-c", SWITCH] if switched else []) + [script, scene, png]
    environment = dict(os.environ)
    environment.pop("VTKPHONG_ERROR_BUDGET", None)
    if budget > 0.0:
        environment["VTKPHONG_ERROR_BUDGET"] = str(budget)
    for attempt in range(2):  # Xvfb may refuse a connection made right after another closed
        result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                universal_newlines=True, timeout=300, env=environment)
        if result.returncode == 0 and os.path.exists(png):
            break
        print("--- %s %s (%s), attempt %d, status %d:\n%s"
              % (script, scene, "switched" if switched else "stock", attempt + 1,
                 result.returncode, result.stdout[-3000:]))
    else:
        return None
    lines = result.stdout.splitlines()
    mappers = [l.split(": ", 1)[1] for l in lines if l.startswith("mapper: ")]
    delegators = [l.split(": ", 1)[1] for l in lines if l.startswith("delegator: ")]
    modes = [l.split(": ", 1)[1] for l in lines if l.startswith("budget: ")]
    return mappers, delegators, modes


def drawn_by_phong(mappers, delegators):
    """Whether every actor's mapper is vtkPhong's (or, VTK >= 9.3, VTK's composite mapper
    whose block drawers are vtkPhong's)."""
    def phong(name):
        if any(p in name for p in PHONG_DRAWERS):
            return True
        return name == "vtkCompositePolyDataMapper" and delegators == ["vtkPhongCompositeDelegator"]
    return bool(mappers) and all(phong(m) for m in mappers)


def not_empty(pixels):
    """At least 2 % of the pixels more than 8 levels from the background (the corner)."""
    background = pixels[0, 0]
    return float((numpy.abs(pixels - background).max(axis=2) > LEVELS).mean()) >= 0.02


def next_to_background(pixels):
    """Pixels with a neighbour (3 x 3) of the background's colour (the corner's)."""
    background = numpy.abs(pixels - pixels[0, 0]).max(axis=2) <= 2
    padded = numpy.pad(background, 1, mode="edge")
    height, width = background.shape
    near = numpy.zeros_like(background)
    for dy in range(3):
        for dx in range(3):
            near |= padded[dy:dy + height, dx:dx + width]
    return near & ~background


def check_budget(checks, name, client, script, scene, base, phong):
    """The third run, under BUDGET: its table cells, or None where it did not draw."""
    run = run_scene(script, scene, base + ".budget.png", True, BUDGET)
    checks.expect(run is not None, name + ": the run under a budget drew")
    if run is None:
        return None
    budget = read_png(base + ".budget.png")
    checks.expect(budget.shape == phong.shape, name + ": under a budget, the same picture size")
    if budget.shape != phong.shape:
        return None
    checks.expect(drawn_by_phong(*run[:2]), name + ": under a budget, drawn by vtkPhong: %s"
                  % (run,))
    levels = numpy.abs(budget - phong).max(axis=2)
    over = levels > BUDGET + BUDGET_SLACK
    silhouette = next_to_background(phong)
    percent = 100.0 * float(over.mean())
    checks.expect(not (over & ~silhouette).any() and percent <= SILHOUETTE_PERCENT,
                  "%s: under a budget of %g levels, within %g levels of the exact picture but "
                  "for at most %g %% of silhouette pixels (%d pixels beyond, %d of them off "
                  "the silhouette, largest %d levels)"
                  % (name, BUDGET, BUDGET + BUDGET_SLACK, SILHOUETTE_PERCENT, int(over.sum()),
                     int((over & ~silhouette).sum()), int(levels.max())))
    modes = sorted(set(run[2])) or ["-"]
    if (client, scene) in BUDGET_PER_VERTEX:
        checks.expect(any("per vertex" in mode for mode in modes),
                      name + ": under a budget, light sums per vertex: %s" % (modes,))
    return "%d | %d | %s" % (int(levels.max()), int(over.sum()), ", ".join(modes))


def short(names):
    return ", ".join(sorted(set(n.replace("vtkOpenGL", "GL").replace("vtkPhong", "Phong")
                                .replace("vtkDataSetMapper>", "DataSet>")
                                for n in names))) or "-"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("-T", dest="temporary", required=True)
    parser.add_argument("--only", nargs="*", default=None)
    args = parser.parse_args()
    os.makedirs(args.temporary, exist_ok=True)
    checks = Checks()
    rows = []
    ran = 0
    for client in ("vedo", "pyvista"):
        version = version_of(client)
        if version is None:
            continue
        script = os.path.join(HERE, client + "_scenes.py")
        scenes = [key[1] for key in EXPECTATIONS if key[0] == client]
        for scene in scenes:
            if args.only and scene not in args.only:
                continue
            ran += 1
            base = os.path.join(args.temporary, "Clients_%s_%s" % (client, scene))
            stock_run = run_scene(script, scene, base + ".stock.png", False)
            phong_run = run_scene(script, scene, base + ".phong.png", True)
            name = "%s %s %s" % (client, version, scene)
            checks.expect(stock_run is not None, name + ": the stock run drew")
            checks.expect(phong_run is not None, name + ": the switched run drew")
            if stock_run is None or phong_run is None:
                continue
            stock = read_png(base + ".stock.png")
            phong = read_png(base + ".phong.png")
            checks.expect(stock.shape == phong.shape, name + ": the same picture size")
            if stock.shape != phong.shape:
                continue
            save_pair(stock, phong, base + ".pair.png")
            checks.expect(not any("Phong" in m for m in stock_run[0] + stock_run[1]),
                          name + ": the stock run drew with VTK's mappers: %s" % (stock_run,))
            checks.expect(drawn_by_phong(*phong_run[:2]),
                          name + ": the switched run drew with vtkPhong's mappers: %s"
                          % (phong_run,))
            checks.expect(not_empty(stock), name + ": the stock picture is not empty")
            checks.expect(not_empty(phong), name + ": vtkPhong's picture is not empty")
            levels = numpy.abs(stock - phong).max(axis=2)
            over = 100.0 * float((levels > LEVELS).mean())
            expectation = EXPECTATIONS[(client, scene)]
            if expectation is MATCH:
                said = "match (<= %.1f %%)" % MATCH_PERCENT
                checks.expect(over <= MATCH_PERCENT,
                              "%s: matches (%.2f %% > %d levels)" % (name, over, LEVELS))
            else:
                why, most, least = expectation
                said = "%s: %.1f..%.1f %%" % (why, least, most)
                checks.expect(least <= over <= most, "%s: %s (%.2f %% > %d levels)"
                              % (name, said, over, LEVELS))
            mappers = "%s / %s" % (short(stock_run[0] + stock_run[1]),
                                   short(phong_run[0] + phong_run[1]))
            budget = check_budget(checks, name, client, script, scene, base, phong) or "- | - | -"
            rows.append("| %s | %s %s | %s | %d | %.2f | %.2f %% | %s | %s |"
                        % (scene, client, version, mappers, int(levels.max()),
                           float(levels.mean()), over, said, budget))
    print("\nVTK %d.%d\n" % VTK)
    print("| scene | client | mappers stock / switched | max | mean | %% > 8 levels "
          "| expectation | budget %g: max | > %g | modes |" % (BUDGET, BUDGET + BUDGET_SLACK))
    print("|---|---|---|---|---|---|---|---|---|---|")
    print("\n".join(rows))
    print()
    checks.expect(ran > 0, "at least one client's scenes ran")
    checks.exit()


if __name__ == "__main__":
    main()
