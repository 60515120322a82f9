"""The PhongLighting plugin in ParaView's engine, run by pvbatch (serial or under MPI) or
by pvpython connected to a pvserver.

    pvbatch [--disable-xdisplay-test] TestPhongParaView.py --plugin PhongLighting.so \\
        --baseline B.png --out DIR [--server HOST:PORT]

The verdict is the output: "ERROR:" lines on failure, "all checks passed" otherwise.

A sphere (ParaView's Sphere source, which every rank generates a piece of) coloured by
the rank that owns each piece is drawn with the "Phong Surface" representation under a
directional, a point and a spot light. Checks, each failing with "ERROR:":

1. the plugin offers "Phong Surface" for polydata and for unstructured grids;
2. the composited picture matches the serial baseline (the same picture whatever the
   number of ranks);
3. with N ranks, N rank colours are on screen (every rank's piece reached the image);
4. in the ShadingNormal debug view every visible pixel of every rank's piece is a unit
   normal encoded as (N + 1) / 2: only vtkPhong's shader draws that, so each rank's piece
   was lit by it;
5. the back faces of the sphere are culled serially (closed) and not under MPI (each
   rank's piece is open), and culling off draws the same picture;
6. nested contours drawn with the depth pre-pass on: used, and the same picture as without;
7. "Error Budget" is accepted on every rank, and at 3 levels every pixel stays within 3
   levels (and 8-bit rounding) of the exact picture (this scene's point and spot lights keep
   it per fragment: only light culling may spend the budget); under the key light alone and
   32 levels the sphere is lit at its vertices ("UsedBudgetMode" 2, pvbatch) and stays within
   32 levels of its exact picture;
8. "Specular Anti-Aliasing" changes a highlight narrower than a pixel, and off gives the
   exact picture back.
"""

import argparse
import math
import os

from phong_paraview_testing import fail, load_plugin, prefer_pythonpath, report

prefer_pythonpath()

from paraview.simple import (  # noqa: E402 (after the path fix)
    AddLight, ColorBy, Contour, CreateRenderView, GetColorTransferFunction, GetParaViewVersion,
    Render,
    ResetCamera, SaveScreenshot, Show, Sphere, Tessellate, Wavelet)
import paraview.simple  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402

# ParaView 6 renamed "Process Id Scalars" (array ProcessId) to "Process Ids" (PointProcessIds).
ProcessIds = getattr(paraview.simple, "ProcessIds", None) or paraview.simple.ProcessIdScalars

SIZE = (400, 300)


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    components = scalars.GetNumberOfComponents()
    pixels = [scalars.GetTuple(i)[:3] for i in range(width * height)]
    return width, height, components, pixels


def background(pixel):
    return max(pixel) < 8  # the view's background is black


def add_lights(view):
    """A directional key, a point and a spot light (ParaView light proxies, so that they
    reach a pvserver's ranks), the light kit off."""
    view.UseLight = 0  # the picture depends on these lights only
    key = AddLight(view=view)
    key.Coords = "Scene"
    key.Type = "Directional"
    key.Position = [1.0, 1.0, 2.0]
    key.Intensity = 0.7
    point = AddLight(view=view)
    point.Coords = "Scene"
    point.Type = "Positional"
    point.ConeAngle = 90.0  # ParaView's widest: a point light's cone test never cuts
    point.Position = [-1.5, 0.3, 1.0]
    point.FocalPoint = [0.0, 0.0, 0.0]
    point.DiffuseColor = [1.0, 0.8, 0.6]
    spot = AddLight(view=view)
    spot.Coords = "Scene"
    spot.Type = "Positional"
    spot.ConeAngle = 15.0
    spot.Position = [0.4, 1.5, 1.5]
    spot.FocalPoint = [0.15, 0.1, 0.3]
    spot.Intensity = 0.6
    return key, point, spot


def check_back_face_culling(display, view, ranks, culled_picture, out, server):
    """5: serially the sphere is closed and its hidden back faces are culled; split between
    ranks each piece is open and drawn whole. Culling off draws the same picture. (Connected
    to a pvserver, the information properties read 0 whatever the server's ranks drew,
    apparently the client's copy of the representation, which does not draw: only the
    pictures are checked there.)"""
    display.UpdatePropertyInformation()
    used = display.GetPropertyValue("UsedClosedSurfaceCulling")
    print("back faces culled: %s" % used)
    if not server and used != (1 if ranks == 1 else 0):
        fail("back-face culling %s with %d rank(s)" % ("used" if used else "not used", ranks))
    display.CullHiddenBackFaces = 0
    Render(view)
    path = os.path.join(out, "PhongParaView-%dranks-unculled.png" % ranks)
    SaveScreenshot(path, view, ImageResolution=list(SIZE))
    _, _, _, unculled = read_png(path)
    differing = sum(1 for a, b in zip(unculled, culled_picture) if a != b)
    print("culling off: %d pixels differ" % differing)
    if len(unculled) != len(culled_picture) or differing > 4:
        fail("culling the back faces changed %d pixels" % differing)
    display.CullHiddenBackFaces = 1


def check_error_budget(display, view, ranks, exact_picture, out):
    """7: the picture under an error budget of 3 levels stays within it of the exact one
    (one more level for the 8-bit rounding of each)."""
    display.ErrorBudget = 3.0
    Render(view)
    path = os.path.join(out, "PhongParaView-%dranks-budget.png" % ranks)
    SaveScreenshot(path, view, ImageResolution=list(SIZE))
    _, _, _, budget_picture = read_png(path)
    largest = largest_difference(budget_picture, exact_picture)
    print("error budget 3 levels: largest difference %d levels" % largest)
    if len(budget_picture) != len(exact_picture) or largest > 4:
        fail("under an error budget of 3 levels a pixel moved by %d levels" % largest)
    display.ErrorBudget = 0.0


def largest_difference(a, b):
    return max(max(abs(x - y) for x, y in zip(p, q)) for p, q in zip(a, b))


def check_budget_per_vertex(display, view, lights, ranks, out, server):
    """7: under the key light alone and a budget of 32 levels the sphere's light sums go per
    vertex (pvbatch reads the mode; through a pvserver only the pictures are checked), and the
    picture stays within the budget (and 8-bit rounding) of the exact one."""
    for light in lights[1:]:
        light.Enable = 0
    pictures = []
    for levels in (0.0, 32.0):
        display.ErrorBudget = levels
        Render(view)
        Render(view)  # the budget's constants come with the second frame
        path = os.path.join(out, "PhongParaView-%dranks-keylight-budget%g.png" % (ranks, levels))
        SaveScreenshot(path, view, ImageResolution=list(SIZE))
        pictures.append(read_png(path)[3])
    display.UpdatePropertyInformation()
    mode = display.GetPropertyValue("UsedBudgetMode")
    largest = largest_difference(*pictures)
    print("key light alone, error budget 32 levels: mode %s, largest difference %d levels"
          % (mode, largest))
    if not server and mode != 2:
        fail("under the key light and 32 levels the sums stayed %s, not per vertex (2)" % mode)
    if len(pictures[0]) != len(pictures[1]) or largest > 33:
        fail("under an error budget of 32 levels a pixel moved by %d levels" % largest)
    display.ErrorBudget = 0.0
    for light in lights[1:]:
        light.Enable = 1


def check_specular_anti_aliasing(display, view, ranks, out):
    """8: Specular Anti-Aliasing averages a highlight narrower than a pixel (shininess 2e4)
    over its pixel: the picture changes, and only near the highlight (a few levels at most
    elsewhere); off again, the exact picture comes back."""
    display.Shininess = 2.0e4
    pictures = {}
    for name, on in (("exact", 0), ("filtered", 1), ("again", 0)):
        display.SpecularAntiAliasing = on
        Render(view)
        path = os.path.join(out, "PhongParaView-%dranks-specular-aa-%s.png" % (ranks, name))
        SaveScreenshot(path, view, ImageResolution=list(SIZE))
        pictures[name] = read_png(path)[3]
    display.Shininess = 200.0
    changed = sum(1 for a, b in zip(pictures["exact"], pictures["filtered"]) if a != b)
    print("specular anti-aliasing: %d pixels changed" % changed)
    if changed == 0 or changed > len(pictures["exact"]) // 4:
        fail("Specular Anti-Aliasing changed %d pixels of %d" % (changed, len(pictures["exact"])))
    if pictures["again"] != pictures["exact"]:
        fail("Specular Anti-Aliasing off did not give the exact picture back")


def check_depth_pre_pass(view, ranks, out, hide, server):
    """6: nested contours (closed shells of ParaView's Wavelet) drawn with the depth pre-pass
    on: it is used, and the picture is the one drawn without it (from the fourth frame on,
    its depth pass draws only the triangle clusters seen)."""
    hide.Visibility = 0
    shells = Contour(Input=Wavelet(), ContourBy=["POINTS", "RTData"],
                     Isosurfaces=[200.0, 215.0, 230.0, 245.0])
    display = Show(shells, view)
    display.SetRepresentationType("Phong Surface")
    display.ColorArrayName = [None, ""]
    display.Specular = 0.4
    ResetCamera(view)
    pictures = {}
    for mode, frames in (("Off", 1), ("On", 4)):
        display.DepthPrePass = mode
        for _ in range(frames):
            Render(view)
        path = os.path.join(out, "PhongParaView-%dranks-shells-%s.png" % (ranks, mode))
        SaveScreenshot(path, view, ImageResolution=list(SIZE))
        pictures[mode] = read_png(path)[3]
    display.UpdatePropertyInformation()
    used = display.GetPropertyValue("UsedDepthPrePass")
    differing = sum(1 for a, b in zip(pictures["Off"], pictures["On"]) if a != b)
    covered = sum(1 for pixel in pictures["Off"] if not background(pixel))
    print("nested contours: pre-pass used %s, %d pixels differ, %d covered"
          % (used, differing, covered))
    if (used != 1 and not server) or differing > 4 or covered < 1000:
        fail("nested contours with the depth pre-pass: used %s, %d pixels differ, %d covered"
             % (used, differing, covered))
    display.Visibility = 0
    hide.Visibility = 1


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--baseline", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--server", help="HOST:PORT of a pvserver to connect to")
    parser.add_argument("--write-baseline", action="store_true")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)

    ranks = load_plugin(args, globals())
    print("ParaView %s, %d rank(s)" % (GetParaViewVersion(), ranks))

    sphere = Sphere(ThetaResolution=128, PhiResolution=64, Radius=0.5)
    owners = ProcessIds(Input=sphere)
    view = CreateRenderView()
    view.ViewSize = list(SIZE)
    view.OrientationAxesVisibility = 0
    view.Background = [0.0, 0.0, 0.0]
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.CameraPosition = [0.0, -0.6, 2.2]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 30.0
    lights = add_lights(view)

    display = Show(owners, view)
    available = display.Representation.Available
    if "Phong Surface" not in available:
        fail("no Phong Surface representation for polydata: %s" % available)
    grid_display = Show(Tessellate(Input=sphere), view)
    if "Phong Surface" not in grid_display.Representation.Available:
        fail("no Phong Surface representation for unstructured grids")
    grid_display.Visibility = 0
    display.SetRepresentationType("Phong Surface")
    display.Specular = 0.5
    display.Shininess = 200.0
    display.LightingModel = "Blinn-Phong"
    display.Emission = [0.02, 0.02, 0.05]

    # 2: the lit picture, plain colour, against the serial baseline.
    display.ColorArrayName = [None, ""]
    display.DiffuseColor = [0.85, 0.8, 0.7]
    display.AmbientColor = [0.85, 0.8, 0.7]
    Render(view)
    final = os.path.join(args.out, "PhongParaView-%dranks.png" % ranks)
    SaveScreenshot(final, view, ImageResolution=list(SIZE))
    if args.write_baseline:
        SaveScreenshot(args.baseline, view, ImageResolution=list(SIZE))
    width, height, _, picture = read_png(final)
    _, _, _, expected = read_png(args.baseline)
    if len(picture) != len(expected):
        fail("picture %dx%d, baseline of another size" % (width, height))
    else:
        differing = sum(1 for a, b in zip(picture, expected)
                        if max(abs(x - y) for x, y in zip(a, b)) > 12)
        print("against the serial baseline: %d of %d pixels differ by more than 12 levels"
              % (differing, len(picture)))
        if differing > 40:
            fail("%d pixels differ from the serial baseline %s" % (differing, args.baseline))
    check_back_face_culling(display, view, ranks, picture, args.out, args.server)
    check_error_budget(display, view, ranks, picture, args.out)
    check_budget_per_vertex(display, view, lights, ranks, args.out, args.server)
    check_specular_anti_aliasing(display, view, ranks, args.out)

    # 3: each rank's piece in its own colour (red rank 0, blue rank 1, ...).
    # ColorBy makes the lookup table (ParaView 6 no longer does on ColorArrayName alone).
    owners.UpdatePipeline()
    owner_array = "ProcessId" if "ProcessId" in owners.PointData.keys() else "PointProcessIds"
    ColorBy(display, ("POINTS", owner_array))
    table = display.LookupTable or GetColorTransferFunction(owner_array)
    table.InterpretValuesAsCategories = 1
    table.Annotations = sum(([str(r), str(r)] for r in range(ranks)), [])
    palette = [(1.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, 0.8, 0.0), (1.0, 0.8, 0.0)]
    table.IndexedColors = [c for r in range(ranks) for c in palette[r % len(palette)]]
    Render(view)
    colours = os.path.join(args.out, "PhongParaView-%dranks-owners.png" % ranks)
    SaveScreenshot(colours, view, ImageResolution=list(SIZE))
    _, _, _, owners_picture = read_png(colours)
    owner_of = []
    for index, pixel in enumerate(owners_picture):
        x, y = index % width, index // width
        # Silhouette pixels blend with the background: only pixels whose four neighbours
        # are on the surface too are attributed.
        inside = 0 < x < width - 1 and 0 < y < height - 1 and not any(
            background(owners_picture[index + step]) for step in (-1, 1, -width, width))
        if background(pixel) or not inside:
            owner_of.append(None)
            continue
        red, green, blue = pixel
        owner_of.append(0 if red > blue + 20 else 1 if blue > red + 20 else None)
    counts = [owner_of.count(r) for r in range(min(ranks, 2))]
    print("visible pixels per rank colour: %s" % counts)
    if any(count < 500 for count in counts):
        fail("a rank's piece is missing from the composited picture: %s" % counts)

    # 4: the shading normal view over the same pixels.
    display.PhongDebugView = "Shading normal"
    Render(view)
    normals = os.path.join(args.out, "PhongParaView-%dranks-normals.png" % ranks)
    SaveScreenshot(normals, view, ImageResolution=list(SIZE))
    _, _, _, normal_picture = read_png(normals)
    checked = [0] * max(ranks, 1)
    bad = [0] * max(ranks, 1)
    for owner, pixel in zip(owner_of, normal_picture):
        if owner is None:
            continue
        length = math.sqrt(sum((2.0 * c / 255.0 - 1.0) ** 2 for c in pixel))
        checked[owner] += 1
        if abs(length - 1.0) > 0.06:
            bad[owner] += 1
    print("shading-normal view: pixels checked per rank %s, not a unit normal %s"
          % (checked[:2], bad[:2]))
    for rank in range(min(ranks, 2)):
        if checked[rank] == 0 or bad[rank] > 0.01 * checked[rank]:
            fail("rank %d's piece is not drawn by vtkPhong's shader (%d of %d pixels)"
                 % (rank, bad[rank], checked[rank]))
    display.PhongDebugView = "Final"
    check_depth_pre_pass(view, ranks, args.out, display, args.server)

    report()


main()
