"""Importing this module makes VTK's object factory return vtkPhong's mappers.

After ``import vtkphong.overrides``, every ``vtkPolyDataMapper()`` made
anywhere in the process, by the script itself, by PyVista, vedo or ParaView's
Python, is a vtkPhong mapper: an unmodified VTK script lights with vtkPhong.
Composite data: from VTK 9.3 on, VTK's own ``vtkCompositePolyDataMapper()``
(PyVista's ``add_composite``) draws its blocks with vtkPhong's block mappers
(its delegators come from the factory). On VTK 9.1, a
``vtkCompositePolyDataMapper2()`` made by name stays VTK's: its ``New()`` and
its helpers' never ask the factory; code that asks the factory for it by name
gets vtkPhong's. Objects made before the import keep their class.

``enable()`` and ``disable()`` switch the overrides at run time;
``enabled()`` tells whether they are on. ``defaults()`` is the lighting
settings object every mapper made through the switch starts from: set an
error budget, a debug view or any other setting there before building the
scene, e.g. ``vtkphong.overrides.defaults().SetErrorBudget(1.0)`` before
PyVista's ``add_mesh``. See vtkPhongObjectFactory.
"""

from .vtkRenderingPhong import vtkPhongLightingSettings, vtkPhongObjectFactory


def enable():
    """Make VTK's factory return vtkPhong's mappers (the import does this)."""
    vtkPhongObjectFactory.SetOverridesEnabled(True)


def disable():
    """Give VTK's own mappers back to code that asks the factory."""
    vtkPhongObjectFactory.SetOverridesEnabled(False)


def enabled():
    """Whether the overrides are on."""
    return vtkPhongObjectFactory.GetOverridesEnabled()


def defaults():
    """The vtkPhongLightingSettings that mappers made through the switch copy when made."""
    return vtkPhongLightingSettings.GetFactoryDefaults()


enable()
