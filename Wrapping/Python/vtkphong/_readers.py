"""The reading half of vtkphong-render, run in a child process.

    /usr/bin/python3 -m vtkphong._readers MESH OUTDIR

reads MESH with the reader its extension calls for and writes what it found
into OUTDIR: one ``part<N>.vtp`` per piece of geometry, ``texture<N>.vti``
for the diffuse textures, and ``parts.json`` listing them with their
materials. It exits 0 when that is done, 1 with a one-line reason on stderr
when the file cannot be read. vtkphong._meshio runs it under a memory limit
and a timeout and reads OUTDIR back: whatever a reader does with a hostile
file (crash, hang, runaway allocation), only this process dies.

Formats: VTK's own readers for VTK's formats (.vtp, .vtu, .vtk),
vtkPhongOFFReader for .off (assimp 5.2's OFF importer accepts vertex indices
that do not exist and misreads integer colours, see docs/io.md), and
vtkPhongAssimpReader for everything else assimp reads.
"""

import json
import os
import sys

from vtkphong._errors import ReadFailure  # noqa: F401 -- part of this module's interface

VTK_EXTENSIONS = (".vtp", ".vtu", ".vtk")


def read_parts(path):
    """[(polydata, material dict or None, texture path or None)] of the file."""
    extension = os.path.splitext(path)[1].lower()
    if extension == ".vtk":
        check_vtk_legacy_counts(path)
    if extension in (".vtp", ".vtu"):
        from vtkphong._xml_cells import check_xml_cells
        check_xml_cells(path)
    if extension in VTK_EXTENSIONS:
        return [(_read_vtk(path, extension), None, None)]
    if extension == ".ply":
        check_ply_header(path)
    if extension == ".off":
        from vtkphong import vtkPhongOFFReader
        reader = vtkPhongOFFReader()
        reader.SetFileName(path)
        reader.Update()
        return [(reader.GetOutput(), None, None)]
    return _read_assimp(path)


# Bytes of each PLY scalar type, for the smallest size a binary element can take.
PLY_SIZES = {"char": 1, "uchar": 1, "int8": 1, "uint8": 1, "short": 2, "ushort": 2,
             "int16": 2, "uint16": 2, "int": 4, "uint": 4, "int32": 4, "uint32": 4,
             "float": 4, "float32": 4, "double": 8, "float64": 8}


def check_ply_header(path):
    """Refuse a PLY file whose header does not end (assimp 5.2's PLY importer loops forever
    on a truncated header) or announces more elements than the file's size can hold; in a
    binary file, walk the elements' records, list counts included (a list count is a number
    the importer allocates for: one flipped byte made a 600-byte file ask for gigabytes)."""
    with open(path, "rb") as stream:
        head = stream.read(65536)
    end = head.find(b"end_header")
    if not head.startswith(b"ply") or end < 0:
        raise ReadFailure("not a PLY file, or its header does not end in its first 64 KiB")
    elements = _ply_elements(head[:end].decode("ascii", "replace").splitlines())
    binary = b"binary" in head[:end]
    needed = _ply_smallest_size(elements, binary)
    size = os.path.getsize(path)
    if needed > size - end:
        raise ReadFailure("its header announces elements needing at least %d bytes; the file"
                          " has %d" % (needed, size))
    if binary:
        payload = head.find(b"\n", end) + 1
        big = b"binary_big_endian" in head[:end]
        _PlyPayload(path, elements, big).walk(payload)


def _ply_smallest_size(elements, binary):
    """The fewest bytes the elements of a PLY header can take: per element, the sum of its
    scalar sizes (a list: its count's) in binary, a digit and a separator in ASCII."""
    if not binary:
        return sum(2 * count for _, count, _ in elements)
    return sum(count * sum(PLY_SIZES.get(count_type or value_type, 1)
                           for count_type, value_type in properties)
               for _, count, properties in elements)


def _ply_elements(header):
    """[(name, count, [(count type or None, value type)])] of a PLY header."""
    elements = []
    for line in header:
        words = line.split()
        if len(words) == 3 and words[0] == "element":
            if not words[2].isdigit():
                raise ReadFailure("its header's element %r has no count" % words[1])
            elements.append((words[1], int(words[2]), []))
        elif elements and len(words) >= 3 and words[:2] == ["property", "list"]:
            elements[-1][2].append((words[2], words[3] if len(words) > 3 else "uchar"))
        elif elements and len(words) >= 3 and words[0] == "property":
            elements[-1][2].append((None, words[1]))
    return elements


class _PlyPayload:
    """A binary PLY's records, walked without reading them into memory: each element's
    records take the size their properties and list counts give, within the file."""

    NUMPY = {"char": "i1", "uchar": "u1", "int8": "i1", "uint8": "u1", "short": "i2",
             "ushort": "u2", "int16": "i2", "uint16": "u2", "int": "i4", "uint": "u4",
             "int32": "i4", "uint32": "u4", "float": "f4", "float32": "f4",
             "double": "f8", "float64": "f8"}

    def __init__(self, path, elements, big):
        import mmap
        self.size = os.path.getsize(path)
        with open(path, "rb") as stream:
            self.data = mmap.mmap(stream.fileno(), 0, access=mmap.ACCESS_READ)
        self.elements, self.order = elements, ">" if big else "<"

    def walk(self, position):
        for name, count, properties in self.elements:
            lists = [p for p in properties if p[0]]
            if not lists:
                position += count * sum(PLY_SIZES.get(p[1], 1) for p in properties)
            elif count > 0:
                position = self.walk_records(name, count, properties, position)
            if position > self.size:
                raise ReadFailure("its %s elements end past the file's %d bytes"
                                  % (name, self.size))

    def count_at(self, kind, position):
        import numpy
        if position + PLY_SIZES.get(kind, 1) > self.size:
            return None
        return int(numpy.frombuffer(self.data, self.order + self.NUMPY.get(kind, "u1"), 1,
                                    position)[0])

    def record(self, properties, position, name):
        """(size, [(offset, count type, count)]) of the record at position."""
        start, counts = position, []
        for count_type, value_type in properties:
            if count_type is None:
                position += PLY_SIZES.get(value_type, 1)
                continue
            n = self.count_at(count_type, position)
            if n is None or n < 0 or position + n * PLY_SIZES.get(value_type, 1) > self.size:
                raise ReadFailure("its %s element at byte %d announces a list of %s values, "
                                  "past the file's %d bytes" % (name, start, n, self.size))
            counts.append((position - start, count_type, n))
            position += PLY_SIZES.get(count_type, 1) + n * PLY_SIZES.get(value_type, 1)
        return position - start, counts

    def walk_records(self, name, count, properties, position):
        """Where the records end. The common file (every face a triangle) is checked at once:
        if all records have the first one's list counts, they are equal-sized."""
        import numpy
        size, counts = self.record(properties, position, name)
        if position + count * size <= self.size:
            rows = numpy.frombuffer(self.data, numpy.uint8, count * size, position)
            rows = rows.reshape(count, size)
            if all((rows[:, offset:offset + PLY_SIZES.get(kind, 1)].copy().view(
                    self.order + self.NUMPY.get(kind, "u1")).ravel() == n).all()
                   for offset, kind, n in counts):
                return position + count * size
        for _ in range(count):
            size, _counts = self.record(properties, position, name)
            position += size
        return position


# Bytes of each legacy VTK scalar type in a BINARY file.
VTK_LEGACY_SIZES = {"bit": 1, "char": 1, "unsigned_char": 1, "short": 2, "unsigned_short": 2,
                    "int": 4, "unsigned_int": 4, "long": 8, "unsigned_long": 8, "float": 4,
                    "double": 8, "vtkidtype": 8, "vtktypeint64": 8, "vtktypeuint64": 8,
                    "vtktypeint32": 4, "vtktypeuint32": 4}


def check_vtk_legacy_counts(path):
    """Refuse a legacy VTK file whose sections announce more values than its size can hold
    (VTK's reader allocates what a count says first: `VERTICES 4294967295 ...` in a file of
    a few hundred bytes asked for 32 GB), or whose cells name points it does not have or
    cannot be told apart (VTK 9.1's reader crashes on a point id of 4294967295, or a cell
    size of 1e9). ASCII values take at least two bytes (a digit and a separator), binary ones
    their type's size; the sections are walked in order, binary payloads skipped by the size
    their header states, then each cell section is read and checked."""
    walk = _LegacyWalk(os.path.getsize(path))
    with open(path, "rb") as stream:
        head = [stream.readline() for _ in range(3)]
        walk.binary = head[2].strip().upper() == b"BINARY"
        walk.version5 = b"Version 5" in head[0]
        line = stream.readline()
        while line:
            skip = walk.section(line.decode("ascii", "replace").split())
            walk.place(stream.tell())
            if skip:
                stream.seek(skip, os.SEEK_CUR)
            line = stream.readline()
    from vtkphong._legacy_cells import check_cells
    check_cells(path, walk)


class _LegacyWalk:
    """The legacy VTK sections seen so far, and the bytes their values need at least."""

    CELL_SECTIONS = ("VERTICES", "LINES", "POLYGONS", "TRIANGLE_STRIPS", "CELLS")

    def __init__(self, size):
        self.size, self.needed = size, 0
        self.binary = self.version5 = False
        self.count = 0              # the current POINT_DATA / CELL_DATA count
        self.cells = (0, 0)         # Version 5: the offsets' and connectivity's lengths
        self.scalars = None         # SCALARS' values and type, due after LOOKUP_TABLE
        self.points = 0             # POINTS' count
        self.cell_sections = []     # [keyword, (cells, values) or [offsets, connectivity]]
        self.unplaced = None        # a cell payload whose file offset comes next

    def place(self, offset):
        """The file offset where the section just read has its values."""
        if self.unplaced is not None:
            self.unplaced.append(offset)
            self.unplaced = None

    def section(self, words):
        """The binary payload's bytes after the header line `words` (0 in ASCII)."""
        if not words:
            return 0
        keyword, numbers = words[0].upper(), [w for w in words[1:] if w.isdigit()]
        if keyword in ("POINT_DATA", "CELL_DATA") and numbers:
            self.count = int(numbers[0])
            return 0
        if keyword == "SCALARS" and len(words) >= 3:
            components = int(words[3]) if len(words) >= 4 and words[3].isdigit() else 1
            self.scalars = (self.count * components, words[2])
            return 0
        if keyword == "LOOKUP_TABLE" and len(words) == 2 and self.scalars:
            values, self.scalars = self.scalars, None
            return self.values(values[0], values[1], "SCALARS")
        if keyword in self.CELL_SECTIONS and len(numbers) >= 2:
            if self.version5:
                self.cells = (int(numbers[0]), int(numbers[1]))
                self.cell_sections.append([keyword, self.cells])
                return 0
            # Each of the n cells takes its size and at least one point id: 2n values at least.
            self.unplaced = [keyword, (int(numbers[0]), int(numbers[1])), "int"]
            self.cell_sections.append(self.unplaced)
            return self.values(max(int(numbers[1]), 2 * int(numbers[0])), "int", keyword)
        if keyword in ("OFFSETS", "CONNECTIVITY") and len(words) >= 2 and self.cell_sections:
            length = self.cells[0] if keyword == "OFFSETS" else self.cells[1]
            self.unplaced = [keyword, length, words[1]]
            self.cell_sections[-1].append(self.unplaced)
            return self.values(length, words[1], keyword)
        if keyword == "POINTS" and numbers:
            self.points = int(numbers[0])
        announced = self.announced(keyword, words, numbers)
        return self.values(announced[0], announced[1], keyword) if announced else 0

    def announced(self, keyword, words, numbers):
        """(values, type) of the other sections, or None."""
        if keyword == "POINTS" and len(words) >= 3 and numbers:
            return 3 * int(numbers[0]), words[2]
        if keyword == "CELL_TYPES" and numbers:
            return int(numbers[0]), "int"
        if keyword in ("VECTORS", "NORMALS") and len(words) >= 3:
            return 3 * self.count, words[2]
        if keyword == "TENSORS" and len(words) >= 3:
            return 9 * self.count, words[2]
        if keyword == "TEXTURE_COORDINATES" and len(words) >= 4 and words[2].isdigit():
            return int(words[2]) * self.count, words[3]
        if keyword == "COLOR_SCALARS" and numbers:
            return int(numbers[-1]) * self.count, "unsigned_char"
        if keyword == "LOOKUP_TABLE" and len(words) == 3 and words[2].isdigit():
            return 4 * int(words[2]), "unsigned_char"
        if keyword in ("X_COORDINATES", "Y_COORDINATES", "Z_COORDINATES") and \
                len(words) >= 3 and numbers:
            return int(numbers[0]), words[2]
        if len(words) == 4 and words[1].isdigit() and words[2].isdigit() and \
                words[3].lower() in VTK_LEGACY_SIZES:
            return int(words[1]) * int(words[2]), words[3]  # an array of a FIELD
        return None

    def values(self, count, scalar, keyword):
        width = VTK_LEGACY_SIZES.get(scalar.lower(), 1) if self.binary else 2
        self.needed += count * width
        if self.needed > self.size:
            raise ReadFailure("its %s section announces %d values, more than the file's %d "
                              "bytes can hold" % (keyword, count, self.size))
        return count * width if self.binary else 0


def _read_vtk(path, extension):
    if extension == ".vtp":
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader as Reader
    elif extension == ".vtu":
        from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader as Reader
    else:
        from vtkmodules.vtkIOLegacy import vtkGenericDataObjectReader as Reader
    reader = Reader()
    reader.SetFileName(path)
    reader.Update()
    return _surface_of(reader.GetOutput())


def _surface_of(output):
    """A .vtu or legacy .vtk file may hold any dataset: its outer surface is drawn."""
    if output is not None and output.IsA("vtkDataSet") and not output.IsA("vtkPolyData"):
        from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
        surface = vtkDataSetSurfaceFilter()
        surface.SetInputData(output)
        surface.Update()
        return surface.GetOutput()
    if output is None or not output.IsA("vtkPolyData"):
        raise ReadFailure("it holds no dataset")
    return output


def _read_assimp(path):
    from vtkphong import vtkPhongAssimpReader
    from vtkphong.materials import material_of
    reader = vtkPhongAssimpReader()
    reader.SetFileName(path)
    reader.Update()
    blocks = reader.GetOutput()
    parts = []
    for index in range(blocks.GetNumberOfBlocks()):
        block = blocks.GetBlock(index)
        if block is not None and block.IsA("vtkPolyData"):
            material = material_of(block)
            texture = material.pop("diffuse_texture", None) if material else None
            parts.append((block, material, texture))
    return parts


# --- writing what was read ------------------------------------------------------

def write_parts(parts, directory):
    """part<N>.vtp (+ texture<N>.vti) per non-empty part, and parts.json listing them."""
    listing = []
    from vtkphong._meshio import polydata_problem
    for polydata, material, texture in parts:
        if polydata.GetNumberOfCells() == 0:
            continue
        problem = polydata_problem(polydata)
        if problem:
            raise ReadFailure(problem)
        number = len(listing)
        entry = {"file": "part%d.vtp" % number, "material": material, "texture": None}
        _write_polydata(polydata, os.path.join(directory, entry["file"]))
        if texture and polydata.GetPointData().GetTCoords() is not None:
            entry["texture"] = _write_texture(texture, directory, number)
        listing.append(entry)
    with open(os.path.join(directory, "parts.json"), "w", encoding="utf-8") as stream:
        json.dump(listing, stream)
    return len(listing)


def _write_polydata(polydata, path):
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    # The material travels in parts.json; field data (strings of any encoding) stays here.
    polydata.GetFieldData().Initialize()
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(polydata)
    writer.SetFileName(path)
    writer.SetDataModeToBinary()
    if not writer.Write():
        raise ReadFailure("cannot write its geometry to %s" % path)


def _write_texture(texture, directory, number):
    """The texture image as a .vti, or None when it is missing or unreadable: a texture is
    an ornament, not a reason to refuse the mesh."""
    from vtkmodules.vtkIOImage import vtkImageReader2Factory
    from vtkmodules.vtkIOXML import vtkXMLImageDataWriter
    if not os.path.isfile(texture):
        return None
    reader = vtkImageReader2Factory.CreateImageReader2(texture)
    if reader is None:
        return None
    reader.SetFileName(texture)
    reader.Update()
    image = reader.GetOutput()
    if image is None or image.GetNumberOfPoints() == 0:
        return None
    name = "texture%d.vti" % number
    writer = vtkXMLImageDataWriter()
    writer.SetInputData(image)
    writer.SetFileName(os.path.join(directory, name))
    return name if writer.Write() else None


# --- the child process ----------------------------------------------------------

def _first_error(collector):
    """VTK's first error message, on one printable line, or ''."""
    text = collector.GetOutput()
    if isinstance(text, bytes):
        text = text.decode("utf-8", "replace")
    for block in text.split("\n\n"):
        if "ERROR" in block:
            message = " ".join(block.split("\n")[1:]) if "\n" in block else block
            if "): " in message:
                message = message.split("): ", 1)[1]
            message = "".join(c if " " <= c <= "~" else "?" for c in message).strip()
            return message if len(message) <= 200 else message[:197] + "..."
    return ""


def main(arguments):
    """Read arguments[0] into the directory arguments[1]; the exit status."""
    from vtkmodules.vtkCommonCore import vtkLogger, vtkOutputWindow, vtkStringOutputWindow
    collector = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(collector)
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
    path, directory = arguments
    try:
        count = write_parts(read_parts(path), directory)
    except ReadFailure as failure:
        count, reason = 0, str(failure)
    except MemoryError:
        count, reason = 0, "out of memory"
    else:
        reason = "it holds no geometry"
    if count == 0:
        vtk_reason = _first_error(collector)
        sys.stderr.write((vtk_reason or reason) + "\n")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
