"""A studio rig of four lights of three kinds on a mesh standing on a floor.

A warm key spot with a soft edge, a cool directional fill, a rim light behind
the subject and a coloured point "kicker" with distance attenuation; every
light's ambient, diffuse and specular colours count, as does the renderer's
ambient light.

    PYTHONPATH=<vtkphong>/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        studio_lighting.py bunny00.off -o studio.png
"""

import argparse

import vtkphong
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkRenderWindow, vtkRenderer,
                                         vtkWindowToImageFilter)

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("mesh", help="an OFF file, e.g. CGAL's bunny00.off")
parser.add_argument("-o", "--output", default="studio.png")
parser.add_argument("--size", type=int, nargs=2, default=(800, 600), metavar=("W", "H"))
args = parser.parse_args()

reader = vtkphong.vtkPhongOFFReader()
reader.SetFileName(args.mesh)
reader.Update()
mesh = reader.GetOutput()
x0, x1, y0, y1, z0, z1 = mesh.GetBounds()
size = max(x1 - x0, y1 - y0, z1 - z0)
center = ((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2)


def at(dx, dy, dz):
    """A point relative to the subject, in units of its size (y is up)."""
    return (center[0] + dx * size, y0 + dy * size, center[2] + dz * size)


subject = vtkActor()
subject_mapper = vtkphong.vtkPhongPolyDataMapper()  # computes the normals the file lacks
subject_mapper.SetInputData(mesh)
subject.SetMapper(subject_mapper)
skin = vtkphong.vtkPhongProperty()
skin.SetLightingModelToNormalizedBlinnPhong()  # highlights keep their energy as n grows
skin.SetColor(0.75, 0.72, 0.7)
skin.SetSpecularColor(1.0, 1.0, 1.0)
skin.SetAmbient(0.15)
skin.SetSpecular(0.3)
skin.SetShininess(200.0)
subject.SetProperty(skin)

floor_source = vtkPlaneSource()
floor_source.SetOrigin(*at(-2, 0, -2))
floor_source.SetPoint1(*at(2, 0, -2))
floor_source.SetPoint2(*at(-2, 0, 2))
floor_source.SetResolution(64, 64)
floor_mapper = vtkphong.vtkPhongPolyDataMapper()
floor_mapper.SetInputConnection(floor_source.GetOutputPort())
floor = vtkActor()
floor.SetMapper(floor_mapper)
floor_material = vtkphong.vtkPhongProperty()
floor_material.SetColor(0.35, 0.35, 0.38)
floor_material.SetSpecularColor(1.0, 1.0, 1.0)
floor_material.SetAmbient(0.2)
floor_material.SetSpecular(0.2)
floor_material.SetShininess(30.0)
floor.SetProperty(floor_material)

renderer = vtkRenderer()
renderer.AddActor(subject)
renderer.AddActor(floor)
renderer.SetBackground(0.02, 0.02, 0.03)
renderer.SetAmbient(0.15, 0.15, 0.2)
renderer.AutomaticLightCreationOff()

key = vtkLight()  # a warm spot from the upper left front, with a soft edge
key.SetLightTypeToSceneLight()
key.SetPositional(True)
key.SetPosition(*at(-1.2, 2.0, 1.5))
key.SetFocalPoint(*at(0, 0.3, 0))
key.SetConeAngle(30.0)
key.SetExponent(2.0)
key.SetColor(1.0, 0.9, 0.75)
key.SetIntensity(1.2)
skin.SetSoftSpotEdge(True)
skin.SetSpotEdgeWidth(8.0)
floor_material.SetSoftSpotEdge(True)
floor_material.SetSpotEdgeWidth(8.0)

fill = vtkLight()  # a cool, dim directional light from the right
fill.SetLightTypeToSceneLight()
fill.SetPosition(*at(2.0, 0.8, 1.0))
fill.SetFocalPoint(*at(0, 0.3, 0))
fill.SetColor(0.7, 0.8, 1.0)
fill.SetIntensity(0.35)

rim = vtkLight()  # behind and above: bright edges, its highlight in white only
rim.SetLightTypeToSceneLight()
rim.SetPosition(*at(0.3, 1.5, -2.0))
rim.SetFocalPoint(*at(0, 0.4, 0))
rim.SetDiffuseColor(0.6, 0.6, 0.6)
rim.SetSpecularColor(1.0, 1.0, 1.0)

kicker = vtkLight()  # a teal point light low on the right, fading with distance
kicker.SetLightTypeToSceneLight()
kicker.SetPositional(True)
kicker.SetConeAngle(180.0)
kicker.SetPosition(*at(0.9, 0.2, 0.6))
kicker.SetColor(0.2, 0.9, 0.8)
kicker.SetAmbientColor(0.0, 0.08, 0.07)
kicker.SetAttenuationValues(0.5, 0.0, 4.0 / (size * size))

for light in (key, fill, rim, kicker):
    renderer.AddLight(light)

window = vtkRenderWindow()
window.SetOffScreenRendering(True)
window.SetSize(*args.size)
window.AddRenderer(renderer)
camera = renderer.GetActiveCamera()
camera.SetFocalPoint(*at(0, 0.45, 0))
camera.SetPosition(*at(0.6, 1.0, 2.6))
camera.SetViewUp(0.0, 1.0, 0.0)
renderer.ResetCameraClippingRange()
window.Render()

grab = vtkWindowToImageFilter()
grab.SetInput(window)
writer = vtkPNGWriter()
writer.SetFileName(args.output)
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
print(args.output)
