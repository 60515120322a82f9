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
import itertools
import os
import random
import re
import resource
import shutil
import signal
import struct
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
    """Files whose header counts the file cannot hold or whose cells the reader would trust
    (issue 28): legacy VTK sections that announce more than the file's size (a
    `VERTICES 4294967295` of a few hundred bytes made VTK's reader ask for 32 GB), cells naming
    points the file lacks, a binary cell size of 1e9, offsets that run backwards (VTK 9.1's
    reader crashes on these), and binary PLY list counts that disagree with the payload:
    (name, path, check)."""
    from vtkphong import _readers
    with open(seed_vtk, "rb") as stream:
        ascii_seed = stream.read()
    legacy = {
        "VERTICES 4294967295": b"# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\n"
                               b"POINTS 3 float\n0 0 0 1 0 0 0 1 0\nVERTICES 4294967295 3\n1 0\n",
        "POLYGONS 1e9 cells": _with_line(ascii_seed, b"POLYGONS", b"POLYGONS 1000000000 4000000000"),
        "POINTS 2^31": _with_line(ascii_seed, b"POINTS", b"POINTS 2147483647 float"),
        "NORMALS beyond POINT_DATA": _with_line(ascii_seed, b"POINT_DATA", b"POINT_DATA 900000000"),
        "POLYGONS naming point 4294967295": b"# vtk DataFile Version 3.0\nx\nASCII\n"
            b"DATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n"
            b"3 0 1 4294967295\n",
        "POLYGONS whose cell sizes overrun": b"# vtk DataFile Version 3.0\nx\nASCII\n"
            b"DATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 2 8\n"
            b"3 0 1 2\n9 0 1 2\n",
    }
    binary_old, binary_new = _binary_seeds(directory)
    legacy["binary: POINTS beyond the payload"] = _with_line(binary_new, b"POINTS",
                                                             b"POINTS 50000000 float")
    legacy["binary: CONNECTIVITY beyond the payload"] = _with_line(
        binary_new, b"POLYGONS", b"POLYGONS 97 600000000")
    legacy["binary: a cell size of 1e9"] = _patch_after(binary_old, b"POLYGONS", 0,
                                                        (10 ** 9).to_bytes(4, "big"))
    legacy["binary: CONNECTIVITY naming point 2^40"] = _patch_after(
        binary_new, b"CONNECTIVITY", 0, (1 << 40).to_bytes(8, "big"))
    legacy["binary: OFFSETS running backwards"] = _patch_after(binary_new, b"OFFSETS", 8,
                                                               (1 << 40).to_bytes(8, "big"))
    shapes = [(name, data, ".vtk", _readers.check_vtk_legacy_counts)
              for name, data in sorted(legacy.items())]
    for name, data in sorted(_ply_shapes().items()):
        shapes.append((name, data, ".ply", _readers.check_ply_header))
    from vtkphong._xml_cells import check_xml_cells
    for name, (data, extension) in sorted(xml_files(directory, broken=True).items()):
        shapes.append((name, data, extension, check_xml_cells))
    paths = []
    for number, (name, data, extension, check) in enumerate(shapes):
        path = os.path.join(directory, "shape-%d%s" % (number, extension))
        with open(path, "wb") as stream:
            stream.write(data)
        paths.append((name, path, check))
    return paths


def _with_line(data, keyword, replacement):
    """data with the first line starting with keyword replaced."""
    start = data.find(b"\n" + keyword) + 1
    end = data.find(b"\n", start)
    return data[:start] + replacement + data[end:]


def _binary_seeds(directory):
    """A sphere as a binary legacy file, in the old format (cell sizes and ids) and in
    VTK 9's (OFFSETS and CONNECTIVITY)."""
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkIOLegacy import vtkPolyDataWriter
    seeds = []
    sphere = vtkSphereSource()  # kept: the writer's connection does not hold it
    for version in (42, 51):
        path = os.path.join(directory, "binary-seed-%d.vtk" % version)
        writer = vtkPolyDataWriter()
        writer.SetInputConnection(sphere.GetOutputPort())
        writer.SetFileName(path)
        writer.SetFileTypeToBinary()
        if hasattr(writer, "SetFileVersion"):
            writer.SetFileVersion(version)
        writer.Write()
        with open(path, "rb") as stream:
            seeds.append(stream.read())
    return seeds


def _patch_after(data, keyword, skip, replacement):
    """data with the bytes after the line starting with keyword, from `skip` on, overwritten
    by replacement."""
    start = data.find(b"\n", data.find(b"\n" + keyword) + 1) + 1 + skip
    return data[:start] + replacement + data[start + len(replacement):]


def _ply_shapes():
    """Binary PLY files whose list counts disagree with the payload (issue 28: `element vertex
    0` and two flipped bytes ran assimp's reader out of its 4 GB)."""
    header = (b"ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\n"
              b"property float y\nproperty float z\nelement face %d\n"
              b"property list uint int vertex_indices\nend_header\n")
    vertices = b"".join(struct.pack("<3f", *p) for p in ((0, 0, 0), (1, 0, 0), (0, 1, 0)))
    face = struct.pack("<I3i", 3, 0, 1, 2)
    return {
        "PLY: element vertex 0, a list count flipped": header % (0, 2) + face[:2] +
            b"\xff\xff" + face[4:] + face,
        "PLY: a list count past the payload": header % (3, 1) + vertices +
            struct.pack("<I", 3000000) + face[4:],
        "PLY: a second face's count flipped": header % (3, 2) + vertices + face +
            struct.pack("<I", 0x7fff0003) + face[4:],
    }


XML_MODES = ("ascii", "binary", "appended raw", "appended raw zlib", "appended base64 zlib",
             "binary lzma")


def xml_files(directory, broken):
    """{name: (bytes, extension)}: VTK XML files in every encoding the checks decode. Valid
    (broken=False): a sphere written by VTK's own writer, which must be read. Broken: cells
    VTK's readers would build wrongly (an empty polygon, a polygon of two points, a point id
    past the points, an unstructured grid's tetrahedron of three points), which VTK's
    writer refuses to write: written here, in the same encodings."""
    if broken:
        points = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)]
        cases = {"an empty polygon": ("PolyData", [[0, 1, 2], [], [2, 3, 0]]),
                 "a polygon of two points": ("PolyData", [[0, 1, 2], [2, 3]]),
                 "a point id past the points": ("PolyData", [[0, 1, 2], [2, 3, 400000]]),
                 "a tetrahedron of three points": ("UnstructuredGrid", [[0, 1, 2]])}
        return {"XML %s: %s" % (mode, name): (_xml_bytes(kind, points, cells, mode),
                                              ".vtp" if kind == "PolyData" else ".vtu")
                for name, (kind, cells) in cases.items() for mode in XML_MODES}
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    sphere = vtkSphereSource()
    sphere.Update()
    files = {}
    for mode in XML_MODES:
        path = os.path.join(directory, "xml.vtp")
        _write_xml(sphere.GetOutput(), mode, path)
        with open(path, "rb") as stream:
            files["XML %s: sphere" % mode] = (stream.read(), ".vtp")
    return files


def _write_xml(data_set, mode, path):
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(data_set)
    writer.SetFileName(path)
    writer.SetCompressorTypeToNone()
    if "zlib" in mode:
        writer.SetCompressorTypeToZLib()
    if "lzma" in mode:
        writer.SetCompressorTypeToLZMA()
    if mode == "ascii":
        writer.SetDataModeToAscii()
    elif mode.startswith("binary"):
        writer.SetDataModeToBinary()
    else:
        writer.SetDataModeToAppended()
        writer.SetEncodeAppendedData("base64" in mode)
    writer.Write()


def _xml_bytes(kind, points, cells, mode):
    """A VTK XML file of `points` and `cells` (polygons, or tetrahedra for a grid), encoded
    as VTK's writer encodes (UInt32 headers; header and data base64-encoded apart)."""
    import base64
    import lzma
    import zlib
    compress = zlib.compress if "zlib" in mode else lzma.compress if "lzma" in mode else None
    arrays = [("Points", "Float32", "f", [c for p in points for c in p], 3),
              ("connectivity", "Int64", "q", [i for c in cells for i in c], 1),
              ("offsets", "Int64", "q", list(itertools.accumulate(len(c) for c in cells)), 1)]
    if kind == "UnstructuredGrid":
        arrays.append(("types", "UInt8", "B", [10] * len(cells), 1))
    appended, xml = b"", []
    for name, vtk_type, code, values, components in arrays:
        raw = struct.pack("<%d%s" % (len(values), code), *values)
        if compress:
            packed = compress(raw)
            header = struct.pack("<4I", 1, len(raw), len(raw), len(packed))
        else:
            packed, header = raw, struct.pack("<I", len(raw))
        attributes = 'type="%s" Name="%s" NumberOfComponents="%d"' % (vtk_type, name, components)
        if mode == "ascii":
            body = " ".join(str(v) for v in values)
            xml.append('<DataArray %s format="ascii">%s</DataArray>' % (attributes, body))
        elif mode.startswith("binary"):
            body = (base64.b64encode(header) + base64.b64encode(packed)).decode()
            xml.append('<DataArray %s format="binary">%s</DataArray>' % (attributes, body))
        else:
            xml.append('<DataArray %s format="appended" offset="%d"/>' % (attributes,
                                                                        len(appended)))
            block = header + packed
            appended += base64.b64encode(header) + base64.b64encode(packed) \
                if "base64" in mode else block
    section = "Polys" if kind == "PolyData" else "Cells"
    count = "NumberOfPolys" if kind == "PolyData" else "NumberOfCells"
    text = ('<?xml version="1.0"?>\n<VTKFile type="%s" version="1.0" byte_order="LittleEndian" '
            'header_type="UInt32"%s>\n<%s><Piece NumberOfPoints="%d" %s="%d">'
            '<Points>%s</Points><%s>%s</%s></Piece></%s>\n'
            % (kind, ' compressor="%s"' % ("vtkZLibDataCompressor" if "zlib" in mode else
                                           "vtkLZMADataCompressor") if compress else "",
               kind, len(points), count, len(cells), xml[0], section, "".join(xml[1:]),
               section, kind))
    data = text.encode()
    if appended:
        encoding = "base64" if "base64" in mode else "raw"
        data += b'<AppendedData encoding="%s">\n_' % encoding.encode() + appended + \
            b"\n</AppendedData>\n"
    return data + b"</VTKFile>\n"


def check_valid_xml(work):
    """The XML checks pass a valid sphere in every encoding, and the reading stage reads it."""
    from vtkphong._xml_cells import check_xml_cells
    failures = []
    for number, (name, (data, extension)) in enumerate(sorted(xml_files(work, False).items())):
        path = os.path.join(work, "valid-%d%s" % (number, extension))
        with open(path, "wb") as stream:
            stream.write(data)
        try:
            check_xml_cells(path)
        except Exception as failure:  # noqa: BLE001 -- any refusal of a valid file fails
            failures.append("%s: refused (%s)" % (name, failure))
            continue
        outcome = fuzz_one(path, work)[0]
        print("valid %s: %s" % (name, outcome))
        if outcome != "ok":
            failures.append("%s: the reader stage gave %s" % (name, outcome))
    return failures


def check_header_counts(work):
    """Every shape is refused by its check, before the reader allocates or crashes (under
    the fuzz's address-space limit a failed allocation would be refused too), and the
    reading stage refuses it (not read, crashed or hung)."""
    failures = []
    seed = os.path.join(work, "seed.vtk")
    for name, path, check in header_count_shapes(seed, work):
        try:
            check(path)
            reason = None
        except Exception as failure:  # noqa: BLE001 -- ReadFailure is the expected one
            reason = "%s: %s" % (type(failure).__name__, failure)
        outcome = fuzz_one(path, work)[0]
        print("header count shape %r: %s (%s)" % (name, outcome, reason))
        if outcome != "refused" or not reason or not reason.startswith("ReadFailure"):
            failures.append("header count shape %r: the reader stage gave %s, the check"
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
    failures += check_valid_xml(work)
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
