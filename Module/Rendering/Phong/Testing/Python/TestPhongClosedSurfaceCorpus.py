"""Closed-surface culling on meshes nobody here wrote: every OFF mesh of CGAL's data (about
140, extracted at test time; valid, open, non-manifold, with holes, concave polygons,
self-intersecting), read without normals, drawn from 4 views with the mapper's
ClosedSurfaceCulling off and on.

- Where culling is not used, the pictures are identical.
- Where it is used, no pixel that differs is one where the geometry shows a back face clearly
  nearer than every front face (by more than 1e-4 of the depth range, in the depth pictures
  of the front faces alone and the back faces alone that stock VTK's mapper draws of the same
  mesh from the same view), inside the front faces' outline, but for at most 2 pixels per
  view (rounding along interior silhouettes): culling hides no back face that can be seen.
  The other pixels that differ are ties by rounding (on the outline, which of a silhouette
  edge's two faces covers a pixel; coincident faces); the table lists them.
- Most closed meshes are culled (at least 60).
- The composite mapper, drawing each mesh as ParaView's Phong Surface does (normals from
  vtkOpenMeshNormals upstream, which orients the faces as the polydata mapper's own normals
  do) in two blocks (the first and the second half of the cells, sharing the points), culls
  in exactly the views where the polydata mapper culls (the analysis welds across blocks),
  under the same rules for the pixels that differ.

    PYTHONPATH=<build>/lib/python3/dist-packages:Testing/Core xvfb-run -a /usr/bin/python3 \\
        TestPhongClosedSurfaceCorpus.py --meshes <build>/data/corpus
"""

import argparse
import glob
import os

import numpy
import vtkphong
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkMultiBlockDataSet, vtkPolyData
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow
from vtkphong_testing import Checks, snapshot

SIZE = 200
VIEWS = 4
TIE = 1e-4  # window depth: front and back faces this close are a tie by rounding
LARGEST = 400000  # triangles: larger meshes are left out (time)
# Along an interior silhouette the two faces meet at a grazing angle, where their depths move
# faster than TIE within a pixel: a pixel or two per view is rounding there, a hidden back
# face is a patch.
ROUNDING_PIXELS = 2
checks = Checks()


def options():
    parser = argparse.ArgumentParser()
    parser.add_argument("--meshes", required=True)
    parser.add_argument("-B", dest="baselines")
    parser.add_argument("-T", dest="temporary")
    return parser.parse_args()


def halves(mesh):
    """The mesh as two blocks, the first and the second half of its polygons, sharing its
    points: closed (where the mesh is) only together."""
    polys = mesh.GetPolys()
    offsets = vtk_to_numpy(polys.GetOffsetsArray()).astype(numpy.int64)
    connectivity = vtk_to_numpy(polys.GetConnectivityArray()).astype(numpy.int64)
    half = len(offsets) // 2
    blocks = vtkMultiBlockDataSet()
    for index, (first, last) in enumerate(((0, half), (half, len(offsets) - 1))):
        cells = vtkCellArray()
        cells.SetData(numpy_to_vtk(offsets[first:last + 1] - offsets[first], deep=1),
                      numpy_to_vtk(connectivity[offsets[first]:offsets[last]], deep=1))
        block = vtkPolyData()
        block.SetPoints(mesh.GetPoints())
        block.GetPointData().ShallowCopy(mesh.GetPointData())
        block.SetPolys(cells)
        blocks.SetBlock(index, block)
    return blocks


class View:
    def __init__(self, window, mesh):
        self.window = window
        self.renderer = vtkRenderer()
        window.GetRenderers().RemoveAllItems()
        window.AddRenderer(self.renderer)
        self.mapper = vtkphong.vtkPhongPolyDataMapper()
        self.mapper.SetInputData(mesh)
        self.stock = vtkPolyDataMapper()
        self.stock.SetInputData(mesh)
        normals = vtkphong.vtkOpenMeshNormals()
        normals.SetInputData(mesh)
        normals.Update()
        self.composite = vtkphong.vtkPhongCompositePolyDataMapper()
        self.composite.SetInputDataObject(halves(normals.GetOutput()))
        self.actor = vtkActor()
        self.actor.SetMapper(self.mapper)
        self.actor.GetProperty().SetSpecular(0.4)
        self.renderer.AddActor(self.actor)
        self.renderer.ResetCamera()

    def pictures(self, mapper):
        """The pictures with culling off and on, and whether the second culled."""
        self.actor.SetMapper(mapper)
        result = []
        for culling in (False, True):
            mapper.SetClosedSurfaceCulling(culling)
            self.window.Render()
            pixels, _ = snapshot(self.window)
            result.append(pixels.reshape(-1, pixels.shape[-1]).astype(int))
        self.actor.SetMapper(self.mapper)
        return result[0], result[1], mapper.GetUsedClosedSurfaceCulling()

    def depth(self, faces):
        """The depth picture of the front or the back faces alone, as stock VTK's mapper draws
        the mesh (VTK's property culling)."""
        self.actor.SetMapper(self.stock)
        prop = self.actor.GetProperty()
        prop.SetBackfaceCulling(faces == "front")
        prop.SetFrontfaceCulling(faces == "back")
        self.window.Render()
        prop.SetBackfaceCulling(False)
        prop.SetFrontfaceCulling(False)
        self.actor.SetMapper(self.mapper)
        values = vtkFloatArray()
        self.window.GetZbufferData(0, 0, SIZE - 1, SIZE - 1, values)
        return vtk_to_numpy(values).copy()

    def turn(self):
        camera = self.renderer.GetActiveCamera()
        camera.Azimuth(97.0)
        camera.Elevation(31.0)
        camera.OrthogonalizeViewUp()
        self.renderer.ResetCameraClippingRange()


def inside(front):
    """The pixels the front faces cover with their 8 neighbours: off the outline, where which
    of a silhouette edge's two faces covers a pixel is rounding."""
    covered = (front < 1.0).reshape(SIZE, SIZE)
    padded = numpy.pad(covered, 1, constant_values=False)
    result = numpy.ones_like(covered)
    for dy in (0, 1, 2):
        for dx in (0, 1, 2):
            result &= padded[dy:dy + SIZE, dx:dx + SIZE]
    return result.reshape(-1)


def check_mesh(window, path):
    """(culled views, differing pixels, pixels a clearly nearer back face lost)"""
    reader = vtkphong.vtkPhongOFFReader()
    reader.SetFileName(path)
    reader.Update()
    mesh = reader.GetOutput()
    if not 0 < mesh.GetNumberOfPolys() <= LARGEST:
        return None
    name = os.path.basename(path)
    view = View(window, mesh)
    culled = differing = lost = worst = 0
    for _ in range(VIEWS):
        depths = {}
        used = None
        for mapper, what in ((view.mapper, name), (view.composite, name + " in two blocks")):
            off, on, used_here = view.pictures(mapper)
            changed = numpy.abs(off - on).max(axis=1) > 0
            if used is None:
                used = used_here
                culled += 1 if used else 0
                differing += int(changed.sum())
            checks.expect(used_here == used, "%s: culled by one mapper only" % what)
            if used_here and changed.any():
                if not depths:
                    depths = {"front": view.depth("front"), "back": view.depth("back")}
                front, back = depths["front"], depths["back"]
                lost_here = int((changed & inside(front) & (back < front - TIE)).sum())
                lost += lost_here
                worst = max(worst, lost_here)
            elif not used_here:
                checks.expect(not changed.any(), "%s: not culled, yet %d pixels differ"
                              % (what, int(changed.sum())))
        view.turn()
    return culled, differing, lost, worst


def main():
    args = options()
    window = vtkRenderWindow()
    window.SetSize(SIZE, SIZE)
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    paths = sorted(glob.glob(os.path.join(args.meshes, "*.off")))
    checks.expect(len(paths) > 100, "CGAL's meshes found (%d)" % len(paths))
    culled_meshes = 0
    print("| mesh | views culled | pixels differing | of them, a visible back face hidden |")
    print("|---|---|---|---|")
    for path in paths:
        result = check_mesh(window, path)
        if result is None:
            continue
        culled, differing, lost, worst = result
        culled_meshes += 1 if culled else 0
        if differing:
            print("| %s | %d of %d | %d | %d |" % (os.path.basename(path), culled, VIEWS,
                                                  differing, lost))
        checks.expect(worst <= ROUNDING_PIXELS, "%s: culling hid %d pixels of a back face "
                      "nearer than every front face in one view" % (os.path.basename(path), worst))
    print("%d of %d meshes culled" % (culled_meshes, len(paths)))
    checks.expect(culled_meshes >= 60, "closed meshes culled: %d" % culled_meshes)
    checks.exit()


main()
