"""Shared pieces of the ParaView test and benchmark scripts, which pvbatch and pvpython run
(pvbatch puts the script's folder first on sys.path, as python3 does).

    from phong_paraview_testing import fail, prefer_pythonpath, report
    prefer_pythonpath()  # before any paraview import
"""

import os
import sys

failures = []


def prefer_pythonpath():
    """pvpython puts the prefix it guesses from its libraries (/lib/python3/dist-packages,
    the system VTK 9.1's vtkmodules on this platform) before PYTHONPATH; ParaView's own
    Python package, unpacked from python3-paraview, must come first (docs/paraview.md)."""
    for entry in reversed(os.environ.get("PYTHONPATH", "").split(os.pathsep)):
        if entry:
            sys.path.insert(0, entry)


def load_plugin(args, ns):
    """Connect to the pvserver at args.server (HOST:PORT) when given, and load args.plugin on
    the server and the client, into the namespace `ns` (the script's globals()). Returns
    the number of ranks that hold the data."""
    from paraview import servermanager
    from paraview.simple import Connect, GetSettingsProxy, LoadPlugin

    if args.server:
        host, port = args.server.split(":")
        Connect(host, int(port))
        LoadPlugin(args.plugin, remote=True, ns=ns)
        # Render on the server's ranks (and composite there), whatever the data size.
        GetSettingsProxy("RenderViewSettings").RemoteRenderThreshold = 0.0
    LoadPlugin(args.plugin, remote=False, ns=ns)
    return servermanager.ActiveConnection.GetNumberOfDataPartitions()


def still_view(size=None):
    """A render view that draws still frames only (no level of detail, which would time
    another mesh), without the orientation axes; `size`: [width, height]."""
    from paraview.simple import CreateRenderView
    view = CreateRenderView()
    if size:
        view.ViewSize = list(size)
    view.OrientationAxesVisibility = 0
    view.LODThreshold = 1e9
    return view


def bare_sphere(resolution):
    """(source, output): ParaView's Sphere at `resolution` (theta and phi) and the same
    without its normals (PassArrays): data without normals, one piece per rank."""
    from paraview.simple import PassArrays, Sphere
    sphere = Sphere(ThetaResolution=resolution, PhiResolution=resolution)
    return sphere, PassArrays(Input=sphere, PointDataArrays=[], CellDataArrays=[])


def fail(message):
    """A failed check: an "ERROR:" line, which ctest's FAIL_REGULAR_EXPRESSION catches."""
    failures.append(message)
    print("ERROR: " + message)


def report():
    """The verdict as ctest reads it. No sys.exit: pvbatch turns SystemExit into a GLX error
    at teardown (GLXBadContext) and exit status 1."""
    if failures:
        print("ERROR: %d check(s) failed" % len(failures))
    else:
        print("all checks passed")
