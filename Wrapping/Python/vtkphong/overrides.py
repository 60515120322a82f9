"""Importing this module makes VTK's object factory return vtkPhong's mappers.

After ``import vtkphong.overrides``, ``vtkPolyDataMapper()`` (and
``vtkOpenGLPolyDataMapper()``, and VTK's composite mapper) made anywhere in the
process, by the script itself, by PyVista, vedo or ParaView's Python, is a
vtkPhong mapper: an unmodified VTK script lights with vtkPhong. Objects made
before the import keep their class.

``enable()`` and ``disable()`` switch the overrides at run time;
``enabled()`` tells whether they are on. See vtkPhongObjectFactory.
"""

from .vtkRenderingPhong import vtkPhongObjectFactory


def enable():
    """Make VTK's factory return vtkPhong's mappers (the import does this)."""
    vtkPhongObjectFactory.SetOverridesEnabled(True)


def disable():
    """Give VTK's own mappers back to code that asks the factory."""
    vtkPhongObjectFactory.SetOverridesEnabled(False)


def enabled():
    """Whether the overrides are on."""
    return vtkPhongObjectFactory.GetOverridesEnabled()


enable()
