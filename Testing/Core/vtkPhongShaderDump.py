"""Render 6720 scene variants and write, for each, the shader signature, the hashes of the
vertex, geometry and fragment sources and of the pixels, and the problems reported.

For refactors of the shader path and the mappers: run it before and after, compare the two files
(`cmp`); they must be identical. Not a ctest (two minutes on llvmpipe).

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \
        Testing/Core/vtkPhongShaderDump.py before.txt
"""
import hashlib, itertools, sys, math
from vtkmodules.vtkFiltersSources import vtkSphereSource, vtkLineSource
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkActor, vtkLight, vtkWindowToImageFilter
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.util.numpy_support import vtk_to_numpy
import vtkmodules.vtkRenderingOpenGL2  # noqa
import vtkphong

out = open(sys.argv[1], "w")
problems = []
def on_error(obj, event, data=None):
    problems.append(str(data))
on_error.CallDataType = 'string0'

def light(kind, positional, cone, att=(1, 0, 0), exponent=1.0, intensity=1.0, amb=(0, 0, 0)):
    l = vtkLight()
    {"head": l.SetLightTypeToHeadlight, "camera": l.SetLightTypeToCameraLight, "scene": l.SetLightTypeToSceneLight}[kind]()
    l.SetPosition(1, 2, 3); l.SetFocalPoint(0, 0, 0)
    l.SetPositional(positional); l.SetConeAngle(cone); l.SetAttenuationValues(*att)
    l.SetExponent(exponent); l.SetIntensity(intensity); l.SetAmbientColor(*amb)
    l.SetDiffuseColor(1, .9, .8); l.SetSpecularColor(.7, .8, 1)
    return l

rigs = {
    "none": [],
    "head": [light("head", False, 30)],
    "dir+point+spot": [light("scene", False, 30), light("camera", True, 120, (1, .1, .01), amb=(.1, .1, .1)), light("scene", True, 30, exponent=3)],
    "bad": [light("scene", False, 30, intensity=float('nan')), light("scene", True, 40, att=(-1, 0, 0), exponent=-2)],
    "point-plain": [light("scene", True, 150)],
}
window = vtkRenderWindow(); window.SetOffScreenRendering(1); window.SetSize(160, 120)
count = 0
for rig, model, ks, ka, interp, view, spec, twosided, extras in itertools.product(
        rigs, [0, 1, 3], [0.0, 0.5], [0.0, 0.3], ["flat", "gouraud", "phong", "pvg"],
        [0, 1, 3, 4, 5, 6, 7, 8], [True, False], [False, True], ["", "back", "tube", "badmat", "soft", "parallel"]):
    if view not in (0, 6) and (model != 1 or interp != "phong" or extras not in ("", "back")):
        continue
    if not spec and (view != 0 or extras != ""):
        continue
    ren = vtkRenderer(); window.AddRenderer(ren)
    for l in rigs[rig]:
        ren.AddLight(l)
    ren.SetTwoSidedLighting(twosided); ren.SetAmbient(.2, .2, .3)
    src = vtkSphereSource(); src.SetThetaResolution(12); src.SetPhiResolution(12)
    m = vtkphong.vtkPhongPolyDataMapper(); m.SetInputConnection(src.GetOutputPort())
    m.SetDebugView(view); m.SetShaderSpecialization(spec); m.SetDebugLightIndex(1 if rig != "head" else 0)
    m.AddObserver(vtkCommand.ErrorEvent, on_error)
    p = vtkphong.vtkPhongProperty(); p.SetLightingModel(model); p.SetSpecular(ks); p.SetAmbient(ka)
    p.SetShininess(40); p.SetEmission(.1, 0, .05)
    if interp == "flat": p.SetInterpolationToFlat()
    elif interp == "gouraud": p.SetInterpolationToGouraud()
    elif interp == "phong": p.SetInterpolationToPhong()
    else: p.SetInterpolationToGouraud(); p.PerVertexGouraudOn()
    a = vtkActor(); a.SetMapper(m); a.SetProperty(p)
    if extras == "back":
        b = vtkphong.vtkPhongProperty(); b.SetDiffuseColor(0, 1, 0); b.SetSpecular(.3); a.SetBackfaceProperty(b)
    if extras == "tube":
        p.SetRepresentationToWireframe(); p.RenderLinesAsTubesOn(); p.SetLineWidth(4)
    if extras == "badmat":
        p.SetDiffuseColor(float('nan'), 1, 1); p.SetOpacity(float('inf'))
    if extras == "soft":
        p.SoftSpotEdgeOn(); p.SmoothTerminatorOn()
    if extras == "parallel":
        ren.GetActiveCamera().ParallelProjectionOn()
    ren.AddActor(a); ren.ResetCamera()
    problems.clear()
    window.Render()
    grab = vtkWindowToImageFilter(); grab.SetInput(window); grab.ReadFrontBufferOff(); grab.Update()
    pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).tobytes()
    key = f"{rig}|{model}|{ks}|{ka}|{interp}|{view}|{spec}|{twosided}|{extras}"
    out.write(f"=== {key}\nsig: {m.GetLastShaderSignature()}\npix: {hashlib.md5(pixels).hexdigest()}\n")
    for src_text in (m.GetLastVertexShaderSource(), m.GetLastGeometryShaderSource(), m.GetLastFragmentShaderSource()):
        out.write(f"src: {hashlib.md5((src_text or '').encode()).hexdigest()}\n")
    for pr in sorted(set(problems)):
        out.write("problem: " + pr.split(':', 2)[-1][:300].replace('\n', ' ') + "\n")
    window.RemoveRenderer(ren); count += 1
print(count, "scenes")
