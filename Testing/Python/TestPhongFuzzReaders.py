"""Mutation fuzzing of vtkphong-render's reading: hostile files in every format must
end in parts or one clean reason, never in a crash, a hang or runaway memory of the
command itself.

    TestPhongFuzzReaders.py CLI -T TEMPORARY [--count N] [--seed S] [--models DIR]

From seed files (assimp's test models and files written here) it makes N mutants per
format with a fixed seed: byte flips, truncation, huge header counts, negative and
repeated indices, NaN/Inf/1e308 numbers, non-UTF-8 bytes (also in an OBJ's .mtl).
Each mutant goes through the command's two stages, each in a forked process so a
crash is counted rather than fatal:

1. the reader (vtkphong._readers: what the command's child process runs), under the
   command's kind of limits: address space (1 GiB above what the interpreter holds)
   and a timeout. Its crash or hang is contained: the command turns it into one line.
2. what the command itself then does: load the parts, check them
   (vtkphong._meshio.check_polydata), compute bounds (the camera reset) and normals
   (vtkOpenMeshNormals). This must never crash or hang.

Then a sample of the mutants whose reader crashed or hung goes through the whole
command, which must exit 1 with one error line. Prints counts per format.
"""

import argparse
import collections
import concurrent.futures
import os
import random
import re
import resource
import shutil
import signal
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtkphong_cli_runs  # noqa: E402

READ_TIMEOUT = 3
CHECK_TIMEOUT = 20
EXTRA_ADDRESS_SPACE = 1 << 30
NUMBER = re.compile(rb"-?\d+(\.\d+)?([eE][-+]?\d+)?")
MTL = b"newmtl \xff\xfeM\xe9tal\nKa 0.2 0.2 0.2\nKd 0.8 0.1 0.1\nKs 0.5 0.5 0.5\nNs 300\n"


# --- seeds --------------------------------------------------------------------------

def seed_files(models, directory):
    """{format: [seed paths]}: assimp's test models, and VTK files written here."""
    def model(*names):
        return [os.path.join(models, name) for name in names
                if os.path.isfile(os.path.join(models, name))]
    seeds = {
        "obj": model("OBJ/box.obj", "OBJ/cube_with_vertexcolors.obj", "OBJ/testline.obj",
                     "OBJ/point_cloud.obj"),
        "ply": model("PLY/cube.ply", "PLY/cube_binary.ply", "PLY/points.ply",
                     "PLY/float-color.ply"),
        "stl": model("STL/triangle.stl", "STL/sphereWithHole.stl"),
        "off": model("OFF/Cube.off"),
        "gltf": model("glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf"),
        "glb": model("glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"),
        "dae": model("Collada/cube_triangulate.dae"),
        "fbx": model("FBX/box.fbx"),
        "3ds": model("3DS/RotatingCube.3DS"),
    }
    seeds["obj"].append(_obj_with_mtl(directory))
    seeds["vtp"], seeds["vtk"] = _vtk_seeds(directory)
    return {fmt: paths for fmt, paths in seeds.items() if paths}


def _obj_with_mtl(directory):
    """An OBJ naming an .mtl whose material name is not UTF-8 (mutants keep the .mtl)."""
    with open(os.path.join(directory, "seed.mtl"), "wb") as stream:
        stream.write(MTL)
    path = os.path.join(directory, "seed-mtl.obj")
    with open(path, "wb") as stream:
        stream.write(b"mtllib seed.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                     b"usemtl \xff\xfeM\xe9tal\nf 1 2 3\nf 2 4 3\n")
    return path


def _vtk_seeds(directory):
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkIOLegacy import vtkPolyDataWriter
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(8)
    sphere.SetPhiResolution(6)
    paths = []
    for writer, name in ((vtkXMLPolyDataWriter(), "seed.vtp"), (vtkPolyDataWriter(), "seed.vtk")):
        writer.SetInputConnection(sphere.GetOutputPort())
        writer.SetFileName(os.path.join(directory, name))
        if name.endswith(".vtp"):
            writer.SetDataModeToAscii()
        writer.Write()
        paths.append([writer.GetFileName()])
    return paths


# --- mutations ----------------------------------------------------------------------

def _replace_number(data, rng, values):
    numbers = list(NUMBER.finditer(data))
    if not numbers:
        return data
    match = rng.choice(numbers)
    return data[:match.start()] + rng.choice(values) + data[match.end():]


MUTATIONS = {
    "flip": lambda d, r: bytes(b if r.random() > 8.0 / max(len(d), 1) else r.randrange(256)
                               for b in d),
    "truncate": lambda d, r: d[:r.randrange(max(len(d), 1))],
    "huge-count": lambda d, r: _replace_number(
        d, r, [b"4294967295", b"2147483647", b"99999999999", b"1073741824"]),
    "bad-index": lambda d, r: _replace_number(d, r, [b"-1", b"-2147483648", b"0", b"65535"]),
    "nan-inf": lambda d, r: _replace_number(d, r, [b"nan", b"inf", b"-inf", b"1e308", b"1e39"]),
    "repeat": lambda d, r: _repeat_lines(d, r),
    "non-utf8": lambda d, r: _insert(d, r, rng_bytes=[b"\xff\xfe", b"\xc3\x28", b"\x80\x80\x80"]),
    "int32": lambda d, r: _overwrite_int(d, r),
}


def _repeat_lines(data, rng):
    lines = data.split(b"\n")
    index = rng.randrange(len(lines))
    return b"\n".join(lines[:index] + [lines[index]] * rng.randrange(2, 50) + lines[index:])


def _insert(data, rng, rng_bytes):
    at = rng.randrange(len(data) + 1)
    return data[:at] + rng.choice(rng_bytes) + data[at:]


def _overwrite_int(data, rng):
    """A binary header or count field set to a huge value (binary PLY, STL, GLB, 3DS, FBX)."""
    if len(data) < 8:
        return data
    at = rng.randrange(min(len(data) - 4, 256))
    return data[:at] + rng.choice([b"\xff\xff\xff\x7f", b"\x00\x00\x00\x80",
                                   b"\xff\xff\xff\xff"]) + data[at + 4:]


def make_mutants(seeds, count, seed, directory):
    """[(format, mutation, path)]: count mutants per format, reproducibly."""
    rng = random.Random(seed)
    mutants = []
    for fmt in sorted(seeds):
        for number in range(count):
            source = rng.choice(seeds[fmt])
            name = rng.choice(sorted(MUTATIONS))
            with open(source, "rb") as stream:
                data = MUTATIONS[name](stream.read(), rng)
            path = os.path.join(directory, "%s-%04d-%s%s"
                                % (fmt, number, name, os.path.splitext(source)[1]))
            with open(path, "wb") as stream:
                stream.write(data)
            mutants.append((fmt, name, path))
    return mutants


# --- the two stages, each in a forked child -----------------------------------------

def in_child(function, timeout, address_space=None):
    """Run function() in a forked child: 'ok', 'refused' (it raised), 'crash' or 'hang'."""
    pid = os.fork()
    if pid == 0:
        status = 2
        try:
            if address_space:
                resource.setrlimit(resource.RLIMIT_AS, (address_space, address_space))
            resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
            status = 0 if function() else 1
        except Exception:  # noqa: BLE001 -- the child's whole job: any failure is a status
            status = 1
        finally:
            os._exit(status)
    deadline = time.monotonic() + timeout
    while True:
        done, status = os.waitpid(pid, os.WNOHANG)
        if done:
            break
        if time.monotonic() > deadline:
            os.kill(pid, signal.SIGKILL)
            os.waitpid(pid, 0)
            return "hang"
        time.sleep(0.002)
    if os.WIFSIGNALED(status):
        return "crash"
    return {0: "ok", 1: "refused"}.get(os.WEXITSTATUS(status), "crash")


def read_stage(path, directory):
    from vtkphong import _readers
    return _readers.write_parts(_readers.read_parts(path), directory) > 0


def command_stage(path, directory):
    """What the command does with the reader's output: load, check, bounds, normals."""
    from vtkphong import _meshio, vtkOpenMeshNormals
    from vtkphong._errors import RenderError
    try:
        parts = _meshio.load_parts(directory, [])
        for part in parts:
            _meshio.check_polydata(path, part.polydata)
    except RenderError:
        return False
    for part in parts:
        part.polydata.GetBounds()
        if part.polydata.GetNumberOfPolys():
            normals = vtkOpenMeshNormals()
            normals.SetInputData(part.polydata)
            normals.Update()
    return True


def fuzz_one(path, work):
    """(reader outcome, command outcome or None) of one mutant."""
    directory = tempfile.mkdtemp(dir=work)
    try:
        in_use = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
        reader = in_child(lambda: read_stage(path, directory), READ_TIMEOUT,
                          _address_space() + EXTRA_ADDRESS_SPACE + in_use)
        if reader != "ok":
            return reader, None
        return reader, in_child(lambda: command_stage(path, directory), CHECK_TIMEOUT)
    finally:
        shutil.rmtree(directory, ignore_errors=True)


def _address_space():
    with open("/proc/self/status") as stream:
        for line in stream:
            if line.startswith("VmSize:"):
                return int(line.split()[1]) * 1024
    return 0


# --- the report ---------------------------------------------------------------------

def category(reader, command):
    """What a user of the command would see."""
    if reader in ("crash", "hang"):
        return "reader-" + reader + " (contained)"
    if reader == "refused":
        return "reader error"
    return {"ok": "parts", "refused": "check refused"}.get(command, "COMMAND-" + command.upper())


def report(results):
    counts = collections.defaultdict(collections.Counter)
    for fmt, _, _, outcome in results:
        counts[fmt][outcome] += 1
    names = ["parts", "check refused", "reader error", "reader-crash (contained)",
             "reader-hang (contained)", "COMMAND-CRASH", "COMMAND-HANG"]
    print("| format | files | " + " | ".join(names) + " |")
    print("|---|---:|" + "---:|" * len(names))
    total = collections.Counter()
    for fmt in sorted(counts):
        total.update(counts[fmt])
        print("| %s | %d | %s |" % (fmt, sum(counts[fmt].values()),
                                     " | ".join(str(counts[fmt][n]) for n in names)))
    print("| all | %d | %s |" % (sum(total.values()), " | ".join(str(total[n]) for n in names)))


def header_count_shapes(seed_vtk, directory):
    """Legacy VTK files whose section counts the file's size cannot hold (issue 28: a
    `VERTICES 4294967295` of a few hundred bytes made VTK's reader ask for 32 GB), made from
    the ASCII seed, and the same counts in a binary file: (name, path)."""
    with open(seed_vtk, "rb") as stream:
        ascii_seed = stream.read()
    shapes = {
        "VERTICES 4294967295": b"# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\n"
                               b"POINTS 3 float\n0 0 0 1 0 0 0 1 0\nVERTICES 4294967295 3\n1 0\n",
        "POLYGONS 1e9 cells": _with_line(ascii_seed, b"POLYGONS", b"POLYGONS 1000000000 4000000000"),
        "POINTS 2^31": _with_line(ascii_seed, b"POINTS", b"POINTS 2147483647 float"),
        "NORMALS beyond POINT_DATA": _with_line(ascii_seed, b"POINT_DATA", b"POINT_DATA 900000000"),
    }
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkIOLegacy import vtkPolyDataWriter
    binary = os.path.join(directory, "binary-seed.vtk")
    writer = vtkPolyDataWriter()
    sphere = vtkSphereSource()
    writer.SetInputConnection(sphere.GetOutputPort())
    writer.SetFileName(binary)
    writer.SetFileTypeToBinary()
    writer.Write()
    with open(binary, "rb") as stream:
        binary_seed = stream.read()
    shapes["binary: POINTS beyond the payload"] = _with_line(binary_seed, b"POINTS",
                                                             b"POINTS 50000000 float")
    shapes["binary: CONNECTIVITY beyond the payload"] = _with_line(
        binary_seed, b"POLYGONS", b"POLYGONS 97 600000000")
    paths = []
    for number, (name, data) in enumerate(sorted(shapes.items())):
        path = os.path.join(directory, "shape-%d.vtk" % number)
        with open(path, "wb") as stream:
            stream.write(data)
        paths.append((name, path))
    return paths


def _with_line(data, keyword, replacement):
    """data with the first line starting with keyword replaced."""
    start = data.find(b"\n" + keyword) + 1
    end = data.find(b"\n", start)
    return data[:start] + replacement + data[end:]


def check_header_counts(work):
    """Every shape is refused by the header check, before VTK's reader allocates (under the
    fuzz's address-space limit VTK's own failed allocation would be refused too), and the
    reading stage refuses it (not read, crashed or hung)."""
    from vtkphong import _readers
    failures = []
    seed = os.path.join(work, "seed.vtk")
    for name, path in header_count_shapes(seed, work):
        try:
            _readers.check_vtk_legacy_counts(path)
            reason = None
        except _readers.ReadFailure as failure:
            reason = str(failure)
        outcome = fuzz_one(path, work)[0]
        print("header count shape %r: %s (%s)" % (name, outcome, reason))
        if outcome != "refused" or not reason:
            failures.append("header count shape %r: the reader stage gave %s, the header check"
                            " %s" % (name, outcome, reason or "let it through"))
    return failures


def check_through_command(cli, results, work, sample):
    """The whole command on mutants whose reader crashed or hung: one line, status 1."""
    contained = [path for _, _, path, outcome in results if "contained" in outcome][:sample]
    jobs = [(path, cli, path, os.path.join(work, "cli-%d.png" % n), 120, (READ_TIMEOUT, 2048))
            for n, path in enumerate(contained)]
    failures = []
    for path, outcome, detail in vtkphong_cli_runs.run_many(jobs, 2):
        if outcome not in ("error", "contained", "rendered"):
            failures.append("%s: the command gave %s %s" % (os.path.basename(path), outcome,
                                                            detail))
    print("%d mutants whose reader crashed or hung, run through %s: %d failures"
          % (len(jobs), os.path.basename(cli), len(failures)))
    return failures


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("cli")
    parser.add_argument("-T", dest="temporary", required=True)
    parser.add_argument("--count", type=int, default=200, help="mutants per format")
    parser.add_argument("--seed", type=int, default=15)
    parser.add_argument("--models", default="/usr/share/assimp/models")
    parser.add_argument("--cli-sample", type=int, default=12)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--formats", nargs="*",
                        help="run only these formats' mutants (all are still made, so each"
                             " format's mutants do not depend on the others run)")
    args = parser.parse_args()
    import vtkphong  # noqa: F401 -- loaded once, before the forks
    from vtkmodules.vtkCommonCore import vtkObject
    vtkObject.GlobalWarningDisplayOff()
    work = os.path.join(args.temporary, "TestPhongFuzzReaders")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(os.path.join(work, "mutants"))
    started = time.monotonic()
    seeds = seed_files(args.models, work)
    mutants = make_mutants(seeds, args.count, args.seed, os.path.join(work, "mutants"))
    if args.formats:
        mutants = [mutant for mutant in mutants if mutant[0] in args.formats]
    # Two at a time (the forks are made from two threads; each child is single-threaded).
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        outcomes = list(pool.map(lambda mutant: category(*fuzz_one(mutant[2], work)), mutants))
    results = [mutant + (outcome,) for mutant, outcome in zip(mutants, outcomes)]
    report(results)
    failures = ["%s (%s): %s" % (os.path.basename(path), mutation, outcome)
                for _, mutation, path, outcome in results if outcome.startswith("COMMAND")]
    failures += check_through_command(args.cli, results, work, args.cli_sample)
    failures += check_header_counts(work)
    memory = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss >> 10
    print("%d mutants in %.0f s; this process peaked at %d MB"
          % (len(mutants), time.monotonic() - started, memory))
    if memory > 2048:
        failures.append("the fuzzing process itself reached %d MB" % memory)
    for failure in failures:
        print("ERROR: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
