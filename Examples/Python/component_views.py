"""The classic figure: the ambient, diffuse and specular terms, and their sum.

vtkPhongPolyDataMapper's debug views show one term of the lighting equation
alone (textures still multiply ambient and diffuse); the four pictures add up
to the last one.

    PYTHONPATH=<vtkphong>/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        component_views.py -o components.png [--mesh bunny00.off]
"""

import argparse

import vtkphong
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkRenderWindow, vtkRenderer,
                                         vtkTextActor, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text)

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("-o", "--output", default="components.png")
parser.add_argument("--mesh", help="an OFF file (default: a sphere)")
args = parser.parse_args()

if args.mesh:
    source = vtkphong.vtkPhongOFFReader()
    source.SetFileName(args.mesh)
else:
    source = vtkSphereSource()
    source.SetThetaResolution(96)
    source.SetPhiResolution(96)

material = vtkphong.vtkPhongProperty()
material.SetLightingModelToBlinnPhong()
material.SetColor(0.9, 0.55, 0.3)
material.SetSpecularColor(1.0, 1.0, 1.0)
material.SetAmbient(0.3)
material.SetDiffuse(0.7)
material.SetSpecular(0.6)
material.SetShininess(60.0)

window = vtkRenderWindow()
window.SetOffScreenRendering(True)
window.SetSize(800, 800)
views = (("ambient", "SetDebugViewToAmbientTerm", 0.0, 0.5),
         ("diffuse", "SetDebugViewToDiffuseTerm", 0.5, 0.5),
         ("specular", "SetDebugViewToSpecularTerm", 0.0, 0.0),
         ("final", "SetDebugViewToFinal", 0.5, 0.0))
for title, set_view, x, y in views:
    mapper = vtkphong.vtkPhongPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    getattr(mapper, set_view)()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.SetProperty(material)  # one material shared by the four views
    renderer = vtkRenderer()
    renderer.SetViewport(x, y, x + 0.5, y + 0.5)
    renderer.SetBackground(0.08, 0.08, 0.1)
    renderer.SetAmbient(0.8, 0.8, 0.9)
    renderer.AddActor(actor)
    key = vtkLight()
    key.SetLightTypeToCameraLight()
    key.SetPosition(-0.4, 0.5, 1.0)
    fill = vtkLight()
    fill.SetLightTypeToCameraLight()
    fill.SetPosition(0.9, -0.2, 0.6)
    fill.SetColor(0.5, 0.6, 0.9)
    renderer.AddLight(key)
    renderer.AddLight(fill)
    label = vtkTextActor()
    label.SetInput(title)
    label.GetTextProperty().SetFontSize(22)
    label.SetPosition(10, 10)
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
