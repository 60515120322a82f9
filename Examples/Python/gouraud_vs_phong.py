"""Per-vertex Gouraud next to per-fragment Phong on the same coarse sphere.

Gouraud evaluates the lighting at the vertices and interpolates colours: the
highlight falls between vertices and turns into a star of facets. Phong
interpolates the normal and evaluates the lighting at every pixel. (A plain
vtkProperty's "Gouraud" is shaded per fragment by VTK and by vtkPhong alike;
true per-vertex Gouraud is vtkPhongProperty.SetInterpolationToPerVertexGouraud.)

    PYTHONPATH=<vtkphong>/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        gouraud_vs_phong.py -o gouraud_vs_phong.png
"""

import argparse

import vtkphong
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkRenderWindow, vtkRenderer,
                                         vtkTextActor, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text)

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("-o", "--output", default="gouraud_vs_phong.png")
parser.add_argument("--resolution", type=int, default=16, help="sphere resolution")
args = parser.parse_args()

sphere = vtkSphereSource()
sphere.SetThetaResolution(args.resolution)
sphere.SetPhiResolution(args.resolution)

window = vtkRenderWindow()
window.SetOffScreenRendering(True)
window.SetSize(800, 400)

for index, (title, per_vertex) in enumerate((("per-vertex Gouraud", True), ("Phong", False))):
    material = vtkphong.vtkPhongProperty()
    material.SetColor(0.2, 0.45, 0.8)
    material.SetSpecularColor(1.0, 1.0, 1.0)
    material.SetAmbient(0.1)
    material.SetSpecular(0.8)
    material.SetShininess(80.0)
    if per_vertex:
        material.SetInterpolationToPerVertexGouraud()
    else:
        material.SetInterpolationToPhong()
    mapper = vtkphong.vtkPhongPolyDataMapper()
    mapper.SetInputConnection(sphere.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.SetProperty(material)

    renderer = vtkRenderer()
    renderer.SetViewport(index * 0.5, 0.0, index * 0.5 + 0.5, 1.0)
    renderer.SetBackground(0.1, 0.1, 0.12)
    renderer.AddActor(actor)
    light = vtkLight()
    light.SetLightTypeToCameraLight()
    light.SetPosition(0.35, 0.45, 1.0)
    renderer.AddLight(light)
    label = vtkTextActor()
    label.SetInput(title)
    label.GetTextProperty().SetFontSize(20)
    label.SetPosition(12, 12)
    renderer.AddActor2D(label)
    renderer.ResetCamera()
    window.AddRenderer(renderer)

window.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(window)
writer = vtkPNGWriter()
writer.SetFileName(args.output)
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
print(args.output)
