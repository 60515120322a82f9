#!/bin/bash
# PyVista's own plotting tests, run twice against the installed PyVista and VTK: once stock,
# once with `import vtkphong.overrides` done first in every Python process (a sitecustomize.py
# put first on PYTHONPATH), so that the tests run unchanged and every vtkPolyDataMapper that
# VTK's factory makes is vtkPhong's. Prints pass/fail/skip/error counts for both runs and the
# tests whose outcome differs.
#
#   run_pyvista_suite.sh TESTS_DIR OUT_DIR [pytest args...]
#
# Meant to run inside the Debian root that has python3-pyvista, python3-vtk9, xvfb,
# python3-pytest (+ python3-hypothesis python3-pytest-cases python3-pytest-mock
# python3-scipy python3-imageio-ffmpeg python3-colorcet) and a vtkPhong build.
#   TESTS_DIR  PyVista's tests/ directory (a source checkout's; its parent holds the
#              pyproject.toml with the pytest settings and tests/plotting/image_cache).
#   OUT_DIR    created; gets stock/ and switched/ (one junit XML and log per test module,
#              failed images), stock.xml, switched.xml (merged) and summary.txt.
# Environment:
#   VTKPHONG_PYTHONPATH  where the vtkphong package is
#                        (default /work/main/build-forky/lib/python3/dist-packages)
#   PYTEST_PYVISTA_SRC   a source copy of pytest-pyvista (the plugin PyVista's image tests
#                        need; not packaged by Debian), the directory holding pytest_pyvista/
#                        (default: TESTS_DIR/../../pytest-pyvista); unused if python3 can
#                        already import pytest_pyvista
#   MODULE_TIMEOUT       seconds per test module per run (default 3600)
#   TEST_MODULES         test modules to run, relative to TESTS_DIR (default: every
#                        plotting/**/test_*.py)
#   ONLY                 "stock" or "switched" to run one side only (the other's XML, if
#                        already in OUT_DIR, is still compared)
# The pytest cache goes to OUT_DIR (pytest-pyvista needs the cache provider, so no
# -p no:cacheprovider). Each test module runs in a pytest process of its own, so a crash (a segfault in a render)
# loses that module's results only; it is reported as a crashed module, and the other
# modules and the other run go on.
set -u

if [ $# -lt 2 ]; then
    sed -n '2,30p' "$0" | sed 's/^# \{0,1\}//'
    exit 2
fi
TESTS_DIR=$(cd "$1" && pwd) || { echo "no tests directory $1" >&2; exit 2; }
mkdir -p "$2" && OUT=$(cd "$2" && pwd) || { echo "cannot create $2" >&2; exit 2; }
shift 2
ROOT=$(dirname "$TESTS_DIR")
VTKPHONG_PYTHONPATH=${VTKPHONG_PYTHONPATH:-/work/main/build-forky/lib/python3/dist-packages}
PYTEST_PYVISTA_SRC=${PYTEST_PYVISTA_SRC:-$(dirname "$ROOT")/pytest-pyvista}
MODULE_TIMEOUT=${MODULE_TIMEOUT:-3600}
ONLY=${ONLY:-}

[ -d "$TESTS_DIR/plotting" ] || { echo "$TESTS_DIR has no plotting/" >&2; exit 2; }

# Helpers, written into OUT_DIR (nothing is written into the sources).
SUP="$OUT/_support"
mkdir -p "$SUP/switch" "$SUP/plugins"
cat > "$SUP/switch/sitecustomize.py" <<'EOF'
# Put first on PYTHONPATH: every Python process starts with vtkPhong's factory overrides on.
import vtkphong.overrides  # noqa: F401
EOF
cat > "$SUP/plugins/pvcompat.py" <<'EOF'
"""pytest plugin (-p pvcompat): test sources newer or older than the installed PyVista may
import PyVista's private VTK namespaces under their other name (pyvista.core._vtk_core,
pyvista.plotting._vtk vs pyvista._vtk). Aliases a missing one to the one that exists; edits
no file."""
import importlib
import sys

import pyvista  # noqa: F401

_names = ("pyvista._vtk", "pyvista.core._vtk_core", "pyvista.plotting._vtk")
_have = {}
for _n in _names:
    try:
        _have[_n] = importlib.import_module(_n)
    except ImportError:
        pass
if _have:
    _src = next(iter(_have.values()))
    for _n in _names:
        if _n not in _have:
            sys.modules[_n] = _src
            _parent, _, _child = _n.rpartition(".")
            setattr(importlib.import_module(_parent), _child, _src)
EOF
cat > "$SUP/probe.py" <<'EOF'
import pyvista as pv
import vtkmodules.vtkRenderingCore as rc
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the factory overrides of OpenGL2)
pl = pv.Plotter(off_screen=True, window_size=(64, 64))
actor = pl.add_mesh(pv.Sphere())
pl.screenshot(return_img=True)
inner = actor.mapper.GetPolyDataMapper() if hasattr(actor.mapper, "GetPolyDataMapper") else None
print("pyvista", pv.__version__, "vtk", pv.vtk_version_info,
      "| factory vtkPolyDataMapper():", rc.vtkPolyDataMapper().GetClassName(),
      "| add_mesh mapper:", actor.mapper.GetClassName(),
      ">", inner.GetClassName() if inner is not None else None)
pl.close()
EOF

PLUGIN_PATH="$SUP/plugins"
if ! python3 -c 'import pytest_pyvista' 2>/dev/null; then
    if [ -d "$PYTEST_PYVISTA_SRC/pytest_pyvista" ]; then
        PLUGIN_PATH="$PLUGIN_PATH:$PYTEST_PYVISTA_SRC"
    else
        echo "pytest_pyvista is not importable and PYTEST_PYVISTA_SRC=$PYTEST_PYVISTA_SRC has no pytest_pyvista/" >&2
        exit 2
    fi
fi

MODULES=${TEST_MODULES:-$(cd "$TESTS_DIR" && find plotting -name 'test_*.py' | LC_ALL=C sort)}

run_side() {  # $1 = stock | switched
    local side=$1 dir="$OUT/$1" pp mod name rc
    shift
    if [ "$side" = switched ]; then
        pp="$SUP/switch:$VTKPHONG_PYTHONPATH:$PLUGIN_PATH"
    else
        pp="$PLUGIN_PATH"
    fi
    rm -rf "$dir"; mkdir -p "$dir"
    echo "== $side: $(PYTHONPATH=$pp timeout 120 xvfb-run -a python3 "$SUP/probe.py" 2>&1 | tail -1)"
    if [ "$side" = switched ] && ! PYTHONPATH=$pp python3 -c \
            'import vtkmodules.vtkRenderingOpenGL2, vtkmodules.vtkRenderingCore as r; assert "Phong" in r.vtkPolyDataMapper().GetClassName()'; then
        echo "the switch did not take (VTKPHONG_PYTHONPATH=$VTKPHONG_PYTHONPATH); switched run skipped" >&2
        return 1
    fi
    local t0=$SECONDS
    for mod in $MODULES; do
        name=$(echo "${mod%.py}" | tr '/' '.')
        ( cd "$ROOT" && PYTHONPATH=$pp timeout -k 30 "$MODULE_TIMEOUT" xvfb-run -a \
            python3 -X faulthandler -m pytest "tests/$mod" -q -o cache_dir="$dir/.pytest_cache" \
            -p pvcompat -p pytest_pyvista.pytest_pyvista \
            --rootdir "$ROOT" --junitxml "$dir/$name.xml" \
            --failed_image_dir "$dir/failed_images" --generated_image_dir "$dir/generated_images" \
            "$@" ) > "$dir/$name.log" 2>&1
        rc=$?
        echo "$rc" > "$dir/$name.rc"
        printf '  %-55s rc=%-3s %s\n' "$mod" "$rc" "$(grep -E '^[0-9]+ (passed|failed|skipped|error|deselected)|^no tests ran|[0-9]+ (passed|failed|error)' "$dir/$name.log" | tail -1)"
    done
    echo "== $side: $((SECONDS - t0)) s"
}

for side in stock switched; do
    if [ -z "$ONLY" ] || [ "$ONLY" = "$side" ]; then
        run_side "$side" "$@" || true
    fi
done

python3 - "$OUT" <<'EOF' | tee "$OUT/summary.txt"
import glob, os, sys
import xml.etree.ElementTree as ET

out = sys.argv[1]

def load(side):
    results, crashed = {}, []
    d = os.path.join(out, side)
    if not os.path.isdir(d):
        return None, []
    merged = ET.Element("testsuites")
    for rcf in sorted(glob.glob(os.path.join(d, "*.rc"))):
        base = rcf[:-3]
        rc = open(rcf).read().strip()
        xmlf = base + ".xml"
        if rc not in ("0", "1", "5") or not os.path.exists(xmlf):
            tail = open(base + ".log", errors="replace").read().strip().splitlines()[-3:]
            crashed.append((os.path.basename(base), rc, " | ".join(tail)))
        if not os.path.exists(xmlf):
            continue
        try:
            root = ET.parse(xmlf).getroot()
        except ET.ParseError as e:
            crashed.append((os.path.basename(base), rc, f"unreadable junit XML: {e}"))
            continue
        for suite in root.iter("testsuite"):
            merged.append(suite)
        for tc in root.iter("testcase"):
            key = f'{tc.get("classname", "")}::{tc.get("name", "")}'
            outcome, msg = "passed", ""
            for kind in ("failure", "error", "skipped"):
                el = tc.find(kind)
                if el is not None:
                    outcome = {"failure": "failed", "error": "error", "skipped": "skipped"}[kind]
                    msg = (el.get("message") or el.text or "").strip().replace("\n", " ")[:300]
                    break
            if outcome == "skipped" and tc.find("skipped").get("type") == "pytest.xfail":
                outcome = "xfailed"
            # a test that passed and then errored in teardown appears once with <error>
            prev = results.get(key)
            if prev is None or prev[0] == "passed":
                results[key] = (outcome, msg)
    ET.ElementTree(merged).write(os.path.join(out, side + ".xml"))
    return results, crashed

sides = {s: load(s) for s in ("stock", "switched")}
kinds = ("passed", "failed", "error", "skipped", "xfailed")
for side, (res, crashed) in sides.items():
    if res is None:
        print(f"{side}: not run")
        continue
    counts = {k: sum(1 for o, _ in res.values() if o == k) for k in kinds}
    print(f"{side}: {len(res)} tests: " + ", ".join(f"{counts[k]} {k}" for k in kinds)
          + (f"; {len(crashed)} module(s) crashed or timed out" if crashed else ""))
    for name, rc, tail in crashed:
        print(f"  crashed: {name} rc={rc}: {tail}")

(a, _), (b, _) = sides["stock"], sides["switched"]
if a is not None and b is not None:
    keys = sorted(set(a) | set(b))
    diff = [k for k in keys if a.get(k, ("absent", ""))[0] != b.get(k, ("absent", ""))[0]]
    same = len(keys) - len(diff)
    print(f"same outcome both ways: {same} of {len(keys)}; differing: {len(diff)}")
    for k in diff:
        sa, sb = a.get(k, ("absent", "")), b.get(k, ("absent", ""))
        print(f"  {k}: stock {sa[0]}, switched {sb[0]}")
        msg = sb[1] if sb[0] != "passed" else sa[1]
        if msg:
            print(f"      {msg}")
EOF
