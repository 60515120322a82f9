"""Read a mesh, compute its normals, light it, render offscreen, save a PNG.

The vtkPhong version of the first script every VTK user writes:

    PYTHONPATH=<vtkphong>/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        render_mesh.py bunny00.off -o bunny.png

Reads OFF, PLY, STL, OBJ and VTP files.
"""

import argparse
import os
import sys

import vtkphong
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkRenderWindow, vtkRenderer,
                                         vtkWindowToImageFilter)

READERS = {".off": vtkphong.vtkPhongOFFReader, ".ply": vtkPLYReader, ".stl": vtkSTLReader,
           ".obj": vtkOBJReader, ".vtp": vtkXMLPolyDataReader}

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("mesh")
parser.add_argument("-o", "--output", default="mesh.png")
parser.add_argument("--size", type=int, nargs=2, default=(800, 600), metavar=("W", "H"))
args = parser.parse_args()

extension = os.path.splitext(args.mesh)[1].lower()
if extension not in READERS:
    sys.exit("render_mesh.py: no reader for %s files" % extension)
reader = READERS[extension]()
reader.SetFileName(args.mesh)

# Normals on OpenMesh's halfedge structure, split at 40 degree creases. (The mapper
# would compute them by itself for a mesh without normals; the filter is shown here.)
normals = vtkphong.vtkOpenMeshNormals()
normals.SetInputConnection(reader.GetOutputPort())
normals.SetFeatureAngle(40.0)
normals.SetWeightingToMax()

mapper = vtkphong.vtkPhongPolyDataMapper()
mapper.SetInputConnection(normals.GetOutputPort())

material = vtkphong.vtkPhongProperty()
material.SetLightingModelToBlinnPhong()
material.SetColor(0.85, 0.6, 0.45)
material.SetAmbient(0.1)
material.SetDiffuse(0.8)
material.SetSpecular(0.5)
material.SetSpecularColor(1.0, 1.0, 1.0)  # SetColor tinted it
material.SetShininess(120.0)

actor = vtkActor()
actor.SetMapper(mapper)
actor.SetProperty(material)

renderer = vtkRenderer()
renderer.AddActor(actor)
renderer.SetBackground(0.1, 0.1, 0.12)
renderer.SetAmbient(0.3, 0.3, 0.35)  # stock VTK ignores it; vtkPhong does not

# A key light and a fill light that follow the camera.
key = vtkLight()
key.SetLightTypeToCameraLight()
key.SetPosition(-0.5, 0.6, 1.0)
key.SetIntensity(0.9)
fill = vtkLight()
fill.SetLightTypeToCameraLight()
fill.SetPosition(0.8, 0.0, 1.0)
fill.SetColor(0.8, 0.85, 1.0)
fill.SetIntensity(0.35)
renderer.AddLight(key)
renderer.AddLight(fill)

window = vtkRenderWindow()
window.SetOffScreenRendering(True)
window.SetSize(*args.size)
window.AddRenderer(renderer)
renderer.ResetCamera()
renderer.GetActiveCamera().Azimuth(30.0)
renderer.GetActiveCamera().Elevation(15.0)
renderer.ResetCamera()
window.Render()

grab = vtkWindowToImageFilter()
grab.SetInput(window)
writer = vtkPNGWriter()
writer.SetFileName(args.output)
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
print(args.output)
