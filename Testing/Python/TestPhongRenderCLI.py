"""vtkphong-render, the command-line renderer, as a user runs it: every input
format (files made here), its .mtl colours and unclamped Ns shininess, PNG and
EXR output, flags and scene files, debug views, the progress line, --help,
and every error path (one line on stderr, a non-zero status, never a crash).

    TestPhongRenderCLI.py <build>/bin/vtkphong-render -T <temporary>
"""

import argparse
import json
import os
import signal
import struct
import subprocess
import time

import vtkphong
from vtkmodules.vtkCommonCore import vtkUnsignedCharArray, vtkVersion
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkAppendFilter, vtkTriangleFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOGeometry import vtkSTLWriter
from vtkmodules.vtkIOLegacy import vtkPolyDataWriter, vtkUnstructuredGridWriter
from vtkmodules.vtkIOPLY import vtkPLYWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
from vtkphong_testing import Checks

parser = argparse.ArgumentParser()
parser.add_argument("cli")
parser.add_argument("-B", dest="baselines")
parser.add_argument("-T", dest="temporary", required=True)
args = parser.parse_args()
checks = Checks()
folder = os.path.join(args.temporary, "TestPhongRenderCLI")
os.makedirs(folder, exist_ok=True)


def path(name):
    return os.path.join(folder, name)


def run(*arguments, environment=None):
    # Bytes, decoded here: text mode would turn the progress line's carriage returns into
    # newlines.
    result = subprocess.run([args.cli] + [str(a) for a in arguments], capture_output=True,
                            timeout=300, env=environment)
    result.stdout = result.stdout.decode("utf-8", "replace")
    result.stderr = result.stderr.decode("utf-8", "replace")
    return result


def read(image_file):
    image = vtkImageData()
    checks.expect(vtkphong.vtkPhongImageIO().ReadImage(image_file, image) == 1,
                  "read " + image_file)
    return image


def pixels(image):
    """Rows of (r, g, b[, a]) tuples in [0, 1]."""
    scalars = image.GetPointData().GetScalars()
    scale = 255.0 if scalars.GetDataTypeAsString() == "unsigned char" else 1.0
    count = scalars.GetNumberOfComponents()
    return [tuple(scalars.GetComponent(i, c) / scale for c in range(count))
            for i in range(scalars.GetNumberOfTuples())]


BACKGROUND = (0.12, 0.12, 0.14)


def covered(values):
    """The pixels that are not the default background."""
    return [p for p in values if max(abs(p[c] - BACKGROUND[c]) for c in range(3)) > 0.02]


# --- input files -----------------------------------------------------------

sphere = vtkSphereSource()
sphere.SetThetaResolution(48)
sphere.SetPhiResolution(48)
triangles = vtkTriangleFilter()
triangles.SetInputConnection(sphere.GetOutputPort())
triangles.Update()
mesh = triangles.GetOutput()
points = [mesh.GetPoint(i) for i in range(mesh.GetNumberOfPoints())]
faces = []
for i in range(mesh.GetNumberOfCells()):
    ids = mesh.GetCell(i).GetPointIds()
    faces.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])


def write_obj(name, materials):
    """A sphere in materials[0] (its upper half only when a second material paints the
    lower half)."""
    with open(path(name + ".mtl"), "w") as mtl:
        for index, (color, shininess) in enumerate(materials):
            mtl.write("newmtl m%d\nKa 0 0 0\nKd %g %g %g\nKs 1 1 1\nNs %g\nillum 2\n\n"
                      % ((index,) + tuple(color) + (shininess,)))
    groups = [faces] if len(materials) == 1 else [
        [f for f in faces if sum(points[k][2] for k in f) >= 0.0],
        [f for f in faces if sum(points[k][2] for k in f) < 0.0]]
    with open(path(name + ".obj"), "w") as obj:
        obj.write("mtllib %s.mtl\n" % name)
        for p in points:
            obj.write("v %.9g %.9g %.9g\n" % p)
        for index, group in enumerate(groups):
            obj.write("usemtl m%d\n" % index)
            for face in group:
                obj.write("f %s\n" % " ".join(str(k + 1) for k in face))
    return path(name + ".obj")


two_colours = write_obj("halves", [((1, 0, 0), 10), ((0, 0, 1), 1000)])
dull = write_obj("dull", [((0.6, 0.6, 0.6), 5)])
sharp = write_obj("sharp", [((0.6, 0.6, 0.6), 2000)])
sharper_than_vtk = write_obj("ns200", [((0.6, 0.6, 0.6), 200)])

colors = vtkUnsignedCharArray()
colors.SetName("RGB")
colors.SetNumberOfComponents(3)
for i in range(mesh.GetNumberOfPoints()):
    colors.InsertNextTuple3(30, 200, 60)
coloured = vtkPolyData()
coloured.DeepCopy(mesh)
coloured.GetPointData().SetScalars(colors)
ply = vtkPLYWriter()
ply.SetInputData(coloured)
ply.SetArrayName("RGB")
ply.SetFileName(path("green.ply"))
ply.Write()

for mode in ("ascii", "binary"):
    stl = vtkSTLWriter()
    stl.SetInputData(mesh)
    stl.SetFileName(path("sphere-%s.stl" % mode))
    getattr(stl, "SetFileTypeTo" + ("ASCII" if mode == "ascii" else "Binary"))()
    stl.Write()

with open(path("sphere.off"), "w") as off:
    off.write("OFF\n%d %d 0\n" % (len(points), len(faces)))
    for p in points:
        off.write("%.9g %.9g %.9g\n" % p)
    for face in faces:
        off.write("%d %s\n" % (len(face), " ".join(map(str, face))))

vtp = vtkXMLPolyDataWriter()
vtp.SetInputData(mesh)
vtp.SetFileName(path("sphere.vtp"))
vtp.Write()
legacy = vtkPolyDataWriter()
legacy.SetInputData(mesh)
legacy.SetFileName(path("sphere.vtk"))
legacy.Write()
grid = vtkAppendFilter()  # an unstructured grid: the CLI draws its surface
grid.SetInputData(mesh)
grid.Update()
grid_writer = vtkUnstructuredGridWriter()
grid_writer.SetInputData(grid.GetOutput())
grid_writer.SetFileName(path("grid.vtk"))
grid_writer.Write()

# --- every format renders --------------------------------------------------

inputs = [two_colours, path("green.ply"), path("sphere-ascii.stl"), path("sphere-binary.stl"),
          path("sphere.off"), path("sphere.vtp"), path("sphere.vtk"), path("grid.vtk")]
for mesh_file in inputs:
    name = os.path.basename(mesh_file)
    output = path(name + ".png")
    result = run(mesh_file, "-o", output, "--size", "160x120")
    checks.expect(result.returncode == 0, "%s renders (status %d: %s)"
                  % (name, result.returncode, result.stderr.strip()))
    checks.expect(result.stdout.strip() == output, "%s: the output path is printed" % name)
    checks.expect(result.stderr == "", "%s: nothing on stderr (%r)" % (name, result.stderr))
    if os.path.exists(output):
        image = read(output)
        checks.expect(image.GetDimensions()[:2] == (160, 120), "%s: --size 160x120" % name)
        checks.expect(image.GetNumberOfScalarComponents() == 3, "%s: an RGB PNG" % name)
        share = len(covered(pixels(image))) / (160.0 * 120.0)
        checks.expect(0.15 < share < 0.7, "%s: the mesh fills the view (%.2f)" % (name, share))

halves = pixels(read(path("halves.obj.png")))
checks.expect(any(p[0] > 0.5 and p[2] < 0.2 for p in halves), "the .mtl's red half shows")
checks.expect(any(p[2] > 0.5 and p[0] < 0.2 for p in halves), "the .mtl's blue half shows")
greens = covered(pixels(read(path("green.ply.png"))))
checks.expect(sum(1 for p in greens if p[1] > p[0] and p[1] > p[2]) > 0.9 * len(greens),
              "the PLY's vertex colours are used")


# Ns is honoured unclamped: a highlight of Ns 2000 is smaller than one of Ns 200
# (VTK's importer clamps both to 128), which is smaller than one of Ns 5.
def highlight_pixels(obj):
    output = obj + ".png"
    run(obj, "-o", output, "--size", "160x120", "--quiet")
    return sum(1 for p in pixels(read(output)) if min(p[:3]) > 0.75)


bright = [highlight_pixels(obj) for obj in (dull, sharper_than_vtk, sharp)]
checks.expect(bright[0] > bright[1] > bright[2], "Ns 5 > 200 > 2000 in highlight size: %s"
              % bright)

# --- flags, scene files, outputs ---------------------------------------------

exr = path("emissive.exr")
result = run(path("sphere.off"), "-o", exr, "--size", "120x90", "--emission", "2,2,2",
             "--quiet")
checks.expect(result.returncode == 0 and result.stdout == "", "EXR output, --quiet")
if os.path.exists(exr):
    image = read(exr)
    checks.expect(image.GetScalarType() == 10 and image.GetNumberOfScalarComponents() == 4,
                  "EXR holds float RGBA")
    checks.expect(max(p[0] for p in pixels(image)) > 2.0, "EXR keeps values above 1")

scene_file = path("scene.json")
with open(scene_file, "w") as stream:
    json.dump({"size": [200, 150], "background": [1, 0, 0], "lobe": "phong",
               "material": {"color": [0, 0, 1], "specular": 0.0},
               "camera": {"azimuth": 0, "elevation": 0, "zoom": 0.5},
               "lights": [{"type": "point", "position": [0, 0, 3], "intensity": 1.5,
                           "attenuation": [1, 0, 0]},
                          {"kind": "headlight", "type": "directional", "intensity": 0.2}]},
              stream)
output = path("scene.png")
result = run(two_colours, "-o", output, "--scene", scene_file)
checks.expect(result.returncode == 0, "a scene file renders (%s)" % result.stderr.strip())
if os.path.exists(output):
    image = read(output)
    values = pixels(image)
    checks.expect(image.GetDimensions()[:2] == (200, 150), "the scene file's size")
    checks.expect(values[0][:3] == (1.0, 0.0, 0.0), "the scene file's background")
    blue = [p for p in values if p[:3] != (1.0, 0.0, 0.0)]
    checks.expect(blue and all(p[0] < 0.05 and p[1] < 0.05 for p in blue),
                  "the scene file's colour overrides the .mtl, no highlight (specular 0)")
    checks.expect(len(blue) < 0.25 * len(values), "the scene file's zoom 0.5")
result = run(two_colours, "-o", output, "--scene", scene_file, "--size", "64x48",
             "--background", "0,1,0", "--quiet")
checks.expect(result.returncode == 0 and read(output).GetDimensions()[:2] == (64, 48)
              and pixels(read(output))[0][:3] == (0.0, 1.0, 0.0),
              "flags win over the file (status %d, %r)" % (result.returncode, result.stderr))

output = path("normal.png")
run(path("sphere.off"), "-o", output, "--size", "120x90", "--debug-view", "normal",
    "--transparent", "--quiet")
values = pixels(read(output))
checks.expect(len(values[0]) == 4 and values[0][3] == 0.0,
              "--transparent: RGBA, the background transparent")
checks.expect(any(p[3] > 0 and p[0] > 0.7 and p[2] > 0.7 for p in values)
              and any(p[3] > 0 and p[1] > 0.7 for p in values),
              "--debug-view normal shows normals as colours")

output = path("budget.png")
run(path("sphere.off"), "-o", output, "--size", "120x90", "--debug-view", "budget-use",
    "--error-budget", "1", "--transparent", "--quiet")
budget_colours = {p[:3] for p in pixels(read(output)) if p[3] > 0}
checks.expect(len(budget_colours) == 1 and
              all(p[0] == 0.0 and p[2] > p[1] > 0.0 for p in budget_colours),
              "--debug-view budget-use draws the surface in one blue (per fragment): %r"
              % sorted(budget_colours)[:4])

output = path("lights.png")
result = run(path("sphere.off"), "-o", output, "--size", "120x90", "--quiet", "--light",
             "spot:0,0,3:1,0.5,0:2", "--light", "directional:-1,1,1", "--lobe",
             "normalized-phong", "--interpolation", "per-vertex-gouraud", "--shininess",
             "5000", "--color", "0.5,0.5,0.5", "--normals-weighting", "angle",
             "--feature-angle", "45", "--azimuth", "-40", "--elevation", "10", "--zoom", "1.2",
             "--error-budget", "2", "--specular-aa")
checks.expect(result.returncode == 0, "every flag at once (%s)" % result.stderr.strip())

# A highlight narrower than a pixel: --specular-aa (and the scene file's "specular_aa")
# average it over its pixel, so the picture changes; without either it stays the exact one.
highlights = {}
scene_aa = path("specular-aa.json")
with open(scene_aa, "w") as stream:
    json.dump({"specular_aa": True}, stream)
for name, extra in (("exact", ()), ("flag", ("--specular-aa",)), ("scene", ("--scene", scene_aa))):
    output = path("highlight-%s.png" % name)
    result = run(path("sphere.off"), "-o", output, "--size", "120x90", "--quiet",
                 "--shininess", "20000", "--specular", "1", *extra)
    highlights[name] = pixels(read(output)) if result.returncode == 0 else None
checks.expect(highlights["exact"] is not None and highlights["flag"] is not None
              and highlights["flag"] != highlights["exact"]
              and highlights["scene"] == highlights["flag"],
              "--specular-aa and the scene file's specular_aa average a narrow highlight")

# --- progress, help ------------------------------------------------------------

big = vtkSphereSource()
big.SetThetaResolution(340)
big.SetPhiResolution(340)
big_writer = vtkSTLWriter()
big_writer.SetInputConnection(big.GetOutputPort())
big_writer.SetFileTypeToBinary()
big_writer.SetFileName(path("big.stl"))
big_writer.Write()
result = run(path("big.stl"), "-o", path("big.png"), "--size", "120x90")
checks.expect(result.returncode == 0 and "reading" in result.stderr and "%" in result.stderr
              and "computing normals" in result.stderr,
              "a progress line for a big mesh: %r" % result.stderr[-200:])
checks.expect(result.stderr.endswith("\n") and result.stderr.count("\n") == 1,
              "the progress line is one line, rewritten with carriage returns")

result = run("--help")
checks.expect(result.returncode == 0, "--help succeeds")
for option in ("--output", "--scene", "--size", "--background", "--transparent", "--lobe",
               "--interpolation", "--color", "--ambient", "--diffuse", "--specular",
               "--shininess", "--emission", "--light", "--azimuth", "--elevation", "--zoom",
               "--debug-view", "--debug-light", "--normals-weighting", "--feature-angle",
               "--error-budget", "--specular-aa", "--quiet", "scene file", "exit status", ".obj", ".exr", "headlight"):
    checks.expect(option in result.stdout, "--help documents " + option)

# --- errors: one line, a non-zero status, no crash ------------------------------

garbage = os.urandom(3000)
for extension in ("stl", "ply", "obj", "off", "vtp", "vtk"):
    with open(path("garbage." + extension), "wb") as stream:
        stream.write(garbage)
with open(path("bad-syntax.json"), "w") as stream:
    stream.write("{oops")
with open(path("bad-value.json"), "w") as stream:
    json.dump({"material": {"shininess": -3}}, stream)
with open(path("bad-key.json"), "w") as stream:
    json.dump({"lights": [{"type": "laser", "position": [0, 0, 1]}]}, stream)
with open(path("missing-mtl.obj"), "w") as stream:
    stream.write("mtllib nowhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n")
with open(path("truncated.stl"), "wb") as stream:
    stream.write(b"\0" * 80 + struct.pack("<I", 1000) + b"\0" * 500)

# What fuzzing found in the readers the command used before: coordinates that overflow the
# camera's arithmetic, cells naming points that do not exist (VTK's bounds crashed on them;
# the legacy file's cells are now refused before VTK's reader reads them).
with open(path("huge.off"), "w") as stream:
    stream.write("OFF\n3 1 0\n0 0 0\n1e308 0 0\n0 1e308 0\n3 0 1 2\n")
with open(path("bad-cell.vtk"), "w") as stream:
    stream.write("# vtk DataFile Version 3.0\nbad\nASCII\nDATASET POLYDATA\n"
                 "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 7000000\n")

good = path("sphere.off")
out = path("error.png")
cases = [
    ((path("nothing.off"), "-o", out), 1, "no such file"),
    ((path("sphere.xyz"), "-o", out), 1, "unknown extension"),
    ((path("truncated.stl"), "-o", out), 1, "truncated.stl: "),
    ((path("huge.off"), "-o", out), 1, "beyond 1e+30"),
    ((path("bad-cell.vtk"), "-o", out), 1, "names point 7000000; the file has 3 points"),
    ((good, "-o", path("image.jpg")), 2, ".png or .exr"),
    ((good, "-o", path("no-such-folder/image.png")), 1, "no directory"),
    ((good,), 2, "-o"),
    ((good, "-o", out, "--bogus"), 2, "--bogus"),
    ((good, "-o", out, "--size", "0x10"), 2, "--size"),
    ((good, "-o", out, "--size", "big"), 2, "--size"),
    ((good, "-o", out, "--color", "1,2"), 2, "colour"),
    ((good, "-o", out, "--color", "nan,0,0"), 2, "finite"),
    ((good, "-o", out, "--specular", "2"), 2, "--specular"),
    ((good, "-o", out, "--error-budget", "-1"), 2, "--error-budget"),
    ((good, "-o", out, "--error-budget", "nan"), 2, "--error-budget"),
    ((good, "-o", out, "--light", "laser:1,1,1"), 2, "--light"),
    ((good, "-o", out, "--lobe", "cook-torrance"), 2, "--lobe"),
    ((good, "-o", out, "--debug-view", "depth"), 2, "--debug-view"),
    ((good, "-o", out, "--scene", path("nothing.json")), 2, "scene file"),
    ((good, "-o", out, "--scene", path("bad-syntax.json")), 2, "not valid JSON"),
    ((good, "-o", out, "--scene", path("bad-value.json")), 2, "material.shininess"),
    ((good, "-o", out, "--scene", path("bad-key.json")), 2, "lights[0].type"),
] + [((path("garbage." + e), "-o", out), 1, "garbage." + e)
     for e in ("stl", "ply", "obj", "off", "vtp", "vtk")]
for arguments, status, words in cases:
    result = run(*arguments)
    label = " ".join(os.path.basename(str(a)) for a in arguments)
    lines = result.stderr.splitlines()
    checks.expect(result.returncode == status,
                  "%s: status %d (got %d)" % (label, status, result.returncode))
    checks.expect(len(lines) == 1 and lines[0].startswith("vtkphong-render: error: ")
                  and words in lines[0], "%s: one error line naming %r, got %r"
                  % (label, words, result.stderr))


def children_of(pid):
    try:
        with open("/proc/%d/task/%d/children" % (pid, pid)) as stream:
            return [int(child) for child in stream.read().split()]
    except OSError:
        return []


# A crash after reading (in VTK, the OpenGL driver, the writer) is one error line too: the
# command renders in a child process, here killed by SIGSEGV while it works.
command = subprocess.Popen([args.cli, good, "-o", path("killed.png"), "--size", "1600x1200"],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE)
renderer = []
deadline = time.time() + 60
while not renderer and command.poll() is None and time.time() < deadline:
    renderer = children_of(command.pid)
    time.sleep(0.002)
if renderer:
    os.kill(renderer[0], signal.SIGSEGV)
stdout, stderr = command.communicate(timeout=300)
lines = stderr.decode("utf-8", "replace").splitlines()
checks.expect(bool(renderer), "the command renders in a child process")
checks.expect(command.returncode == 1 and len(lines) == 1
              and "the renderer crashed (SIGSEGV) on " + good in lines[0],
              "a crashed renderer: status 1 and one error line (status %d, %r)"
              % (command.returncode, lines))

environment = dict(os.environ)
environment.pop("DISPLAY", None)
result = run(good, "-o", out, environment=environment)
checks.expect(result.returncode == 1 and "X display" in result.stderr,
              "no display: one error line (%r)" % result.stderr)



def unused_display():
    """A display number no X server listens on."""
    number = 1999
    while any(os.path.exists(name % number) for name in ("/tmp/.X11-unix/X%d", "/tmp/.X%d-lock")):
        number += 1
    return ":%d" % number


# An X server that refuses the connection: VTK 9.1 would abort the renderer; the command
# tries again for a few seconds, then says so in one line.
environment = dict(os.environ, DISPLAY=unused_display())
result = run(good, "-o", out, environment=environment)
checks.expect(result.returncode == 1 and result.stderr.count("\n") == 1
              and "cannot connect to the X display " + environment["DISPLAY"] in result.stderr,
              "a display that refuses: one error line (%r)" % result.stderr)

# An X server that starts while the command tries (as one busy server accepts late): it
# renders.
display = unused_display()
command = subprocess.Popen([args.cli, good, "-o", path("late-display.png"), "--quiet"],
                           env=dict(os.environ, DISPLAY=display),
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE)
time.sleep(1.0)
server = subprocess.Popen(["Xvfb", display, "-screen", "0", "640x480x24", "-nolisten", "tcp",
                           "-noreset"],
                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
try:
    stdout, stderr = command.communicate(timeout=120)
finally:
    server.terminate()
    server.wait(timeout=30)
checks.expect(command.returncode == 0 and len(covered(pixels(read(path("late-display.png"))))) > 0,
              "a display that accepts late: rendered (status %d, %r)"
              % (command.returncode, stderr))

# When VTK itself aborts the renderer (here: no connection made by the command first, and a
# display that refuses), the error line carries what VTK said before it died. From VTK 9.4 on,
# a window that cannot reach X falls back to EGL or OSMesa and VTK does not abort: the
# picture must then be drawn.
package = os.path.normpath(os.path.join(os.path.dirname(os.path.realpath(args.cli)),
                                        "../lib/python3/dist-packages"))
script = ("import sys, vtkphong._rendering as rendering\n"
          "rendering._libx11 = lambda: None\n"
          "from vtkphong.render import main\n"
          "sys.exit(main(sys.argv[1:], isolated=True))\n")
python_path = package + os.pathsep + os.environ.get("PYTHONPATH", "")
fallback_out = path("no-display.png")
result = subprocess.run(["/usr/bin/python3", "-c", script, good, "-o", fallback_out],
                        capture_output=True, timeout=300, text=True,
                        env=dict(os.environ, DISPLAY=unused_display(), PYTHONPATH=python_path))
if (vtkVersion.GetVTKMajorVersion(), vtkVersion.GetVTKMinorVersion()) >= (9, 4):
    checks.expect(result.returncode == 0 and os.path.exists(fallback_out)
                  and len(covered(pixels(read(fallback_out)))) > 0,
                  "no X display, VTK's fallback window: rendered (status %d, %r)"
                  % (result.returncode, result.stderr))
else:
    checks.expect(result.returncode == 1 and result.stderr.count("\n") == 1
                  and "the renderer crashed (SIGABRT)" in result.stderr
                  and "after VTK's error: bad X server connection" in result.stderr,
                  "VTK's abort: one error line with VTK's reason (%r)" % result.stderr)

result = run(path("missing-mtl.obj"), "-o", path("missing-mtl.png"), "--quiet")
checks.expect(result.returncode == 0 and result.stderr.startswith("vtkphong-render: warning: ")
              and "nowhere.mtl" in result.stderr and result.stderr.count("\n") == 1,
              "a missing .mtl: one warning, the default material (%r)" % result.stderr)

# A material name that is not UTF-8 (the command used to fail with a TypeError on it).
with open(path("latin1.mtl"), "wb") as stream:
    stream.write(b"newmtl M\xe9tal\nKd 0.9 0.1 0.1\nKs 0.5 0.5 0.5\nNs 200\n")
with open(path("latin1.obj"), "wb") as stream:
    stream.write(b"mtllib latin1.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl M\xe9tal\nf 1 2 3\n")
result = run(path("latin1.obj"), "-o", path("latin1.png"), "--quiet")
checks.expect(result.returncode == 0 and result.stderr == "",
              "a material name in Latin-1 renders (%r)" % result.stderr)


# Under an address-space limit (ulimit -v), as batch systems and containers set one: the
# reading child's limit must stay within the inherited one (setrlimit cannot raise a hard
# limit, and the default asks for half the RAM). assimp's own test model, a file not made here.
def run_limited(limit_kb, *arguments):
    import resource

    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (limit_kb << 10, limit_kb << 10))

    result = subprocess.run([args.cli] + [str(a) for a in arguments], capture_output=True,
                            timeout=300, preexec_fn=limit)
    result.stderr = result.stderr.decode("utf-8", "replace")
    return result


spider = "/usr/share/assimp/models/STL/Spider_binary.stl"  # Debian's assimp-testmodels
if not os.path.exists(spider):
    spider = path("sphere-binary.stl")
result = run_limited(6000000, spider, "-o", path("limited.png"), "--quiet")
checks.expect(result.returncode == 0 and result.stderr == "" and
              len(covered(pixels(read(path("limited.png"))))) > 0,
              "ulimit -v 6000000 (5.7 GB): a valid file renders (%r)" % result.stderr)
# Too little to render at all: one line naming the file, status 1 (never a traceback).
for limit_kb in (800000, 400000):
    result = run_limited(limit_kb, spider, "-o", path("starved.png"), "--quiet")
    lines = result.stderr.splitlines()
    checks.expect(result.returncode == 0 or (
        result.returncode == 1 and len(lines) == 1 and spider in lines[0]
        and lines[0].startswith("vtkphong-render: error: ")),
        "ulimit -v %d: renders or one error line naming the file (%r)" % (limit_kb, lines))
checks.exit()
