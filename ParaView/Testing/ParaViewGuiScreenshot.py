"""Screenshot of the ParaView GUI with the PhongLighting plugin loaded from the command line,
"Phong Surface" chosen and its properties in the Properties panel (docs/paraview.md).

    /usr/bin/python3 ParaView/Testing/ParaViewGuiScreenshot.py \\
        --plugin-dir build-paraview/lib/paraview-5.11/plugins/PhongLighting \\
        --output docs/paraview-properties.png

Not a ctest test: a check done by looking at the picture. Everything it needs is made in a
temporary directory, nothing is installed: an Xvfb server whose screen is a file (-fbdir, XWD
format, converted here with numpy and VTK's PNG writer); a HOME with ParaView settings that
turn the welcome dialog off, apply automatically and put the view's properties in their own
panel (so that the display's properties end the Properties panel); a sphere without normals;
and a QtTesting event file (--test-script) that picks "Phong Surface" in the representation
toolbar, shows the advanced properties too and scrolls the Properties panel to its end. ParaView 5.11's --plugins takes plugin
names, looked up in --plugin-search-paths.
"""

import argparse
import os
import shutil
import struct
import subprocess
import tempfile
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

SETTINGS = """{ "settings" : { "GeneralSettings" : { "AutoApply" : 1, "PropertiesPanelMode" : 2 } } }
"""
# pqSettings (QSettings) keys with a dot live in [General]; the window fills the screen.
QT_SETTINGS = ("[General]\nGeneralSettings.ShowWelcomeDialog=0\n\n"
               "[MainWindow]\nSize=@Size(1280 1024)\nPosition=@Point(0 0)\n")
EVENTS = """<?xml version="1.0" ?>
<pqevents>
  <pqevent object="pqClientMainWindow/representationToolbar/displayRepresentation/comboBox"
    command="set_string" arguments="Phong Surface" />
  <pqevent object="pqClientMainWindow/propertiesDock/propertiesPanel/SearchBox/AdvancedButton"
    command="set_boolean" arguments="true" />
  <pqevent object="pqClientMainWindow/propertiesDock/propertiesPanel/scrollArea/qt_scrollarea_vcontainer/1QScrollBar0"
    command="set_int" arguments="100000" />
</pqevents>
"""
SCREEN = (1280, 1024)


def write_sphere(path):
    source = vtkSphereSource()
    source.SetThetaResolution(24)
    source.SetPhiResolution(24)
    source.Update()
    sphere = source.GetOutput()
    sphere.GetPointData().RemoveArray("Normals")
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(sphere)
    writer.Write()


def make_home(home, version):
    config = os.path.join(home, ".config", "ParaView")
    os.makedirs(config)
    with open(os.path.join(config, "ParaView-UserSettings.json"), "w") as out:
        out.write(SETTINGS)
    with open(os.path.join(config, "ParaView%s.ini" % version), "w") as out:
        out.write(QT_SETTINGS)


def xwd_to_png(xwd, png):
    """An Xvfb screen file (XWD, 32 bits per pixel TrueColor) to PNG."""
    with open(xwd, "rb") as screen:
        data = screen.read()
    fields = struct.unpack(">25I", data[:100])
    header, width, height, byte_order, line, colours = (
        fields[0], fields[4], fields[5], fields[7], fields[12], fields[19])
    start = header + 12 * colours
    pixels = np.frombuffer(data[start:start + line * height], dtype=np.uint8)
    pixels = pixels.reshape(height, line)[:, :width * 4].reshape(height, width, 4)
    rgb = pixels[:, :, [2, 1, 0]] if byte_order == 0 else pixels[:, :, [1, 2, 3]]
    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    rows = np.ascontiguousarray(rgb[::-1]).reshape(-1, 3)  # VTK's rows start at the bottom
    image.GetPointData().SetScalars(numpy_to_vtk(rows, deep=True))
    writer = vtkPNGWriter()
    writer.SetFileName(png)
    writer.SetInputData(image)
    writer.Write()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin-dir", required=True, help="the directory of PhongLighting.so")
    parser.add_argument("--output", required=True)
    parser.add_argument("--paraview", default="paraview")
    parser.add_argument("--version", default="5.11.0", help="names ParaView's Qt settings file")
    parser.add_argument("--display", default=":77")
    parser.add_argument("--wait", type=float, default=30.0)
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="vtkphong-gui-")
    home = os.path.join(work, "home")
    make_home(home, args.version)
    sphere = os.path.join(work, "sphere-without-normals.vtp")
    write_sphere(sphere)
    events = os.path.join(work, "events.xml")
    with open(events, "w") as out:
        out.write(EVENTS)
    xvfb = subprocess.Popen(["Xvfb", args.display, "-screen", "0", "%dx%dx24" % SCREEN,
                             "-fbdir", work], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    time.sleep(2.0)
    environment = dict(os.environ, HOME=home, XDG_CONFIG_HOME=os.path.join(home, ".config"),
                       DISPLAY=args.display)
    paraview = subprocess.Popen(
        [args.paraview, "--plugin-search-paths=" + os.path.abspath(args.plugin_dir),
         "--plugins=PhongLighting", "--data=" + sphere, "--test-script=" + events],
        env=environment, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        time.sleep(args.wait)
        xwd_to_png(os.path.join(work, "Xvfb_screen0"), args.output)
        print("wrote %s" % args.output)
    finally:
        paraview.terminate()
        log, _ = paraview.communicate(timeout=30)
        xvfb.terminate()
        xvfb.wait(timeout=30)
        shutil.rmtree(work, ignore_errors=True)
    for line in log.splitlines():
        if "ERR" in line or "critical" in line or "Success" in line:
            print(line)


if __name__ == "__main__":
    main()
