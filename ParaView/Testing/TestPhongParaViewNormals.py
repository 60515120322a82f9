"""The normals "Phong Surface" computes, on data that carries none, in pvbatch serially and
under MPI.

    pvbatch --disable-xdisplay-test TestPhongParaViewNormals.py --plugin PhongLighting.so \\
        --baseline B.png --out DIR [--no-ghosts] [--write-baseline] [--server HOST:PORT]
    mpiexec -np 4 pvbatch --disable-xdisplay-test TestPhongParaViewNormals.py ...

(--server: run as pvpython connected to a pvserver, as RunWithPvserver.py does.)

The verdict is the output: "ERROR:" lines on failure, "all checks passed" otherwise.

The data: a 24 x 24 sphere (VTK's vtkSphereSource) with its Normals array removed, written
to a .vtp file and read back, so that it starts whole on rank 0. Then RedistributeDataSet
spreads its cells over the ranks (with one rank it only turns the polydata into an
unstructured grid).

--from-source: the sphere comes from ParaView's Sphere source itself, its normals stripped by
PassArrays, then RedistributeDataSet, as users build it. Under MPI the source makes one piece
per rank, each with its own copies of the points on its cuts (and of the poles), some of them
a float step apart (the source sums the angles differently for each piece): after the
redistribution a rank holds copies from several source pieces. Checks 1, 2 and 4 only (the
volume of check 3 would be each rank's own hull), 5 and 6.
Checks, each failing with "ERROR:":

1. smooth: drawn diffusely by "Phong Surface", it is close to the same sphere drawn with
   its exact normals (the source's own, ComputeNormals off): the mean difference and the
   share of pixels more than 8 levels off stay under thresholds. Faceted shading (the
   normals lost on the way to the mapper) is 5.4 levels and 22 % off;
2. not faceted: it differs from ParaView's own "Surface" on the same data (which has no
   normals to draw and is faceted);
3. the same for a volume without normals (Delaunay3D of the sphere's points: a tetrahedral
   unstructured grid whose surface ParaView's geometry filter extracts);
4. no seam: the lit, composited picture of the surface equals the serial baseline pixel for
   pixel (within a tight threshold) whatever the number of ranks; so does the volume's
   diffuse picture, against the exact normals' one (which serially it equals within a
   level). Where the pieces meet, each rank's
   normals must see the faces of its neighbours (ghost cells); --no-ghosts turns the
   representation's NormalsAcrossPieces off, to show that this check sees the seam that
   follows.
5. no seam on the polydata drawn without the redistribution (the source's own pieces, or
   the file's one piece on the first rank and nothing on the others): the same lit picture
   as the serial baseline, no pixel more than 4 levels off. Polydata pieces take their cut
   points' normals from the seam mesh (vtkPhongSeamFacesExchange, the other ranks' faces
   there) rather than from vtkGhostCellsGenerator's ghost cells.
6. the same for that polydata made into triangle strips (TriangleStrips).
7. bad input: the same polydata with one point of each piece made NaN (a ProgrammableFilter)
   draws, under MPI too, over the same pixels as ParaView's own "Surface" (within 1 %): the
   faces at the NaN point are left out, nothing hangs or crashes.
8. data that carries point normals (a Calculator's constant +z, which no computation gives)
   is drawn with its own by default (ComputeNormals "Where Missing"): the same picture as
   ComputeNormals "Never", within a level, on the polydata as it comes (under MPI the file's
   ranks without points count as carrying them) and redistributed; "Always" replaces them
   (the picture differs as the faceted one does).
9. files nobody here wrote (assimp's test models, --models DIR; skipped without): Wuson as
   PLY, which carries point normals, is drawn with them by default (the same picture as
   "Never", no pixel more than 8 levels off), and as STL, which carries none, with computed
   ones (the same picture as "Always", and not the faceted one of "Never"). ParaView's
   readers load them on the first rank, the others empty. --files-only runs this check
   alone (under a memory limit, in vtkPhongParaView-Normals-Files-Limited).
"""

import argparse
import os

from phong_paraview_testing import fail, load_plugin, prefer_pythonpath, report

prefer_pythonpath()

from paraview.simple import (  # noqa: E402 (after the path fix)
    AddLight, Calculator, CreateRenderView, Delaunay3D, OpenDataFile, PassArrays, GetParaViewVersion, Hide,
    RedistributeDataSet, Render, ProgrammableFilter, ResetCamera, SaveScreenshot, Show, Sphere, TriangleStrips)
from paraview.simple import XMLPolyDataReader  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkSphereSource  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter  # noqa: E402

SIZE = (400, 400)
# Thresholds: (mean levels over the sphere's pixels, share of them more than 8 levels off).
SMOOTH_LIMITS = (2.0, 0.05)     # computed normals against the exact ones
FACETED_LEAST = (3.0, 0.10)     # "Surface" (faceted) against "Phong Surface"
SEAM_LIMITS = (8, 20)           # a pixel differs by more than 8 levels; at most 20 such
# Checks 5 and 6 (polydata pieces): the largest difference, in levels. The seam mesh gives
# 0-1; with the points between two other ranks not merged, 4 ranks' poles were 11 off (18
# pixels, under SEAM_LIMITS).
PIECES_LARGEST = 4


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels[:, :3].astype(int)


def shot(view, out, name):
    Render(view)
    path = os.path.join(out, name + ".png")
    SaveScreenshot(path, view, ImageResolution=list(SIZE))
    return read_png(path)


def compare(a, b):
    """Mean difference (levels, largest channel) and share of pixels more than 8 levels off,
    over the pixels where either picture shows the sphere (the background is black)."""
    on_sphere = (a.max(axis=1) > 8) | (b.max(axis=1) > 8)
    difference = abs(a - b).max(axis=1)[on_sphere]
    if difference.size == 0:
        return 0.0, 0.0, 0
    return float(difference.mean()), float((difference > 8).mean()), int(difference.size)


def write_bare_sphere(out):
    """The sphere without normals, in one piece, as a file every rank can read."""
    source = vtkSphereSource()
    source.SetThetaResolution(24)
    source.SetPhiResolution(24)
    source.SetRadius(0.5)
    source.Update()
    sphere = source.GetOutput()
    sphere.GetPointData().RemoveArray("Normals")
    path = os.path.join(out, "sphere-without-normals.vtp")
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(sphere)
    writer.Write()
    return path


def make_view():
    view = CreateRenderView()
    view.ViewSize = list(SIZE)
    view.OrientationAxesVisibility = 0
    view.Background = [0.0, 0.0, 0.0]
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.CameraPosition = [0.6, 0.8, 2.2]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 30.0
    # One directional light from the upper left, the light kit off: a light at a slant
    # shows facets and seams more than the kit's soft fill does.
    view.UseLight = 0
    key = AddLight(view=view)
    key.Coords = "Scene"
    key.Type = "Directional"
    key.Position = [-1.0, 1.0, 1.2]
    key.Intensity = 1.0
    return view


def show(source, view, representation, specular=0.0, compute_normals=True, across=True):
    display = Show(source, view)
    display.SetRepresentationType(representation)
    display.ColorArrayName = [None, ""]
    display.DiffuseColor = [0.85, 0.8, 0.7]
    display.Specular = specular
    if representation == "Phong Surface":
        display.ComputeNormals = 1 if compute_normals else 0
        display.Shininess = 40.0
        display.NormalsAcrossPieces = 1 if across else 0
    return display


def check_smooth(label, smooth, exact, faceted):
    mean, share, count = compare(smooth, exact)
    print("%s, Phong Surface against the exact normals: %.2f levels mean, %.1f %% of %d "
          "pixels more than 8 levels off" % (label, mean, 100.0 * share, count))
    if mean > SMOOTH_LIMITS[0] or share > SMOOTH_LIMITS[1]:
        fail("%s: Phong Surface is not smooth (%.2f levels, %.1f %% off the exact normals)"
             % (label, mean, 100.0 * share))
    mean, share, _ = compare(faceted, exact)
    print("%s, Surface (faceted) against the exact normals: %.2f levels mean, %.1f %%"
          % (label, mean, 100.0 * share))
    mean, share, _ = compare(smooth, faceted)
    print("%s, Phong Surface against Surface: %.2f levels mean, %.1f %%"
          % (label, mean, 100.0 * share))
    if mean < FACETED_LEAST[0] or share < FACETED_LEAST[1]:
        fail("%s: Phong Surface looks like the faceted Surface (%.2f levels, %.1f %%)"
             % (label, mean, 100.0 * share))


def check_seam(label, picture, expected, ranks, largest=None):
    if expected.shape != picture.shape:
        fail("%s: picture and reference differ in size" % label)
        return
    difference = abs(picture - expected).max(axis=1)
    differing = int((difference > SEAM_LIMITS[0]).sum())
    print("%s, %d rank(s) against the serial picture: %d pixels differ by more than %d levels "
          "(largest %d, mean over the sphere %.3f)" % (
              label, ranks, differing, SEAM_LIMITS[0], int(difference.max()),
              float(difference[expected.max(axis=1) > 8].mean())))
    if differing > SEAM_LIMITS[1]:
        fail("%s: %d pixels differ from the serial picture: a seam between the pieces"
             % (label, differing))
    elif largest is not None and difference.max() > largest:
        fail("%s: a pixel differs from the serial picture by %d levels (at most %d): a seam "
             "where pieces meet" % (label, int(difference.max()), largest))


def check_polydata_seam(label, polydata, view, args, ranks, across):
    """Checks 5 and 6: the polydata drawn lit, against the serial baseline."""
    display = show(polydata, view, "Phong Surface", specular=0.6, across=across)
    check_seam(label, shot(view, args.out, "%s-%dranks" % (label, ranks)),
               read_png(args.baseline), ranks, PIECES_LARGEST)
    Hide(polydata, view)
    del display


NAN_SCRIPT = """
from vtkmodules.vtkCommonCore import vtkPoints
output = self.GetOutput()
output.ShallowCopy(self.GetInput())
points = vtkPoints()
points.DeepCopy(output.GetPoints())
if points.GetNumberOfPoints() > 5:
    points.SetPoint(5, float("nan"), float("nan"), float("nan"))
output.SetPoints(points)
"""


def check_nan_point(polydata, view, args, ranks):
    """Check 7: a NaN point in every piece; the pixels covered, Phong Surface against
    Surface, on a background no shading gives (unlit faces are black)."""
    bad = ProgrammableFilter(Input=polydata)
    bad.Script = NAN_SCRIPT
    view.Background = [0.2, 0.3, 0.4]
    covered = []
    for representation in ("Surface", "Phong Surface"):
        display = show(bad, view, representation)
        picture = shot(view, args.out, "nan-%s-%dranks" % (representation.replace(" ", ""), ranks))
        covered.append(int((abs(picture - [51, 76, 102]).max(axis=1) > 2).sum()))
        Hide(bad, view)
        del display
    view.Background = [0.0, 0.0, 0.0]
    print("NaN point in each piece, %d rank(s): pixels covered by Surface %d, by Phong Surface %d"
          % (ranks, covered[0], covered[1]))
    if covered[0] < 1000 or abs(covered[1] - covered[0]) > 0.01 * covered[0]:
        fail("a NaN point: Phong Surface covers %d pixels, Surface %d" % (covered[1], covered[0]))


def shots_by_mode(data, view, args, name, frame=False):
    """The data drawn by "Phong Surface" with ComputeNormals Never, Where Missing and Always
    (0, 1, 2), in that order; `frame`: the camera reset to the data first."""
    pictures = []
    for mode in (0, 1, 2):
        display = show(data, view, "Phong Surface")
        display.ComputeNormals = mode
        if frame and mode == 0:
            ResetCamera(view)
        pictures.append(shot(view, args.out, "%s-mode%d" % (name, mode)))
        Hide(data, view)
        del display
    return pictures


def check_data_normals(label, data, view, args, ranks):
    """Check 8: the data's own point normals (a constant +z) drawn by default, replaced with
    ComputeNormals "Always"."""
    carried = Calculator(Input=data, ResultArrayName="Normals", Function="kHat")
    carried.ResultNormals = 1
    pictures = shots_by_mode(carried, view, args, "%s-normals-%dranks" % (label, ranks))
    kept = compare(pictures[1], pictures[0])
    replaced = compare(pictures[2], pictures[0])
    print("%s with its own normals, %d rank(s): Where Missing against Never %.2f levels mean, "
          "%.1f %% off; Always against Never %.2f levels mean, %.1f %% off" % (
              label, ranks, kept[0], 100.0 * kept[1], replaced[0], 100.0 * replaced[1]))
    if kept[2] < 1000 or kept[0] > 1.0 or kept[1] > 0.0:
        fail("%s: the data's own normals are not the ones drawn by default" % label)
    if replaced[0] < FACETED_LEAST[0] or replaced[1] < FACETED_LEAST[1]:
        fail("%s: ComputeNormals Always did not replace the data's normals" % label)


def check_model_files(models, view, args, ranks):
    """Check 9: assimp's Wuson with its own normals (PLY) and without (STL), drawn with
    ComputeNormals "Where Missing" against "Never" and "Always"."""
    for name, carries in (("PLY/Wuson.ply", True), ("OBJ/WusonOBJ.obj", True), ("STL/Wuson.stl", False)):
        data = OpenDataFile(os.path.join(models, name))
        label = os.path.basename(name)
        pictures = shots_by_mode(data, view, args, "%s-%dranks" % (label, ranks), frame=True)
        never = compare(pictures[1], pictures[0])
        always = compare(pictures[1], pictures[2])
        print("%s, %d rank(s): Where Missing against Never %.2f levels mean, %.2f %% off; "
              "against Always %.2f levels mean, %.2f %% off (%d pixels)" % (
                  label, ranks, never[0], 100.0 * never[1], always[0], 100.0 * always[1],
                  never[2]))
        same, other = (never, always) if carries else (always, never)
        if same[2] < 1000 or same[0] > 1.0 or same[1] > 0.0:
            fail("%s: drawn by default as ComputeNormals %s does not draw it" % (
                label, "Never" if carries else "Always"))
        if not carries and (other[0] < FACETED_LEAST[0] or other[1] < FACETED_LEAST[1]):
            fail("%s: without normals in the file, the default drew no computed ones" % label)


def check_against_surface(label, display, view, out, exact, ranks):
    """Checks 1 and 2 (3 for the volume): the display drawn as "Phong Surface", then as
    ParaView's "Surface", against the exact normals' picture. Returns the smooth picture."""
    prefix = "" if label == "surface" else label + "-"
    smooth = shot(view, out, "%ssmooth-%dranks" % (prefix, ranks))
    display.SetRepresentationType("Surface")
    faceted = shot(view, out, "%sfaceted-%dranks" % (prefix, ranks))
    check_smooth(label, smooth, exact, faceted)
    return smooth


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--baseline", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--no-ghosts", action="store_true")
    parser.add_argument("--write-baseline", action="store_true")
    parser.add_argument("--server", help="HOST:PORT of a pvserver to connect to")
    parser.add_argument("--from-source", action="store_true",
                        help="the sphere from ParaView's Sphere source, one piece per rank")
    parser.add_argument("--models", help="assimp's test models (check 9)")
    parser.add_argument("--files-only", action="store_true", help="check 9 alone")
    args = parser.parse_args()
    args.out = os.path.abspath(args.out)  # the server reads the sphere's file from there
    os.makedirs(args.out, exist_ok=True)
    ranks = load_plugin(args, globals())
    print("ParaView %s, %d rank(s)%s%s" % (
        GetParaViewVersion(), ranks, ", no ghost cells" if args.no_ghosts else "",
        ", pieces from the Sphere source" if args.from_source else ""))

    if args.files_only:
        check_model_files(args.models, make_view(), args, ranks)
        report()
        return
    sphere = Sphere(ThetaResolution=24, PhiResolution=24, Radius=0.5)
    if args.from_source:
        bare = PassArrays(Input=sphere, PointDataArrays=[], CellDataArrays=[])
    else:
        bare = XMLPolyDataReader(FileName=[write_bare_sphere(args.out)])
    pieces = RedistributeDataSet(Input=bare)
    volume = RedistributeDataSet(Input=Delaunay3D(Input=bare))
    across = not args.no_ghosts
    view = make_view()

    # 1, 2: the redistributed surface without normals, diffuse light only.
    exact = show(sphere, view, "Phong Surface", compute_normals=False)
    exact_picture = shot(view, args.out, "exact-%dranks" % ranks)
    Hide(sphere, view)
    display = show(pieces, view, "Phong Surface", across=across)
    check_against_surface("surface", display, view, args.out, exact_picture, ranks)

    # 4: the same with a highlight, against the serial picture.
    display.SetRepresentationType("Phong Surface")
    display.Specular = 0.6
    lit = shot(view, args.out, "lit-%dranks" % ranks)
    if args.write_baseline:
        SaveScreenshot(args.baseline, view, ImageResolution=list(SIZE))
    else:
        check_seam("surface", lit, read_png(args.baseline), ranks)
    Hide(pieces, view)
    # 5: the polydata as it comes, not redistributed (no unstructured grid): its cut points'
    # normals come from the seam mesh, not from the ghost-cell generator. The file's one
    # piece leaves every rank but the first empty. 6: the same as triangle strips (the
    # exchange sends strip triangles).
    if not args.write_baseline:
        for label, polydata in (("pieces", bare), ("strips", TriangleStrips(Input=bare))):
            check_polydata_seam(label, polydata, view, args, ranks, across)
        check_nan_point(bare, view, args, ranks)
        check_data_normals("polydata", bare, view, args, ranks)
        check_data_normals("redistributed", pieces, view, args, ranks)
    if args.from_source:
        # Delaunay3D of a source's pieces is each rank's own hull: not the sphere's volume.
        report()
        return

    # 3: a tetrahedral volume without normals.
    grid = show(volume, view, "Phong Surface", across=across)
    smooth_picture = check_against_surface("volume", grid, view, args.out, exact_picture, ranks)
    # Serially the volume's computed normals draw the exact normals' picture within a level
    # (Max's weights are exact for points on a sphere): the exact picture is the serial one.
    check_seam("volume", smooth_picture, exact_picture, ranks)
    del exact
    Hide(volume, view)
    if args.models and not args.write_baseline:
        check_model_files(args.models, view, args, ranks)  # last: it moves the camera

    report()


main()
