"""Running vtkphong-render on many files and sorting the outcomes, for the corpus and
fuzz tests (TestPhongAssimpCorpus.py, TestPhongFuzzCLI.py) and `./vtkphong.sh fuzz`.

An outcome is one of:
  rendered     status 0 and something other than the background in the picture
  blank        status 0 but only background (a failure where a mesh was expected)
  error        status 1 or 2 and exactly one line "vtkphong-render: error: ..." on stderr
  contained    such an error line saying the reader or the renderer crashed, or the reader
               did not finish: a child process died or was stopped, the command did not
  crash        killed by a signal, another status, a traceback, or not one error line
  hang         still running after the time limit
"""

import collections
import concurrent.futures
import os
import subprocess

import numpy

BACKGROUND = (0.12, 0.12, 0.14)
OUTCOMES = ("rendered", "blank", "error", "contained", "crash", "hang")
CONTAINED = ("the reader crashed", "the reader did not finish", "the renderer crashed")


def run_cli(cli, mesh, image, timeout, read_limits=(60, 2048)):
    """(outcome, detail) of one run of the command on mesh, writing image."""
    environment = dict(os.environ)
    environment["VTKPHONG_READ_TIMEOUT"] = str(read_limits[0])
    environment["VTKPHONG_READ_MEMORY_MB"] = str(read_limits[1])
    command = [cli, mesh, "-o", image, "--size", "120x90", "--quiet"]
    try:
        result = subprocess.run(command, capture_output=True, timeout=timeout,
                                env=environment, check=False)
    except subprocess.TimeoutExpired:
        return "hang", "no exit after %d s" % timeout
    stderr = result.stderr.decode("utf-8", "replace")
    lines = [line for line in stderr.splitlines() if "warning: " not in line]
    if result.returncode == 0:
        return ("rendered", "") if covered_pixels(image) > 0 else ("blank", "")
    if (result.returncode in (1, 2) and len(lines) == 1
            and lines[0].startswith("vtkphong-render: error: ") and "Traceback" not in stderr):
        detail = lines[0][len("vtkphong-render: error: "):]
        return ("contained" if any(words in detail for words in CONTAINED) else "error"), detail
    return "crash", "status %d: %s" % (result.returncode, stderr.strip()[-300:])


def covered_pixels(image):
    """Pixels of the PNG that differ from the default background by more than 2 levels."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    if not os.path.isfile(image):
        return 0
    reader = vtkPNGReader()
    reader.SetFileName(image)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    if scalars is None:
        return 0
    rgb = vtk_to_numpy(scalars)[:, :3].astype(int)
    background = numpy.array([round(255 * c) for c in BACKGROUND])
    return int((numpy.abs(rgb - background).max(axis=1) > 2).sum())


def run_many(jobs, workers):
    """[(key, outcome, detail)] of run_cli over jobs [(key, cli arguments...)], in order."""
    with concurrent.futures.ThreadPoolExecutor(max_workers=workers) as pool:
        futures = [pool.submit(run_cli, *arguments) for _, *arguments in jobs]
        return [(job[0],) + future.result() for job, future in zip(jobs, futures)]


def count_table(results, group_of):
    """Markdown table of outcome counts per group (group_of(key) names the group)."""
    counts = collections.defaultdict(collections.Counter)
    for key, outcome, _ in results:
        counts[group_of(key)][outcome] += 1
    lines = ["| format | files | " + " | ".join(OUTCOMES) + " |",
             "|---|---:|" + "---:|" * len(OUTCOMES)]
    total = collections.Counter()
    for group in sorted(counts):
        total.update(counts[group])
        lines.append("| %s | %d | %s |" % (group, sum(counts[group].values()),
                                             " | ".join(str(counts[group][o]) for o in OUTCOMES)))
    lines.append("| all | %d | %s |" % (sum(total.values()),
                                        " | ".join(str(total[o]) for o in OUTCOMES)))
    return "\n".join(lines)
