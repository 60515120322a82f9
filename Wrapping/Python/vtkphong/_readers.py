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

VTK_EXTENSIONS = (".vtp", ".vtu", ".vtk")


class ReadFailure(Exception):
    """The file cannot be read; the message is the reason."""


def read_parts(path):
    """[(polydata, material dict or None, texture path or None)] of the file."""
    extension = os.path.splitext(path)[1].lower()
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
    on a truncated header) or announces more elements than the file's size can hold."""
    with open(path, "rb") as stream:
        head = stream.read(65536)
    end = head.find(b"end_header")
    if not head.startswith(b"ply") or end < 0:
        raise ReadFailure("not a PLY file, or its header does not end in its first 64 KiB")
    header = head[:end].decode("ascii", "replace").splitlines()
    needed = _ply_smallest_size(header, b"binary" in head[:end])
    if needed > os.path.getsize(path) - end:
        raise ReadFailure("its header announces elements needing at least %d bytes; the file"
                          " has %d" % (needed, os.path.getsize(path)))


def _ply_smallest_size(header, binary):
    """The fewest bytes the elements of a PLY header can take: per element, the sum of its
    scalar sizes (a list: its count's) in binary, a digit and a separator in ASCII."""
    total, count = 0, 0
    for line in header:
        words = line.split()
        if len(words) == 3 and words[0] == "element":
            if not words[2].isdigit():
                raise ReadFailure("its header's element %r has no count" % words[1])
            count = int(words[2])
            total += 0 if binary else 2 * count
        elif binary and len(words) >= 3 and words[0] == "property":
            scalar = words[2] if words[1] == "list" else words[1]
            total += count * PLY_SIZES.get(scalar, 1)
    return total


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
