"""The two vtkPhong mappers expose the same settings, and each reaches the one settings object.

Fails when a setting exists on one mapper and not on the other, when a mapper's setter does not
reach its vtkPhongLightingSettings, when the two disagree on a default, a clamp or the NaN
policy, and when ParaView's "Phong Surface" lacks a property for a user setting."""

import math
import os
import re

import vtkphong
from vtkmodules.vtkCommonCore import vtkCommand, vtkObject
from vtkphong_testing import Checks

checks = Checks()
Settings = vtkphong.vtkPhongLightingSettings
# Each mapper against the VTK class it extends (the composite one's depends on the version).
mappers = {
    "polydata": (vtkphong.vtkPhongPolyDataMapper, vtkphong.vtkPhongPolyDataMapper.__mro__[1]),
    "composite": (vtkphong.vtkPhongCompositePolyDataMapper,
                  vtkphong.vtkPhongCompositePolyDataMapper.__mro__[1]),
}

# The polydata mapper's normals stage: it computes missing normals itself; the composite mapper,
# like VTK's, draws the normals its blocks carry (Phong Surface computes them upstream). The
# only settings of one mapper the other lacks, on purpose (vtkPhongCompositePolyDataMapper.h).
NORMALS_STAGE = {"SetComputeMissingNormals", "SetNormalsWeighting", "SetNormalsFeatureAngle",
                 "SetNormalsSplitting", "SetNormalsWeightingToUniform", "SetNormalsWeightingToArea",
                 "SetNormalsWeightingToAngle", "SetNormalsWeightingToMax"}


def own_setters(cls, stock):
    """Set* methods a vtkPhong mapper adds to the VTK class it replaces."""
    return {name for name in dir(cls)
            if name.startswith("Set") and not hasattr(stock, name)}


def settings_setters():
    return {name for name in dir(Settings) if name.startswith("Set") and not hasattr(vtkObject, name)}


# 1. The same Set methods on both mappers, and every setting of the settings object on each.
setters = {kind: own_setters(*classes) for kind, classes in mappers.items()}
only_polydata = setters["polydata"] - setters["composite"]
only_composite = setters["composite"] - setters["polydata"]
checks.expect(only_polydata == NORMALS_STAGE,
              "only the normals stage is the polydata mapper's alone (extra: %s, missing: %s)"
              % (sorted(only_polydata - NORMALS_STAGE), sorted(NORMALS_STAGE - only_polydata)))
checks.expect(not only_composite, "nothing is the composite mapper's alone: %s"
              % sorted(only_composite))
for kind, names in setters.items():
    missing = settings_setters() - names
    checks.expect(not missing, "%s mapper has every setting: missing %s" % (kind, sorted(missing)))
    checks.expect("SetLightingSettings" in names, kind + " mapper takes a settings object")

# 2. Each mapper setter reaches the settings object; defaults and clamps are the object's.
values = {"DebugView": 6, "DebugLightIndex": 3, "ShaderSpecialization": False,
          "InterpolatedDotProducts": False, "LightCullingBound": 0.25, "ErrorBudget": 1.5,
          "SpecularAntiAliasing": True, "LightingWithoutLights": True, "DepthPrePass": 1,
          "DepthPrePassOcclusionCulling": False, "ClosedSurfaceCulling": False,
          "MaximumNumberOfShaderPrograms": 7}
defaults = Settings()
for kind, (cls, _) in mappers.items():
    mapper = cls()
    settings = mapper.GetLightingSettings()
    checks.expect(isinstance(settings, Settings), kind + ": GetLightingSettings")
    for name, value in values.items():
        checks.expect(getattr(mapper, "Get" + name)() == getattr(defaults, "Get" + name)(),
                      "%s: default %s is the settings object's" % (kind, name))
        before = mapper.GetMTime()
        getattr(mapper, "Set" + name)(value)
        checks.expect(getattr(settings, "Get" + name)() == value,
                      "%s: Set%s reaches the settings object" % (kind, name))
        checks.expect(mapper.GetMTime() > before, "%s: Set%s modifies the mapper" % (kind, name))
    mapper.SetDebugView(99)
    mapper.SetMaximumNumberOfShaderPrograms(10 ** 6)
    checks.expect(mapper.GetDebugView() == vtkphong.vtkPhongLightingSettings.BudgetUse and
                  mapper.GetMaximumNumberOfShaderPrograms() == 4096, kind + ": clamped alike")
    checks.expect(cls.SingleLight == Settings.SingleLight and cls.BudgetUse == Settings.BudgetUse and
                  cls.DepthPrePassAutomatic == Settings.DepthPrePassAutomatic,
                  kind + ": the enumerations are the settings object's")

    # One NaN policy: refused with an error naming the mapper, the value kept.
    errors = []

    def on_error(obj, event, data=None, errors=errors):
        errors.append((obj.GetClassName(), str(data)))
    on_error.CallDataType = "string0"
    mapper.AddObserver(vtkCommand.ErrorEvent, on_error)
    mapper.SetLightCullingBound(float("nan"))
    checks.expect(mapper.GetLightCullingBound() == 0.25 and len(errors) == 1 and
                  errors[0][0] == cls.__name__ and "NaN refused" in errors[0][1],
                  kind + ": NaN refused through the mapper: %s" % errors)

    # Shared settings: one object drives several mappers; ShallowCopy copies the settings.
    shared = Settings()
    mapper.SetLightingSettings(shared)
    shared.SetDepthPrePass(0)
    checks.expect(mapper.GetDepthPrePass() == 0, kind + ": a shared settings object drives it")
    copy = cls()
    vtkObject.GlobalWarningDisplayOff()  # VTK 9.1 warns about its deprecated shader-code copy
    copy.ShallowCopy(mapper)
    vtkObject.GlobalWarningDisplayOn()
    checks.expect(copy.GetDepthPrePass() == 0 and copy.GetLightingSettings() is not shared,
                  kind + ": ShallowCopy copies the settings, not the object")
    checks.expect(not math.isnan(copy.GetLightCullingBound()), kind + ": no NaN copied")

# 3. ParaView's Phong Surface: a property for every user setting (not the measurement-only ones).
xml = os.path.join(os.path.dirname(__file__), "..", "..", "..", "..", "..", "ParaView",
                   "PhongLighting", "PhongRepresentation.xml")
commands = set(re.findall(r'command="(Set\w+)"', open(xml).read()))
measurement_only = {"SetShaderSpecialization", "SetInterpolatedDotProducts"}
plain = {name for name in settings_setters()
         if not name.startswith("SetDebugViewTo") and not name.endswith(("On", "Off"))}
missing = plain - measurement_only - commands
checks.expect(not missing, "Phong Surface has a property for every user setting: missing %s"
              % sorted(missing))

checks.exit()
