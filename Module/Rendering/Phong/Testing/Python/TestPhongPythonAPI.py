"""vtkphong from Python: every class and the documented API by name, the
defaults, clamps and errors, and the enums, through VTK's own wrappers."""

import vtkphong
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkRenderingCore import vtkActor, vtkProperty, vtkRenderer
from vtkphong_testing import Checks

checks = Checks()

for name in ("vtkPhongPolyDataMapper", "vtkPhongCompositePolyDataMapper", "vtkPhongProperty",
             "vtkPhongOFFReader", "vtkPhongAssimpReader",
             "vtkOpenMeshNormals", "vtkPhongFloatRenderPass", "vtkPhongReference",
             "vtkPhongImageComparison", "vtkPhongImageIO"):
    cls = getattr(vtkphong, name, None)
    checks.expect(cls is not None, "vtkphong exposes " + name)
    checks.expect(cls is not None and bool(cls.__doc__), name + " has a docstring")

material = vtkphong.vtkPhongProperty()
checks.expect(isinstance(material, vtkProperty), "vtkPhongProperty is a vtkProperty")
for method in ("SetLightingModelToPhong", "SetLightingModelToBlinnPhong",
               "SetLightingModelToNormalizedPhong", "SetLightingModelToNormalizedBlinnPhong",
               "SetShininess", "SetEmission", "SetSmoothTerminator", "SmoothTerminatorOn",
               "SetSoftSpotEdge", "SetSpotEdgeWidth", "SetPerVertexGouraud",
               "SetInterpolationToPerVertexGouraud"):
    checks.expect(hasattr(material, method), "vtkPhongProperty." + method)

checks.expect(material.GetLightingModel() == vtkphong.vtkPhongProperty.Phong, "default lobe Phong")
material.SetLightingModelToNormalizedBlinnPhong()
checks.expect(material.GetLightingModelAsString() == "NormalizedBlinnPhong", "lobe by name")
checks.expect(material.GetShininess() == 1.0, "default shininess is VTK's SpecularPower, 1")
material.SetShininess(250000.0)
checks.expect(material.GetShininess() == 250000.0, "shininess beyond 128 is kept")
checks.expect(material.GetSpecularPower() == 128.0, "SpecularPower stays in VTK's range")
material.SetEmission(0.1, 0.2, 0.3)
checks.expect(material.GetEmission() == (0.1, 0.2, 0.3), "emission round trip")
material.SetInterpolationToPerVertexGouraud()
checks.expect(material.GetPerVertexGouraud() and material.GetInterpolationAsString() == "Gouraud",
              "per-vertex Gouraud sets both settings")

messages = []
material.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: messages.append(event))
material.AddObserver(vtkCommand.WarningEvent, lambda caller, event: messages.append(event))
material.SetShininess(float("nan"))
checks.expect(material.GetShininess() == 250000.0 and len(messages) == 1, "NaN shininess refused")
material.SetShininess(-1.0)
checks.expect(material.GetShininess() == 0.0 and len(messages) == 2, "negative shininess clamped")

mapper = vtkphong.vtkPhongPolyDataMapper()
checks.expect(mapper.GetDebugView() == vtkphong.vtkPhongPolyDataMapper.Final, "default view")
for view in ("AmbientTerm", "DiffuseTerm", "SpecularTerm", "EmissionTerm", "ShadingNormal",
             "SingleLight", "PositionVC", "NormalVC", "BudgetUse", "Final"):
    getattr(mapper, "SetDebugViewTo" + view)()
    checks.expect(mapper.GetDebugViewAsString() == view, "debug view " + view)
mapper.SetDebugLightIndex(3)
checks.expect(mapper.GetDebugLightIndex() == 3, "debug light index")
checks.expect(mapper.GetShaderCompileCount() == 0 and mapper.GetNumberOfShaderVariants() == 0,
              "no shader before the first render")
# The error budget and what it chose, on both mappers (the enum on each, as the settings'),
# before any render: the exact mode's report.
for budgeted in (mapper, vtkphong.vtkPhongCompositePolyDataMapper()):
    kind = type(budgeted).__name__
    checks.expect(budgeted.GetErrorBudget() == 0.0, kind + ": default budget 0, the exact mode")
    budgeted.SetErrorBudget(1.5)
    checks.expect(budgeted.GetErrorBudget() == 1.5, kind + ": budget round trip")
    budgeted.SetErrorBudget(0.0)
    checks.expect((type(budgeted).BudgetPerFragment, type(budgeted).BudgetSpecularPerVertex,
                   type(budgeted).BudgetPerVertex) == (0, 1, 2) and
                  vtkphong.vtkPhongLightingSettings.BudgetPerVertex == 2, kind + ": budget modes")
    checks.expect(budgeted.GetBudgetMode() == 0 and
                  budgeted.GetBudgetModeAsString() == "per fragment" and
                  budgeted.GetSquaredShininess() == 0 and budgeted.GetErrorBound() == 0.0,
                  kind + ": nothing spent before a render")
normals = vtkphong.vtkOpenMeshNormals()
for method in ("SetFeatureAngle", "SetSplitting", "SetConsistency", "SetAutoOrientNormals",
               "SetComputePointNormals", "SetComputeCellNormals", "SetFlipNormals",
               "SetNonManifoldTraversal", "SetWeightingToUniform", "SetWeightingToArea",
               "SetWeightingToAngle", "SetWeightingToMax"):
    checks.expect(hasattr(normals, method), "vtkOpenMeshNormals." + method)
checks.expect(normals.GetWeightingAsString() == "Max", "Max is the default weighting")
checks.expect(normals.GetFeatureAngle() == 30.0 and normals.GetSplitting(), "VTK's defaults")
mapper.SetNormalsWeightingToAngle()
checks.expect(mapper.GetNormalsWeighting() == vtkphong.vtkOpenMeshNormals.Angle,
              "the mapper's normals weighting")
checks.expect(mapper.GetNormalsGenerator().IsA("vtkOpenMeshNormals"), "the mapper's generator")

copy = vtkphong.vtkPhongPolyDataMapper()
copy.ShallowCopy(mapper)
checks.expect(copy.GetDebugLightIndex() == 3, "ShallowCopy copies the debug settings")
checks.expect("DebugLightIndex: 3" in str(mapper), "PrintSelf prints the settings")
checks.expect("Shininess: 0" in str(material), "vtkPhongProperty prints its own settings")
actor = vtkActor()
actor.SetMapper(mapper)
actor.SetProperty(material)
checks.expect(actor.GetProperty() is material, "an actor takes a vtkPhongProperty")

# The measuring tools.
float_pass = vtkphong.vtkPhongFloatRenderPass()
checks.expect(float_pass.GetCopyToWindow() and not float_pass.GetBlending(), "float pass defaults")
checks.expect(float_pass.GetDelegatePass().IsA("vtkRenderStepsPass"), "default delegate")
reference = vtkphong.vtkPhongReference()
reference.SetSurfaceToTorus(0.0, 0.0, 0.0, 1.0, 0.25)
checks.expect(reference.GetSurface() == vtkphong.vtkPhongReference.Torus, "reference surface")
renderer = vtkRenderer()
renderer.SetAmbient(0.5, 0.5, 0.5)
plain = vtkActor()
plain.GetProperty().SetAmbient(1.0)
plain.GetProperty().SetColor(1.0, 0.5, 0.25)
reference.SetRenderer(renderer)
reference.SetActor(plain)
reference.SetImageSize(4, 4)
rgb = [0.0, 0.0, 0.0]
reference.ShadePoint((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), False, rgb)
checks.expect(rgb == [0.5, 0.25, 0.125], "ShadePoint: ka*Ca*Ia without lights, got %s" % rgb)
comparison = vtkphong.vtkPhongImageComparison()
checks.expect(abs(comparison.GetThreshold() - 1.0 / 255.0) < 1e-12, "threshold: one level")
checks.expect(hasattr(vtkphong.vtkPhongImageIO(), "WriteImage"), "vtkPhongImageIO.WriteImage")

# The assimp reader's statics and vtkphong.materials: field data onto a vtkPhongProperty.
extensions = vtkphong.vtkPhongAssimpReader.GetSupportedExtensions()
checks.expect("*.obj" in extensions and "*.gltf" in extensions, "assimp reads OBJ and glTF")
checks.expect(vtkphong.vtkPhongAssimpReader().GetMaxFileSize() == 1 << 30, "1 GiB size limit")


def material_block(name, arrays):
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkStringArray
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    block = vtkPolyData()
    names = vtkStringArray()
    names.SetName("MaterialName")
    names.InsertNextValue(name)
    block.GetFieldData().AddArray(names)
    for array_name, values in arrays.items():
        array = vtkDoubleArray()
        array.SetName(array_name)
        array.SetNumberOfComponents(len(values))
        array.InsertNextTuple(values)
        block.GetFieldData().AddArray(array)
    return block


from vtkphong.materials import apply_material, material_of  # noqa: E402
prop = vtkphong.vtkPhongProperty()
apply_material(prop, material_of(material_block("steel", {
    "MaterialDiffuse": (0.5, 0.25, 0.125), "MaterialSpecular": (0.9, 0.9, 0.9),
    "MaterialShininess": (3000.0,), "MaterialEmission": (0.1, 0.0, 0.0),
    "MaterialOpacity": (0.5,)})))
checks.expect(list(prop.GetDiffuseColor()) == [0.5, 0.25, 0.125] and prop.GetDiffuse() == 1.0,
              "Kd as the diffuse colour, coefficient 1")
checks.expect(prop.GetShininess() == 3000.0, "Ns unclamped: %g" % prop.GetShininess())
checks.expect(list(prop.GetEmission()) == [0.1, 0.0, 0.0] and prop.GetOpacity() == 0.5,
              "Ke as the emission, d as the opacity")
untouched = vtkphong.vtkPhongProperty()
apply_material(untouched, material_of(material_block("DefaultMaterial", {
    "MaterialDiffuse": (0.2, 0.3, 0.4), "MaterialSpecular": (1.0, 1.0, 1.0),
    "MaterialShininess": (7.0,)})))
checks.expect(untouched.GetShininess() == vtkphong.vtkPhongProperty().GetShininess() and
              list(untouched.GetDiffuseColor()) == [1.0, 1.0, 1.0],
              "assimp's made-up DefaultMaterial is not applied")
checks.exit()
