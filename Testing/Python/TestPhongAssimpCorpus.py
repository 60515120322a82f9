"""vtkphong-render on every model of assimp's own test corpus (Debian's
assimp-testmodels, /usr/share/assimp/models): valid files and deliberately broken
ones, none written here.

    TestPhongAssimpCorpus.py CLI -T TEMPORARY [--models DIR] [--folders F...] [--jobs N]
                             [--list]

For each file whose extension the command takes: a file assimp's own command
(`assimp info`, assimp-utils) loads with at least one face must render something
on screen; every other file must render or fail with one error line and status
1; none may crash or hang. Prints the counts per format (docs/io.md) and, with
--list, each file's outcome.
"""

import argparse
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtkphong_cli_runs  # noqa: E402

# Files assimp loads that the command refuses on purpose, and why (docs/io.md).
EXPECTED_REFUSALS = {
    # A face line "220" announces 220 vertices and gives none: vtkPhongOFFReader refuses
    # it; assimp 5.2 makes one point of it.
    "OFF/invalid.off": "a face without its vertex indices",
}

# Files that render nothing visible, rightly.
EXPECTED_BLANK = {
    "OBJ/number_formats.obj": "its one face joins three collinear points",
}

# Extensions that are textures, sources or side files, never meshes.
NOT_MESHES = (".jpg", ".jpeg", ".png", ".tga", ".bmp", ".dds", ".txt", ".mtl", ".bin",
              ".glsl", ".md", ".xml", ".zip", ".zae", ".max", ".lnk", ".html", ".skel")


def mesh_files(models, folders):
    """Every file of the corpus (or of its folders named) whose extension the command
    takes, sorted."""
    from vtkphong._meshio import known_extension
    found = []
    roots = [os.path.join(models, folder) for folder in folders] if folders else [models]
    for folder, subfolders, names in (entry for root in roots for entry in os.walk(root)):
        subfolders.sort()
        for name in sorted(names):
            path = os.path.join(folder, name)
            if not name.lower().endswith(NOT_MESHES) and known_extension(path):
                found.append(path)
    return found


def assimp_faces(path):
    """Faces `assimp info` finds in the file, 0 when it cannot load it, None without the
    assimp command."""
    if shutil.which("assimp") is None:
        return None
    try:
        result = subprocess.run(["assimp", "info", path], capture_output=True, timeout=30,
                                check=False)
    except subprocess.TimeoutExpired:
        return 0
    match = re.search(rb"^Faces:\s+(\d+)", result.stdout, re.MULTILINE)
    return int(match.group(1)) if result.returncode == 0 and match else 0


def check(results, faces, models):
    failures = []
    for path, outcome, detail in results:
        relative = os.path.relpath(path, models)
        if outcome == "blank" and relative in EXPECTED_BLANK:
            continue
        if outcome in ("crash", "hang", "blank"):
            failures.append("%s: %s %s" % (relative, outcome, detail))
        elif faces.get(path) and outcome != "rendered" and relative not in EXPECTED_REFUSALS:
            failures.append("%s: assimp loads %d faces but the command says: %s"
                            % (relative, faces[path], detail))
    return failures


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("cli")
    parser.add_argument("-T", dest="temporary", required=True)
    parser.add_argument("--models", default="/usr/share/assimp/models")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--folders", nargs="*", help="only these folders of the corpus")
    args = parser.parse_args()
    if not os.path.isdir(args.models):
        print("ERROR: no corpus at %s (install assimp-testmodels)" % args.models)
        return 1
    output = os.path.join(args.temporary, "TestPhongAssimpCorpus")
    os.makedirs(output, exist_ok=True)
    files = mesh_files(args.models, args.folders)
    jobs = [(path, args.cli, path, os.path.join(output, "%d.png" % n), 120, (30, 2048))
            for n, path in enumerate(files)]
    results = vtkphong_cli_runs.run_many(jobs, args.jobs)
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        faces = dict(zip(files, pool.map(assimp_faces, files)))
    if args.list:
        for path, outcome, detail in results:
            print("%-9s %-60s %s" % (outcome, os.path.relpath(path, args.models), detail))
    print(vtkphong_cli_runs.count_table(
        results, lambda path: os.path.splitext(path)[1].lower()))
    failures = check(results, faces, args.models)
    for failure in failures:
        print("ERROR: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
