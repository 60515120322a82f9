"""Reading the mesh files of vtkphong-render: one Part per piece of geometry.

Most formats are one VTK reader each. OBJ goes through VTK's importer instead,
because only the importer reads the .mtl materials; and STL files are checked
first, because vtkSTLReader would take any file for binary STL.
"""

import os
import struct

from vtkphong._errors import RenderError

FORMATS = {
    ".obj": "Wavefront OBJ, with the colours and Ns shininess of its .mtl file",
    ".ply": "PLY (its vertex colours are used)",
    ".stl": "STL, ASCII or binary",
    ".off": "OFF (polygons of any size, vertex colours)",
    ".vtp": "VTK XML polydata",
    ".vtk": "VTK legacy file (any dataset; its outer surface is drawn)",
}


class Part:
    """A piece of geometry with, for OBJ files, the material of its .mtl."""

    def __init__(self, polydata, material=None, texture=None):
        self.polydata = polydata
        self.material = material  # a vtkProperty from the file, or None
        self.shininess = None     # the file's Ns
        self.texture = texture


def read_mesh(path, progress, warnings):
    """The mesh's parts; RenderError when it cannot be read."""
    extension = os.path.splitext(path)[1].lower()
    if extension not in FORMATS:
        raise RenderError("cannot read %s: unknown extension %r (known: %s)"
                          % (path, extension, ", ".join(FORMATS)))
    if not os.path.isfile(path):
        raise RenderError("cannot read %s: no such file" % path)
    if extension == ".obj":
        parts = _read_obj(path, warnings)
    else:
        parts = [Part(_read_polydata(path, extension, progress))]
    if sum(part.polydata.GetNumberOfCells() for part in parts) == 0:
        raise RenderError("cannot read %s: it holds no geometry" % path)
    return parts


# --- every format but OBJ: a VTK reader -----------------------------------------

def _read_polydata(path, extension, progress):
    if extension == ".stl":
        _check_stl(path)
    reader = _reader_for(extension)
    reader.SetFileName(path)
    progress.observe(reader, "reading")
    reader.Update()
    output = _surface_of(reader.GetOutput())
    if output is None or not output.IsA("vtkPolyData"):
        raise RenderError("cannot read %s: it holds no dataset" % path)
    return output


def _reader_for(extension):
    # Imported here: each VTK module loads only when its format is read.
    if extension == ".stl":
        from vtkmodules.vtkIOGeometry import vtkSTLReader as Reader
    elif extension == ".ply":
        from vtkmodules.vtkIOPLY import vtkPLYReader as Reader
    elif extension == ".off":
        from vtkphong import vtkPhongOFFReader as Reader
    elif extension == ".vtp":
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader as Reader
    else:
        from vtkmodules.vtkIOLegacy import vtkGenericDataObjectReader as Reader
    return Reader()


def _surface_of(output):
    """A legacy .vtk file may hold any dataset: its outer surface is what is drawn."""
    if output is not None and output.IsA("vtkDataSet") and not output.IsA("vtkPolyData"):
        from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
        surface = vtkDataSetSurfaceFilter()
        surface.SetInputData(output)
        surface.Update()
        return surface.GetOutput()
    return output


def _check_stl(path):
    """vtkSTLReader reads any file as binary STL; refuse files that are neither."""
    with open(path, "rb") as stream:
        head = stream.read(1024)
    if head.lstrip().lower().startswith(b"solid") and all(
            byte in b"\t\n\r" or 32 <= byte < 127 for byte in head):
        return  # ASCII
    size = os.path.getsize(path)
    if size < 84:
        raise RenderError("cannot read %s: not an STL file (too short)" % path)
    (count,) = struct.unpack("<I", head[80:84])
    if size != 84 + 50 * count:
        raise RenderError("cannot read %s: not an STL file (as binary STL it would hold %d"
                          " triangles in %d bytes; it has %d)"
                          % (path, count, 84 + 50 * count, size))


# --- OBJ: VTK's importer, for the materials --------------------------------------

def _read_obj(path, warnings):
    from vtkmodules.vtkIOImport import vtkOBJImporter
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow
    # The importer makes actors in a render window's renderer; nothing is drawn in it.
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    importer = vtkOBJImporter()
    importer.SetFileName(path)
    importer.SetTexturePath(os.path.dirname(os.path.abspath(path)))
    has_materials, shininess = _material_library(importer, path, warnings)
    importer.SetRenderWindow(window)
    importer.Update()
    parts = _obj_parts(importer, renderer, has_materials, shininess)
    # The importer keeps its render window; it is not needed any more.
    window.Finalize()
    return parts


def _material_library(importer, path, warnings):
    """Whether the OBJ's .mtl file is there (then the importer reads it), and its Ns
    values: the importer clamps those, the command does not."""
    library = _mtl_library(path)
    if library is None:
        return False, {}
    if not os.path.isfile(library):
        warnings.append("%s names the material file %s, which is missing; the default"
                        " material is used" % (path, library))
        return False, {}
    importer.SetFileNameMTL(library)
    return True, _mtl_shininess(library)


def _obj_parts(importer, renderer, has_materials, shininess):
    """A Part per non-empty actor the importer made, with its .mtl material when it
    has one."""
    parts = []
    actors = renderer.GetActors()
    actors.InitTraversal()
    for index in range(actors.GetNumberOfItems()):
        actor = actors.GetNextActor()
        polydata = actor.GetMapper().GetInput() if actor.GetMapper() else None
        if polydata is None or polydata.GetNumberOfCells() == 0:
            continue
        description = importer.GetOutputDescription(index)
        name = None
        if " with material named " in description:
            name = description.split(" with material named ", 1)[1].split(" texture file ")[0]
        part = Part(polydata)
        if name is not None and name != "x" and has_materials:
            part.material = actor.GetProperty()
            part.shininess = shininess.get(name)
            part.texture = actor.GetTexture()
        parts.append(part)
    return parts


def _mtl_library(obj_path):
    """The .mtl file an OBJ names (mtllib), or None."""
    with open(obj_path, "rb") as stream:
        for raw in stream:
            line = raw.decode("utf-8", "replace").strip()
            if line.startswith("mtllib "):
                return os.path.join(os.path.dirname(obj_path), line[7:].strip())
    return None


def _mtl_shininess(mtl_path):
    """Ns of each material of an .mtl file (VTK's importer clamps it)."""
    shininess = {}
    current = None
    with open(mtl_path, "rb") as stream:
        for raw in stream:
            parts = raw.decode("utf-8", "replace").split()
            if len(parts) >= 2 and parts[0] == "newmtl":
                current = parts[1]
            elif len(parts) >= 2 and parts[0] == "Ns" and current is not None:
                try:
                    shininess[current] = float(parts[1])
                except ValueError:
                    pass
    return shininess
