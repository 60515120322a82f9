"""Reading the mesh files of vtkphong-render: one Part per piece of geometry.

The file is read in a child process (vtkphong._readers) with a limit on its
address space and a timeout: a reader that crashes, hangs or allocates without
bound on a hostile file kills only the child, and the command reports one line.
The child passes the parts back as .vtp files in a temporary directory; this
module reads them and checks what VTK would trust blindly (cell point ids,
array lengths, finite coordinates) before the camera or the normals see them.
"""

import json
import os
import resource
import shutil
import signal
import subprocess
import sys
import tempfile

from vtkphong._errors import RenderError

FORMATS = {
    ".obj": "Wavefront OBJ, with its .mtl materials and vertex colours",
    ".ply": "PLY (vertex colours, float or 8-bit; point clouds)",
    ".stl": "STL, ASCII or binary",
    ".off": "OFF (polygons of any size, vertex and face colours)",
    ".gltf": "glTF 2 (.gltf, .glb), with its node transforms and materials",
    ".fbx": "FBX",
    ".dae": "COLLADA",
    ".3ds": "3D Studio",
    ".vtp": "VTK XML polydata",
    ".vtu": "VTK XML unstructured grid (its outer surface is drawn)",
    ".vtk": "VTK legacy file (any dataset; its outer surface is drawn)",
    "...": "and every other format assimp reads (`assimp listext`)",
}

# The largest coordinate accepted: the camera and the bounds are computed in double
# precision from squares of coordinates, which overflow long before 1e308.
MAX_COORDINATE = 1e30

# The child's limits; the environment may change them.
TIMEOUT_VARIABLE = "VTKPHONG_READ_TIMEOUT"      # seconds, default 300
MEMORY_VARIABLE = "VTKPHONG_READ_MEMORY_MB"     # address space, default half the RAM


class Part:
    """A piece of geometry with, when the file gave one, its material (a dict of
    vtkphong.materials.material_of) and its texture (a vtkTexture)."""

    def __init__(self, polydata, material=None, texture=None, name=None):
        self.polydata = polydata
        self.material = material
        self.texture = texture
        self.name = name


def known_extension(path):
    """Whether the command has a reader for the file's extension."""
    extension = os.path.splitext(path)[1].lower()
    if extension in FORMATS or extension == ".glb":
        return True
    from vtkphong import vtkPhongAssimpReader
    return bool(extension) and vtkPhongAssimpReader.CanReadFile(path)


def read_mesh(path, progress, warnings):
    """The mesh's parts; RenderError when it cannot be read."""
    if not known_extension(path):
        raise RenderError("cannot read %s: unknown extension %r (known: %s)"
                          % (path, os.path.splitext(path)[1].lower(),
                             ", ".join(key for key in FORMATS if key != "...")))
    if not os.path.isfile(path):
        raise RenderError("cannot read %s: no such file" % path)
    _check_material_library(path, warnings)
    directory = tempfile.mkdtemp(prefix="vtkphong-read-")
    try:
        progress.stage("reading")
        run_reader(path, directory)
        parts = load_parts(directory, warnings)
    finally:
        shutil.rmtree(directory, ignore_errors=True)
    for part in parts:
        check_polydata(path, part.polydata)
    return parts


def _check_material_library(path, warnings):
    """A warning when an OBJ names a .mtl file that is missing (assimp goes on without)."""
    if os.path.splitext(path)[1].lower() != ".obj":
        return
    with open(path, "rb") as stream:
        for raw in stream:
            line = raw.decode("utf-8", "replace").strip()
            if line.startswith("mtllib "):
                library = os.path.join(os.path.dirname(path), line[7:].strip())
                if not os.path.isfile(library):
                    warnings.append("%s names the material file %s, which is missing; the"
                                    " default material is used" % (path, library))
                return


# --- the child process -------------------------------------------------------------

def reader_limits():
    """(timeout in seconds, address-space limit in bytes) for the child."""
    default_mb = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") // (2 << 20)
    timeout = _positive_number(TIMEOUT_VARIABLE, 300.0)
    memory_mb = int(_positive_number(MEMORY_VARIABLE, max(default_mb, 2048)))
    return timeout, memory_mb << 20


def _positive_number(variable, default):
    text = os.environ.get(variable)
    if text is None:
        return default
    try:
        value = float(text)
    except ValueError:
        value = -1.0
    if not value > 0.0:
        raise RenderError("%s must be a positive number, not %r" % (variable, text))
    return value


def run_reader(path, directory, limits=None):
    """Run vtkphong._readers on path into directory; RenderError naming the file and the
    reason when the child fails, crashes, runs out of memory or time."""
    timeout, memory = limits or reader_limits()
    memory = inherited_memory_limit(memory)
    package_root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    environment = dict(os.environ)
    environment["PYTHONPATH"] = os.pathsep.join(
        [package_root] + [p for p in environment.get("PYTHONPATH", "").split(os.pathsep) if p])

    def limit_memory():
        # Never above what this process may have (a hard limit cannot be raised).
        resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))

    try:
        child = subprocess.run(
            [sys.executable, "-m", "vtkphong._readers", os.path.abspath(path), directory],
            env=environment, preexec_fn=limit_memory, timeout=timeout,
            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, check=False)
    except subprocess.TimeoutExpired:
        raise RenderError("cannot read %s: the reader did not finish in %g s" % (path, timeout))
    except (OSError, subprocess.SubprocessError) as error:
        raise RenderError("cannot read %s: the reader could not start (%s; address space "
                          "limited to %d MB)" % (path, error, memory >> 20))
    if child.returncode != 0:
        raise RenderError("cannot read %s: %s" % (path, _child_failure(child, path, memory)))


def address_space_limit():
    """The address-space limit this process runs under (ulimit -v: the lower of the soft
    and hard limits), in bytes, or None."""
    limits = [limit for limit in resource.getrlimit(resource.RLIMIT_AS)
              if limit != resource.RLIM_INFINITY and limit >= 0]
    return min(limits) if limits else None


def inherited_memory_limit(memory):
    """memory, lowered to the address-space limit this process runs under (ulimit -v):
    the child may not have more than its parent, whatever the default says."""
    inherited = address_space_limit()
    return memory if inherited is None else min(memory, inherited)


def _child_failure(child, path, memory):
    """Why the child failed, in words."""
    if child.returncode < 0:
        name = signal.Signals(-child.returncode).name
        return "the reader crashed (%s; address space limited to %d MB)" % (name, memory >> 20)
    lines = child.stderr.decode("utf-8", "replace").strip().splitlines()
    reason = lines[-1] if lines else "the reader failed (status %d)" % child.returncode
    if "MemoryError" in reason or "bad_alloc" in reason:
        return "out of memory (address space limited to %d MB)" % (memory >> 20)
    for prefix in ("Cannot read %s: " % os.path.abspath(path), os.path.abspath(path) + ", "):
        reason = reason.replace(prefix, "")
    reason = reason.replace(os.path.abspath(path), os.path.basename(path))
    return "".join(c if " " <= c <= "~" else "?" for c in reason)[:240]


# --- what the child wrote ----------------------------------------------------------

def load_parts(directory, warnings):
    """The Parts listed in directory/parts.json."""
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    with open(os.path.join(directory, "parts.json"), encoding="utf-8") as stream:
        listing = json.load(stream)
    parts = []
    for entry in listing:
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(os.path.join(directory, entry["file"]))
        reader.Update()
        polydata = reader.GetOutput()
        _colours_to_bytes(polydata)
        texture = _load_texture(directory, entry["texture"]) if entry["texture"] else None
        material = entry["material"]
        parts.append(Part(polydata, material, texture, material and material.get("name")))
    return parts


def _colours_to_bytes(polydata):
    """Float RGB or RGBA scalars (in [0, 1]) become 8-bit, which the mapper shows as they
    are (VTK would map floats through a lookup table); an alpha channel that is 0
    everywhere (AMF) is taken as unset, not as an invisible mesh, and colours that are
    all 0 (Blender's default cube) as no colours."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    import numpy
    for data in (polydata.GetPointData(), polydata.GetCellData()):
        scalars = data.GetScalars()
        if scalars is None or scalars.GetNumberOfComponents() not in (3, 4):
            continue
        values = vtk_to_numpy(scalars)
        if scalars.GetDataTypeAsString() in ("float", "double"):
            values = numpy.nan_to_num(values, nan=0.0, posinf=1.0, neginf=0.0)
            values = numpy.clip(values, 0.0, 1.0) * 255.0 + 0.5
        elif scalars.GetDataTypeAsString() != "unsigned char":
            continue
        values = numpy.array(values, numpy.uint8)
        if len(values) and values.max() == 0:
            data.SetScalars(None)  # all black and transparent: colours never set (Blender)
            continue
        if values.shape[1] == 4 and len(values) and values[:, 3].max() == 0:
            values[:, 3] = 255
        converted = numpy_to_vtk(values, deep=True)
        converted.SetName(scalars.GetName() or "Colors")
        data.SetScalars(converted)


def _load_texture(directory, name):
    from vtkmodules.vtkIOXML import vtkXMLImageDataReader
    from vtkmodules.vtkRenderingCore import vtkTexture
    reader = vtkXMLImageDataReader()
    reader.SetFileName(os.path.join(directory, name))
    reader.Update()
    texture = vtkTexture()
    texture.SetInputData(reader.GetOutput())
    texture.InterpolateOn()
    texture.RepeatOn()
    return texture


# --- checks before VTK trusts the geometry -----------------------------------------

def check_polydata(path, polydata):
    """RenderError unless every cell names existing points, every coordinate is finite and
    at most MAX_COORDINATE, and every point (cell) array has a tuple per point (cell)."""
    problem = polydata_problem(polydata)
    if problem:
        raise RenderError("cannot read %s: %s" % (path, problem))


def polydata_problem(polydata):
    """What check_polydata refuses in the polydata, or None. The reading child asks too, before
    VTK's own writer touches the cells (VTK 9.3's legacy reader output crashed it)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    import numpy
    count = polydata.GetNumberOfPoints()
    if count:
        coordinates = vtk_to_numpy(polydata.GetPoints().GetData())
        if not numpy.all(numpy.isfinite(coordinates)):
            return "it has coordinates that are not finite"
        if numpy.abs(coordinates).max() > MAX_COORDINATE:
            return "it has coordinates beyond %g" % MAX_COORDINATE
    for kind in ("Verts", "Lines", "Polys", "Strips"):
        problem = _cells_problem(getattr(polydata, "Get" + kind)(), count, kind.lower())
        if problem:
            return problem
    return (_arrays_problem(polydata.GetPointData(), count, "points") or
            _arrays_problem(polydata.GetCellData(), polydata.GetNumberOfCells(), "cells"))


def _cells_problem(cells, count, kind):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    connectivity = vtk_to_numpy(cells.GetConnectivityArray())
    if len(offsets) == 0 and len(connectivity) == 0:
        return None
    if (len(offsets) == 0 or offsets[0] != 0 or offsets[-1] != len(connectivity)
            or (len(offsets) > 1 and (offsets[1:] < offsets[:-1]).any())):
        return "its %s are malformed" % kind
    if len(connectivity) and (connectivity.min() < 0 or connectivity.max() >= count):
        return "its %s name points that do not exist (%d points)" % (kind, count)
    return None


def _arrays_problem(data, count, what):
    for index in range(data.GetNumberOfArrays()):
        array = data.GetAbstractArray(index)
        if array is not None and array.GetNumberOfTuples() != count:
            return "its array %r has %d values for %d %s" % (
                array.GetName(), array.GetNumberOfTuples(), count, what)
    return None
