"""Shared pieces of the vtkphong Python tests: arguments, scene lights, image comparison.

A picture is compared with Testing/Data/Baseline/<name>.png twice: by VTK's
own regression test, and pixel by pixel (at most 24 pixels may differ by
more than 6 levels), as the C++ tests do. On a mismatch the rendered image
and the difference are written to the -T folder.
"""

import argparse
import os
import sys

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkLight, vtkWindowToImageFilter
from vtkmodules.vtkTestingRendering import vtkTesting

STRICT_LEVELS = 6
STRICT_PIXEL_BUDGET = 24


def vtk_changed(change):
    """Whether the VTK under test has `change`, one of the per-version facts that
    cmake/vtkPhongVersions.cmake names (VTKPHONG_VTK_CHANGES)."""
    return change in os.environ.get("VTKPHONG_VTK_CHANGES", "").split(",")


def arguments():
    parser = argparse.ArgumentParser()
    parser.add_argument("-B", dest="baselines", required=True)
    parser.add_argument("-T", dest="temporary", required=True)
    return parser.parse_args()


def scene_light(renderer, position, color=(1.0, 1.0, 1.0), positional=False):
    """A scene light at `position` aimed at the origin (a 60 degree spot when positional),
    added to the renderer."""
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPosition(*position)
    light.SetFocalPoint(0.0, 0.0, 0.0)
    light.SetColor(*color)
    light.SetPositional(positional)
    if positional:
        light.SetConeAngle(60.0)
    renderer.AddLight(light)
    return light


def snapshot(window):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    image = grab.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(height, width, 3).astype(int), image


def compare_with_baseline(window, name, args):
    """True when the window's picture matches the baseline <name>.png."""
    baseline = os.path.join(args.baselines, name + ".png")
    os.makedirs(args.temporary, exist_ok=True)
    testing = vtkTesting()
    for argument in ("-V", baseline, "-T", args.temporary):
        testing.AddArgument(argument)
    testing.SetRenderWindow(window)
    if not os.path.exists(baseline):
        pixels, image = snapshot(window)
        writer = vtkPNGWriter()
        writer.SetFileName(os.path.join(args.temporary, name + ".png"))
        writer.SetInputData(image)
        writer.Write()
        print("no baseline %s; the picture is in %s" % (baseline, args.temporary), file=sys.stderr)
        return False
    if testing.RegressionTest(0.15) != vtkTesting.PASSED:
        print("VTK's image comparison failed for %s" % name, file=sys.stderr)
        return False

    pixels, image = snapshot(window)
    expected = read_png(baseline)
    if expected.shape != pixels.shape:
        print("%s: size %s differs from the baseline's %s" % (name, pixels.shape, expected.shape),
              file=sys.stderr)
        return False
    changed = int((numpy.abs(pixels - expected).max(axis=2) > STRICT_LEVELS).sum())
    if changed > STRICT_PIXEL_BUDGET:
        writer = vtkPNGWriter()
        writer.SetFileName(os.path.join(args.temporary, name + ".strict.png"))
        writer.SetInputData(image)
        writer.Write()
        print("%s: %d pixels differ by more than %d levels" % (name, changed, STRICT_LEVELS),
              file=sys.stderr)
        return False
    return True


def read_png(path):
    """A PNG's RGB pixels as an int array (rows, columns, 3), the first row at the bottom as
    VTK stores them."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    channels = image.GetNumberOfScalarComponents()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, channels)
    return pixels[:, :, :3].astype(int)


class Checks:
    """Collects failed expectations; the test exits non-zero if any failed."""

    def __init__(self):
        self.failures = []

    def expect(self, condition, what):
        if not condition:
            print("Check failed: " + what, file=sys.stderr)
            self.failures.append(what)

    def exit(self):
        print("%d checks failed" % len(self.failures) if self.failures else "all checks passed")
        sys.exit(1 if self.failures else 0)
