"""VTK_AUTOLOAD_PATH gives a program vtkPhong's mappers with no change to its code.

The program links VTK alone (PlainVTKProgram.cxx); VTK's Python imports no vtkphong. Each is
run without the variable (VTK's mappers), then with the directory of vtkPhong's factory
library (vtkPhong's mappers), and the pictures must differ where vtkPhong's lighting differs
from VTK's and be drawn in both.
"""

import argparse
import os
import subprocess
import sys

from vtkmodules.vtkCommonCore import vtkVersion
from vtkphong_testing import Checks, read_png

parser = argparse.ArgumentParser()
parser.add_argument("--program", required=True)
parser.add_argument("--autoload", required=True)
parser.add_argument("-T", dest="temporary", required=True)
args = parser.parse_args()
checks = Checks()
os.makedirs(args.temporary, exist_ok=True)

COMPOSITE_DRAWER = ("vtkCompositePolyDataMapperDelegator"
                    if (vtkVersion.GetVTKMajorVersion(), vtkVersion.GetVTKMinorVersion()) >= (9, 3)
                    else "vtkCompositePolyDataMapper2")
PHONG_CLASS = {"vtkPolyDataMapper": "vtkPhongPolyDataMapper",
               "vtkCompositePolyDataMapper2": "vtkPhongCompositePolyDataMapper",
               "vtkCompositePolyDataMapperDelegator": "vtkPhongCompositeDelegator"}


def environment(autoload, budget=None):
    env = {k: v for k, v in os.environ.items()
           if k not in ("VTK_AUTOLOAD_PATH", "VTKPHONG_ERROR_BUDGET")}
    if autoload:
        env["VTK_AUTOLOAD_PATH"] = args.autoload
    if budget is not None:
        env["VTKPHONG_ERROR_BUDGET"] = budget
    return env


def made_classes(output):
    """{VTK class: class the factory made} from the program's 'name: class' lines."""
    made = {}
    for line in output.splitlines():
        name, _, made_class = line.partition(": ")
        if made_class:
            made.setdefault(name, set()).add(made_class.strip())
    return made


def run_program(autoload, budget=None):
    out = os.path.join(args.temporary, "TestPhongAutoload_%s%s.png"
                       % ("autoload" if autoload else "stock",
                          "_budget" if budget is not None else ""))
    result = subprocess.run([args.program, out], capture_output=True, text=True, timeout=300,
                            env=environment(autoload, budget))
    checks.expect(result.returncode == 0, "the program %s VTK_AUTOLOAD_PATH exits 0 (%d, %r)"
                  % ("with" if autoload else "without", result.returncode, result.stderr[-500:]))
    return made_classes(result.stdout), out


stock, stock_png = run_program(False)
phong, phong_png = run_program(True)
for name in ("vtkPolyDataMapper", COMPOSITE_DRAWER):
    checks.expect(stock.get(name) and not any("Phong" in c for c in stock[name]),
                  "without the variable, VTK's factory makes VTK's %s (%s)" % (name, stock.get(name)))
    checks.expect(phong.get(name) == {PHONG_CLASS[name]},
                  "with VTK_AUTOLOAD_PATH, the factory makes %s for %s (%s)"
                  % (PHONG_CLASS[name], name, phong.get(name)))
if os.path.exists(stock_png) and os.path.exists(phong_png):
    a, b = read_png(stock_png), read_png(phong_png)
    checks.expect(a.max() > 0 and b.max() > 0, "both pictures are drawn")
    # The same scene lit by VTK and by vtkPhong: identical in the diffuse, apart where the
    # exact model differs (VTK's specular on the composite's back-facing normals, ...).
    differing = int((abs(a - b).max(axis=2) > 6).sum())
    print("stock and autoloaded pictures: %d pixels differ by more than 6 levels" % differing)

# An error budget with no change to the program: VTKPHONG_ERROR_BUDGET. At 255 levels its
# coarse spheres go per vertex (their bound is about 134 levels), so the picture moves off
# the exact one; measured 149 pixels by more than 2 levels, at most 29.
_, budget_png = run_program(True, "255")
if os.path.exists(phong_png) and os.path.exists(budget_png):
    exact, budgeted = read_png(phong_png).astype(int), read_png(budget_png).astype(int)
    moved = int((abs(exact - budgeted).max(axis=2) > 2).sum())
    checks.expect(moved > 20, "VTKPHONG_ERROR_BUDGET=255 reaches the autoloaded mappers: %d "
                  "pixels moved by more than 2 levels off the exact picture" % moved)

# VTK's own Python, vtkphong not imported.
script = ("from vtkmodules.vtkRenderingCore import vtkPolyDataMapper\n"
          "import vtkmodules.vtkRenderingOpenGL2\n"
          "print('vtkPolyDataMapper: ' + vtkPolyDataMapper().GetClassName())\n")
for autoload in (False, True):
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                            timeout=120, env=environment(autoload))
    made = made_classes(result.stdout).get("vtkPolyDataMapper")
    expected = {"vtkPhongPolyDataMapper"} if autoload else {"vtkOpenGLPolyDataMapper"}
    checks.expect(result.returncode == 0 and made == expected,
                  "VTK's Python %s VTK_AUTOLOAD_PATH: vtkPolyDataMapper() is %s (%s, %r)"
                  % ("with" if autoload else "without", expected, made, result.stderr[-300:]))
checks.exit()
