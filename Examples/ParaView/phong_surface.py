"""Render an isosurface with vtkPhong's "Phong Surface" representation in ParaView.

Runs serially or on several MPI ranks (each rank contours and lights its own piece; IceT
composites the picture):

    pvbatch --disable-xdisplay-test phong_surface.py --plugin PhongLighting.so
    mpiexec -np 2 pvbatch --disable-xdisplay-test phong_surface.py --plugin PhongLighting.so

In the ParaView GUI, load the plugin (Tools > Manage Plugins, on the client and the
server), then pick "Phong Surface" in the representation menu; the properties below are
in the Properties panel (advanced).
"""

import argparse

from paraview.simple import (AddLight, Contour, CreateRenderView, LoadPlugin, Render,
                             SaveScreenshot, Show, Wavelet)

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--plugin", default="PhongLighting",
                    help="the plugin's file, or its name when ParaView can find it")
parser.add_argument("--output", default="phong_surface.png")
args = parser.parse_args()

LoadPlugin(args.plugin, remote=False, ns=globals())

# A smooth, curved surface from ParaView's own data: an isosurface of the Wavelet source.
wavelet = Wavelet(WholeExtent=[-40, 40, -40, 40, -40, 40])
surface = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[160.0])

view = CreateRenderView()
view.ViewSize = [800, 600]
view.OrientationAxesVisibility = 0
view.UseLight = 0  # no light kit: the three lights below are the scene's lighting

key = AddLight(view=view)  # a directional key light, warm
key.Coords = "Camera"
key.Position = [1.0, 1.0, 1.0]
key.DiffuseColor = [1.0, 0.95, 0.85]
key.Intensity = 0.8
fill = AddLight(view=view)  # a positional fill light from the left, cool
fill.Coords = "Camera"
fill.Type = "Positional"
fill.ConeAngle = 90.0
fill.Position = [-2.0, 0.0, 1.0]
fill.FocalPoint = [0.0, 0.0, 0.0]
fill.DiffuseColor = [0.6, 0.7, 1.0]
fill.Intensity = 0.4
spot = AddLight(view=view)  # a spot from above, narrow
spot.Coords = "Camera"
spot.Type = "Positional"
spot.ConeAngle = 20.0
spot.Position = [0.0, 2.0, 1.0]
spot.FocalPoint = [0.0, 0.0, 0.0]
spot.Intensity = 0.5

display = Show(surface, view)
display.SetRepresentationType("Phong Surface")
display.ColorArrayName = [None, ""]
display.DiffuseColor = [0.75, 0.55, 0.35]
display.Specular = 0.6
display.LightingModel = "Blinn-Phong"
display.Shininess = 400.0       # beyond vtkProperty's 128
display.NormalsWeighting = "Max"  # normals computed on each rank's piece

view.ResetCamera()
Render(view)
SaveScreenshot(args.output, view, ImageResolution=[800, 600])
print(args.output)
