"""vtkphong-render: render a mesh file to an image with vtkPhong's lighting.

The command-line renderer (``vtkphong-render MESH -o OUT.png``), also usable
from Python::

    from vtkphong import render
    render.main(["bunny.off", "-o", "bunny.png", "--lobe", "phong"])

Run ``vtkphong-render --help`` for the options, the scene-file format and the
exit codes.

This module is the command line: the options, the settings the flags give,
the progress line, the error messages and exit status. The rest lies beside
it in the package:

- ``_scene``: the defaults, the studio light rig, the JSON scene file;
- ``_meshio``: reading the mesh files;
- ``_rendering``: the VTK pipeline and writing the image;
- ``_errors``: UsageError and RenderError, which main turns into exit statuses.
"""

import argparse
import math
import os
import sys

from vtkphong._errors import RenderError, UsageError
from vtkphong._meshio import FORMATS, address_space_limit, read_mesh
from vtkphong._rendering import OUTPUTS, render, write_image
from vtkphong._scene import (CAMERA_LIMITS, DEBUG_VIEWS, INTERPOLATIONS, LIGHT_TYPES, LOBES,
                             WEIGHTINGS, check_size, scene_settings)

PROGRAM = "vtkphong-render"

# Meshes bigger than this (bytes on disk) get a progress line.
PROGRESS_FILE_SIZE = 8 * 1024 * 1024

EPILOG = """\
input formats:
%(formats)s

output formats (by the extension of -o):
%(outputs)s

lights:
  Without --light or a scene file's "lights", a three-light studio rig is used
  (key, fill and rim camera lights that follow the view). --light TYPE:X,Y,Z
  adds a scene light (TYPE: directional, point or spot) at X,Y,Z measured from
  the mesh's centre in units of its bounding radius, aimed at the centre;
  optional :R,G,B colour and :INTENSITY follow, e.g.
      --light point:1,1,1.5:1,0.9,0.8:1.2
  Any --light replaces the rig and the scene file's lights.

scene file (--scene FILE.json), every key optional, flags win over it:
  {
    "size": [W, H], "background": [R, G, B], "transparent": false,
    "lobe": "blinn-phong", "interpolation": "phong",
    "debug_view": "final", "debug_light": 0, "error_budget": 0, "specular_aa": false,
    "renderer_ambient": [1, 1, 1],
    "camera": {"azimuth": 30, "elevation": 20, "zoom": 1},
    "material": {"color": [R, G, B], "ambient": 0.1, "diffuse": 0.8,
                 "specular": 0.4, "shininess": 60,
                 "specular_color": [1, 1, 1], "emission": [0, 0, 0]},
    "normals": {"weighting": "max", "feature_angle": 30, "splitting": true},
    "lights": [{"type": "point", "kind": "scene",
                "position": [1, 1, 1.5], "focal_point": [0, 0, 0],
                "color": [1, 1, 1], "intensity": 1,
                "ambient_color": [0, 0, 0], "specular_color": [1, 1, 1],
                "attenuation": [1, 0, 0], "cone_angle": 30, "exponent": 1}]
  }
  Light "kind": "scene" (positions relative to the mesh, as --light),
  "camera" (VTK camera-light coordinates: the camera at (0, 0, 1), the focal
  point at the origin) or "headlight" (at the camera; no position).

materials and colours:
  Files with materials (OBJ's .mtl, glTF, FBX, COLLADA, 3DS...) give each part
  its Ka, Kd, Ks colours, Ke emission, opacity, diffuse texture and Ns
  shininess (unclamped, used as is with the default Blinn-Phong lobe).
  Material flags override the file. Vertex and face colours (8-bit or float)
  are shown unless --color is given. Point clouds and lines are drawn as
  points and lines a few pixels wide, unlit when they have no normals.

robustness:
  The file is read in a child process with a limit on its address space
  (VTKPHONG_READ_MEMORY_MB, default half the RAM) and a timeout
  (VTKPHONG_READ_TIMEOUT, default 300 s); cells naming points that do not
  exist, coordinates that are not finite or beyond 1e30 are refused. A file
  that cannot be read is one line on stderr and status 1, never a crash.
  The rendering runs in a child process too: should VTK or the OpenGL driver
  crash on what it was given, that is also one line and status 1.

exit status: 0 on success, 1 when the mesh cannot be read or the image cannot
be made or written, 2 for bad options or a bad scene file. Errors are one line
on stderr. Rendering needs an X display (run under xvfb-run -a on a server).
""" % {
    "formats": "\n".join("  %-6s %s" % item for item in FORMATS.items()),
    "outputs": "\n".join("  %-6s %s" % item for item in OUTPUTS.items()),
}



# --- option values ---------------------------------------------------------

def _numbers(text, count, what):
    try:
        values = [float(part) for part in text.split(",")]
    except ValueError:
        raise UsageError("%s must be %d comma-separated numbers, not %r" % (what, count, text))
    if len(values) != count or not all(math.isfinite(v) for v in values):
        raise UsageError("%s must be %d comma-separated finite numbers, not %r"
                         % (what, count, text))
    return values


def _color(text, what="a colour"):
    values = _numbers(text, 3, what)
    if min(values) < 0.0:
        raise UsageError("%s must not be negative: %r" % (what, text))
    return values


def _size(text):
    parts = text.lower().split("x")
    try:
        width, height = (int(part) for part in parts)
    except ValueError:
        raise UsageError("--size must be WIDTHxHEIGHT, e.g. 1024x768, not %r" % text)
    check_size([width, height], "--size")
    return [width, height]


def _unit_range(name, low=0.0, high=1.0):
    def parse(text):
        try:
            value = float(text)
        except ValueError:
            raise UsageError("%s must be a number, not %r" % (name, text))
        if not (low <= value <= high):
            raise UsageError("%s must be in [%g, %g], not %r" % (name, low, high, text))
        return value
    return parse


def _light_option(text):
    parts = text.split(":")
    if len(parts) < 2 or len(parts) > 4 or parts[0] not in LIGHT_TYPES:
        raise UsageError("--light must be TYPE:X,Y,Z[:R,G,B[:INTENSITY]] with TYPE one of %s,"
                         " not %r" % (", ".join(LIGHT_TYPES), text))
    light = {"kind": "scene", "type": parts[0],
             "position": _numbers(parts[1], 3, "a --light position")}
    if len(parts) > 2:
        light["color"] = _color(parts[2], "a --light colour")
    if len(parts) > 3:
        light["intensity"] = _unit_range("a --light intensity", 0.0, 1e6)(parts[3])
    return light


# --- the parser: its options in the order --help lists them ------------------

class _Parser(argparse.ArgumentParser):
    # argparse would print the usage and exit; the command's errors are one line.
    def error(self, message):
        raise UsageError("%s (see --help)" % message)


def make_parser():
    parser = _Parser(
        prog=PROGRAM,
        description="Render a mesh to an image with vtkPhong's exact Phong / Blinn-Phong"
                    " lighting: camera fitted to the mesh, a three-light studio rig,"
                    " Blinn-Phong, normals computed when the file has none.",
        epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mesh", help="the mesh file (%s)" % ", ".join(FORMATS))
    parser.add_argument("-o", "--output", required=True, help="the image to write (.png or .exr)")
    parser.add_argument("--scene", metavar="FILE.json", help="a scene file (format below)")
    _add_image_options(parser)
    _add_material_options(parser)
    _add_light_and_camera_options(parser)
    _add_debug_and_normals_options(parser)
    parser.add_argument("--quiet", action="store_true", help="no progress line, no output path")
    return parser


def _add_image_options(parser):
    parser.add_argument("--size", type=_size, metavar="WxH", help="image size (default 1024x768)")
    parser.add_argument("--background", type=_color, metavar="R,G,B",
                        help="background colour (default 0.12,0.12,0.14)")
    parser.add_argument("--transparent", action="store_true", default=None,
                        help="PNG with alpha: the background transparent")


def _add_material_options(parser):
    parser.add_argument("--lobe", choices=LOBES, help="specular lobe (default blinn-phong)")
    parser.add_argument("--interpolation", choices=INTERPOLATIONS,
                        help="shading interpolation (default phong)")
    parser.add_argument("--color", type=_color, metavar="R,G,B",
                        help="surface colour (default: the file's colours, else 0.8 grey)")
    parser.add_argument("--ambient", type=_unit_range("--ambient"), metavar="K",
                        help="ambient coefficient ka in [0, 1] (default 0.1)")
    parser.add_argument("--diffuse", type=_unit_range("--diffuse"), metavar="K",
                        help="diffuse coefficient kd in [0, 1] (default 0.8)")
    parser.add_argument("--specular", type=_unit_range("--specular"), metavar="K",
                        help="specular coefficient ks in [0, 1] (default 0.4)")
    parser.add_argument("--shininess", type=_unit_range("--shininess", 0.0, 1e6), metavar="N",
                        help="specular exponent n in [0, 1e6] (default 60)")
    parser.add_argument("--emission", type=_color, metavar="R,G,B", help="emitted colour")


def _add_light_and_camera_options(parser):
    parser.add_argument("--light", type=_light_option, action="append", metavar="SPEC",
                        help="add a scene light (see 'lights' below); repeatable")
    parser.add_argument("--azimuth", type=_unit_range("--azimuth", *CAMERA_LIMITS["azimuth"]),
                        metavar="DEG", help="camera azimuth around the mesh (default 30)")
    parser.add_argument("--elevation",
                        type=_unit_range("--elevation", *CAMERA_LIMITS["elevation"]),
                        metavar="DEG", help="camera elevation (default 20)")
    parser.add_argument("--zoom", type=_unit_range("--zoom", *CAMERA_LIMITS["zoom"]),
                        metavar="F", help="camera zoom factor (default 1)")


def _add_debug_and_normals_options(parser):
    parser.add_argument("--debug-view", choices=DEBUG_VIEWS,
                        help="show one term, the normal, one light, or how the error budget is spent "
                             "(default final)")
    parser.add_argument("--debug-light", type=int, metavar="I",
                        help="the light shown by --debug-view single-light (default 0)")
    parser.add_argument("--error-budget", type=_unit_range("--error-budget", 0, 255),
                        metavar="LEVELS",
                        help="how far each pixel may stray from the exact model, in 8-bit "
                        "levels, for speed (default 0: exact; docs/lighting-model.md)")
    parser.add_argument("--specular-aa", action="store_true", default=None,
                        help="average each highlight over its pixel: no sparkle or flicker "
                        "from highlights narrower than a pixel (default off)")
    parser.add_argument("--normals-weighting", choices=WEIGHTINGS,
                        help="weighting of computed normals (default max)")
    parser.add_argument("--feature-angle", type=_unit_range("--feature-angle", 0, 180),
                        metavar="DEG", help="normals split above this angle (default 30)")


# --- the settings: defaults < scene file < flags ------------------------------

def settings_from(options):
    """The full settings: the defaults, then the scene file, then the flags."""
    settings = scene_settings(options.scene)
    _apply_flags(settings, options)
    if settings["debug_light"] < 0:
        raise UsageError("--debug-light must be 0 or more")
    return settings


def _apply_flags(settings, options):
    """Each flag given wins over the scene file; argparse leaves the others None."""
    flags = {"size": options.size, "background": options.background,
             "transparent": options.transparent, "lobe": options.lobe,
             "interpolation": options.interpolation, "debug_view": options.debug_view,
             "debug_light": options.debug_light, "lights": options.light,
             "error_budget": options.error_budget, "specular_aa": options.specular_aa}
    for key, value in flags.items():
        if value is not None:
            settings[key] = value
    for key in ("color", "ambient", "diffuse", "specular", "shininess", "emission"):
        value = getattr(options, key)
        if value is not None:
            settings["material"][key] = value
            settings["material_set"].add(key)
    for key in ("azimuth", "elevation", "zoom"):
        if getattr(options, key) is not None:
            settings["camera"][key] = getattr(options, key)
    if options.normals_weighting is not None:
        settings["normals"]["weighting"] = options.normals_weighting
    if options.feature_angle is not None:
        settings["normals"]["feature_angle"] = options.feature_angle


# --- what the user sees besides the image: progress, VTK's complaints ---------

class Progress:
    """One line on stderr, rewritten in place, for big meshes."""

    def __init__(self, enabled):
        self.enabled = enabled
        self.shown = False

    def observe(self, algorithm, stage):
        if not self.enabled:
            return

        def report(caller, _event):
            sys.stderr.write("\r%s: %s %3d%%" % (PROGRAM, stage, int(100 * caller.GetProgress())))
            sys.stderr.flush()
            self.shown = True
        algorithm.AddObserver("ProgressEvent", report)

    def stage(self, stage):
        if self.enabled:
            sys.stderr.write("\r%s: %s     " % (PROGRAM, stage))
            sys.stderr.flush()
            self.shown = True

    def done(self):
        if self.shown:
            sys.stderr.write("\r%s: done%s\n" % (PROGRAM, " " * 24))
            sys.stderr.flush()
            self.shown = False


class _MessageLog:
    """VTK's warnings and errors, kept instead of printed (the command prints one line of
    its own). They go to a file as they come, so that a renderer killed by a signal (VTK
    aborts on some failures) still leaves what VTK said before it; the file is the
    parent's when the command runs isolated, and is removed by whoever made it."""

    def __init__(self, path=None):
        from vtkmodules.vtkCommonCore import vtkFileOutputWindow, vtkLogger, vtkOutputWindow
        self.owned = path is None
        self.path = path or _new_message_file()
        self.window = vtkFileOutputWindow()
        self.window.SetFileName(self.path)
        self.window.FlushOn()
        vtkOutputWindow.SetInstance(self.window)
        vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)

    def GetOutput(self):
        return _read_messages(self.path)

    def close(self):
        from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
        vtkOutputWindow.SetInstance(vtkStringOutputWindow())  # closes the file
        if self.owned:
            _remove(self.path)


def _new_message_file():
    import tempfile
    handle, path = tempfile.mkstemp(prefix="vtkphong-render-", suffix=".log")
    os.close(handle)
    return path


def _read_messages(path):
    try:
        with open(path, "rb") as stream:
            return stream.read()
    except OSError:
        return b""


def _remove(path):
    try:
        os.remove(path)
    except OSError:
        pass


# The isolated command's message file: made by the parent before the fork, written by the
# child, read by the parent if the child dies of a signal.
_ISOLATED_MESSAGE_FILE = None


def _first_vtk_error(collector):
    """The first VTK error message collected, on one printable line, or ''."""
    return _first_error_in(collector.GetOutput())


def _first_error_in(text):
    """The first VTK error message in text (what VTK's output window wrote), on one
    printable line, or ''."""
    if isinstance(text, bytes):
        text = text.decode("utf-8", "replace")
    for block in text.split("\n\n"):
        block = block.strip("\n")
        if "ERROR" in block or "Warning" in block:
            # "ERROR: In file, line N\nvtkClass (0x...): message, maybe on several lines"
            message = " ".join(block.split("\n")[1:]) if "\n" in block else block
            if "): " in message:
                message = message.split("): ", 1)[1]
            message = "".join(c if " " <= c <= "~" else "?" for c in message).strip()
            return message if len(message) <= 160 else message[:157] + "..."
    return ""


def _with_reason(error, collector):
    """The error, with VTK's first complaint appended when there is one."""
    reason = _first_vtk_error(collector)
    return RenderError("%s (%s)" % (error, reason) if reason else str(error))


# --- the command -------------------------------------------------------------

def run(arguments):
    """Render as the command line asks; raises UsageError or RenderError."""
    options = make_parser().parse_args(arguments)
    settings = settings_from(options)
    _check_output(options.output)
    if sys.platform.startswith("linux") and not os.environ.get("DISPLAY"):
        raise RenderError("no X display to render with: run under xvfb-run -a")

    collector = _MessageLog(_ISOLATED_MESSAGE_FILE)
    try:
        _render_and_write(options, settings, collector)
    except (RenderError, UsageError):
        raise
    except Exception as error:  # a bug: still one line, naming the file, unless debugging
        if os.environ.get("VTKPHONG_DEBUG"):
            raise
        raise RenderError("internal error while rendering %s: %s: %s (VTKPHONG_DEBUG=1 shows "
                          "the traceback)" % (options.mesh, type(error).__name__, error))
    finally:
        collector.close()


def _render_and_write(options, settings, collector):
    progress = Progress(_is_big(options.mesh) and not options.quiet)
    parts = _read_parts(options.mesh, progress, collector)
    image = render(parts, settings, progress)
    progress.done()
    scalars = image.GetPointData().GetScalars()
    if scalars is None or image.GetNumberOfPoints() == 0:
        message = _first_vtk_error(collector)
        raise RenderError("rendering failed" + (": " + message if message else ""))
    write_image(image, options.output, settings)
    if not options.quiet:
        print(options.output)


def _check_output(output):
    """Refuse a bad -o before the mesh is read: reading may take minutes."""
    output_extension = os.path.splitext(output)[1].lower()
    if output_extension not in OUTPUTS:
        raise UsageError("-o must name a .png or .exr file, not %r" % output)
    output_directory = os.path.dirname(os.path.abspath(output))
    if not os.path.isdir(output_directory):
        raise RenderError("cannot write %s: no directory %s" % (output, output_directory))


def _is_big(path):
    try:
        return os.path.getsize(path) > PROGRESS_FILE_SIZE
    except OSError:
        return False  # read_mesh says what is wrong with the file


def _read_parts(path, progress, collector):
    """The mesh's parts, its warnings printed; a failure tells VTK's reason too."""
    warnings = []
    try:
        parts = read_mesh(path, progress, warnings)
    except RenderError as error:
        progress.done()
        raise _with_reason(error, collector)
    except OSError as error:
        progress.done()
        raise RenderError("cannot read %s: %s" % (path, error.strerror or error))
    for warning in warnings:
        progress.done()
        print("%s: warning: %s" % (PROGRAM, warning), file=sys.stderr)
    return parts


def main(arguments=None, isolated=False):
    """The command: returns its exit status.

    isolated: run it in a forked child process (the installed command does), so that a
    crash anywhere (VTK, the OpenGL driver) is still one error line and status 1.
    """
    if arguments is None:
        arguments = sys.argv[1:]
    if isolated and hasattr(os, "fork"):
        return _main_in_child(arguments)
    try:
        run(arguments)
    except UsageError as error:
        print("%s: error: %s" % (PROGRAM, error), file=sys.stderr)
        return 2
    except RenderError as error:
        print("%s: error: %s" % (PROGRAM, error), file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("%s: interrupted" % PROGRAM, file=sys.stderr)
        return 130
    except Exception as error:  # a bug: still one line, unless asked for the traceback
        if os.environ.get("VTKPHONG_DEBUG"):
            raise
        print("%s: error: internal error: %s: %s (VTKPHONG_DEBUG=1 shows the traceback)"
              % (PROGRAM, type(error).__name__, error), file=sys.stderr)
        return 1
    return 0


def _main_in_child(arguments):
    """main(arguments) in a forked child; its status, or an error line if a signal ended it.

    The file is already read in a child of its own (_meshio); this one contains what comes
    after: VTK's pipeline, the OpenGL driver, the image writer."""
    global _ISOLATED_MESSAGE_FILE
    sys.stdout.flush()
    sys.stderr.flush()
    _ISOLATED_MESSAGE_FILE = _new_message_file()
    try:
        return _wait_for_child(arguments, _ISOLATED_MESSAGE_FILE)
    finally:
        _remove(_ISOLATED_MESSAGE_FILE)
        _ISOLATED_MESSAGE_FILE = None


def _wait_for_child(arguments, message_file):
    """Fork, run main in the child, and turn its end into a status."""
    read_end, write_end = os.pipe()
    child = os.fork()
    if child == 0:
        os.close(read_end)
        os.dup2(write_end, 2)  # the C++ runtime's last words go through the filter below
        status = 1
        try:
            status = main(arguments)
        except SystemExit as exit:  # --help, --version
            status = exit.code if isinstance(exit.code, int) else int(exit.code is not None)
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os._exit(status)
    os.close(write_end)
    relay = _StderrRelay(read_end)
    while True:
        try:
            wait_status = os.waitpid(child, 0)[1]
            break
        except KeyboardInterrupt:
            continue  # the terminal's SIGINT reached the child too; it says "interrupted"
    relay.finish()
    if os.WIFSIGNALED(wait_status):
        print("%s: error: %s" % (PROGRAM, _crash_reason(
            os.WTERMSIG(wait_status), arguments, _read_messages(message_file), relay.dropped)),
              file=sys.stderr)
        return 1
    return os.WEXITSTATUS(wait_status)


class _StderrRelay:
    """Copies the rendering child's standard error to ours as it comes, but for the lines the
    C++ runtime writes as it aborts (kept in `dropped` for the one error line)."""

    RUNTIME_LINES = ("terminate called", "  what():")

    def __init__(self, descriptor):
        import threading
        self.dropped = []
        # newline="": a progress line rewritten with carriage returns passes as it is.
        self._stream = os.fdopen(descriptor, "r", errors="replace", newline="")
        self._thread = threading.Thread(target=self._copy, daemon=True)
        self._thread.start()

    def _copy(self):
        for line in self._stream:
            if line.startswith(self.RUNTIME_LINES):
                self.dropped.append(line.strip())
            else:
                sys.stderr.write(line)
                sys.stderr.flush()

    def finish(self):
        self._thread.join()
        self._stream.close()


def _crash_reason(number, arguments, messages, runtime_lines):
    """The error line's text for a rendering child ended by a signal."""
    said = _first_error_in(messages)
    mesh = _mesh_argument(arguments)
    out_of_memory = any("bad_alloc" in line for line in runtime_lines) or (
        said and "Unable to allocate" in said)
    if out_of_memory:
        limit = address_space_limit()
        return "out of memory rendering %s%s" % (
            mesh, " (address space limited to %d MB by ulimit -v)" % (limit >> 20) if limit else "")
    return "the renderer crashed (%s) on %s%s; please report it with the file" % (
        _signal_name(number), mesh, ", after VTK's error: " + said.rstrip(".") if said else "")


def _signal_name(number):
    import signal
    try:
        return signal.Signals(number).name
    except ValueError:
        return "signal %d" % number


def _mesh_argument(arguments):
    """The mesh the command line names, for the error line (or "the input")."""
    try:
        return make_parser().parse_known_args(arguments)[0].mesh
    except (UsageError, SystemExit):
        return "the input"


if __name__ == "__main__":
    sys.exit(main(isolated=True))
