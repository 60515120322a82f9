"""Runs one script of Examples/Python as a user would (VTK's Python, the
vtkphong package on PYTHONPATH, offscreen) and checks what it made: its
picture against Testing/Data/Baseline/TestPhongPythonExample_<name>.png (at
most 24 pixels may differ by more than 6 levels, as the other image tests), or
for measure_accuracy.py the table it prints.

    TestPhongPythonExample.py EXAMPLE -B <baselines> -T <temporary> [--mesh bunny00.off]
"""

import argparse
import os
import re
import subprocess
import sys

import vtkphong
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkphong_testing import Checks

parser = argparse.ArgumentParser()
parser.add_argument("example")
parser.add_argument("-B", dest="baselines", required=True)
parser.add_argument("-T", dest="temporary", required=True)
parser.add_argument("--mesh")
parser.add_argument("--examples", default=os.path.join(os.path.dirname(__file__), "..", "..",
                                                       "Examples", "Python"))
args = parser.parse_args()
checks = Checks()
os.makedirs(args.temporary, exist_ok=True)

name = os.path.splitext(args.example)[0]
script = os.path.join(args.examples, args.example)
output = os.path.join(args.temporary, "TestPhongPythonExample_%s.png" % name)
if os.path.exists(output):
    os.remove(output)
command = [sys.executable, script]
if name in ("render_mesh", "studio_lighting"):
    command.append(args.mesh)
if name != "measure_accuracy":
    command += ["-o", output]
run = subprocess.run(command, capture_output=True, text=True, timeout=300)
sys.stdout.write(run.stdout)
sys.stderr.write(run.stderr)
checks.expect(run.returncode == 0, "%s exits with 0 (got %d)" % (args.example, run.returncode))
checks.expect("Traceback" not in run.stderr, "%s raises nothing" % args.example)

if name == "measure_accuracy":
    # | resolution | interpolation | mean | p99 | max |
    rows = re.findall(r"^\| (\d+) \| ([^|]+) \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) \|$",
                      run.stdout, re.MULTILINE)
    errors = {(int(r), mode.strip()): float(mean) for r, mode, mean, _, _ in rows}
    resolutions = sorted({r for r, _ in errors})
    checks.expect(len(resolutions) >= 3, "the table has rows for several resolutions")
    for low, high in zip(resolutions, resolutions[1:]):
        for mode in ("per-vertex Gouraud", "Phong"):
            checks.expect(errors[(high, mode)] < errors[(low, mode)],
                          "%s error falls from %d to %d" % (mode, low, high))
    for resolution in resolutions:
        checks.expect(errors[(resolution, "Phong")] < errors[(resolution, "per-vertex Gouraud")],
                      "Phong beats per-vertex Gouraud at %d" % resolution)
    checks.exit()


def baseline_and_alternates(baseline_file):
    """The baseline and its alternates, as VTK's harness names them (NAME.png, NAME_1.png, ...):
    an alternate holds what another release's VTK or Mesa draws."""
    files = [baseline_file]
    stem = baseline_file[:-len(".png")]
    while os.path.exists("%s_%d.png" % (stem, len(files))):
        files.append("%s_%d.png" % (stem, len(files)))
    return files


def failed_pixels(picture, baseline_file):
    """Pixels more than 6 levels off the baseline, the error map written beside the output."""
    baseline = vtkImageData()
    io.ReadImage(baseline_file, baseline)
    comparison = vtkphong.vtkPhongImageComparison()
    comparison.SetTestImage(picture)
    comparison.SetReferenceImage(baseline)
    comparison.UseCoverageOff()  # opaque pictures: every pixel counts
    comparison.SetThreshold(6.5 / 255.0)
    comparison.SetMaximumFailedPixels(24)
    comparison.SetErrorMapFileName(output.replace(".png", ".error.png"))
    return None if comparison.Compare() == 1 else comparison.GetNumberOfFailedPixels()


checks.expect(os.path.exists(output), "%s wrote its picture" % args.example)
if os.path.exists(output):
    io = vtkphong.vtkPhongImageIO()
    picture = vtkImageData()
    baseline_file = os.path.join(args.baselines, os.path.basename(output))
    io.ReadImage(output, picture)
    if not os.path.exists(baseline_file):
        checks.expect(False, "a baseline %s exists (the picture is %s)" % (baseline_file, output))
    else:
        failures = []
        for candidate in baseline_and_alternates(baseline_file):
            failed = failed_pixels(picture, candidate)
            if failed is None:
                break
            failures.append("%d pixels differ from %s by more than 6 levels"
                            % (failed, os.path.basename(candidate)))
        else:
            checks.expect(False, "%s matches a baseline (%s)" % (args.example, "; ".join(failures)))
checks.exit()
