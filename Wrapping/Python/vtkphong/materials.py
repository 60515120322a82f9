"""The materials of vtkPhongAssimpReader's blocks, onto vtkPhongProperty.

vtkPhongAssimpReader carries each mesh's material as field data on its block
(docs/io.md has the table). ``material_of(block)`` reads it into a dict and
``apply_material(prop, material)`` sets a vtkPhongProperty from it::

    from vtkphong import vtkPhongAssimpReader, vtkPhongProperty
    from vtkphong.materials import material_of, apply_material

    reader = vtkPhongAssimpReader()
    reader.SetFileName("model.obj")
    reader.Update()
    block = reader.GetOutput().GetBlock(0)
    prop = vtkPhongProperty()
    apply_material(prop, material_of(block))

The colours carry the magnitudes (the MTL meaning: Kd is the diffuse
reflectance), so the ambient, diffuse and specular coefficients are set to 1
when their colour is given; the shininess is the file's exponent, unclamped.
"""

import math

# Field-data array -> (key of the dict, number of components).
FIELDS = {
    "MaterialAmbient": ("ambient", 3),
    "MaterialDiffuse": ("diffuse", 3),
    "MaterialSpecular": ("specular", 3),
    "MaterialEmission": ("emission", 3),
    "MaterialShininess": ("shininess", 1),
    "MaterialOpacity": ("opacity", 1),
}

# assimp gives files without a material one it makes up (unnamed, or this name, with
# white colours); it is not the file's and is not applied.
DEFAULT_MATERIAL_NAMES = ("", "DefaultMaterial")


def material_of(block):
    """The block's material as a dict (name, ambient, diffuse, specular, emission,
    shininess, opacity, diffuse_texture: whichever the file gave), or None when the file
    gave none. Values that are not finite are left out."""
    fields = block.GetFieldData()
    name = _string(fields, "MaterialName")
    if name is None or name in DEFAULT_MATERIAL_NAMES:
        return None
    material = {"name": name}
    for array_name, (key, components) in FIELDS.items():
        array = fields.GetArray(array_name)
        if array is None or array.GetNumberOfTuples() < 1 or \
                array.GetNumberOfComponents() != components:
            continue
        values = list(array.GetTuple(0))
        if all(math.isfinite(value) for value in values):
            material[key] = values if components > 1 else values[0]
    texture = _string(fields, "MaterialDiffuseTexture")
    if texture:
        material["diffuse_texture"] = texture
    return material


def _string(fields, name):
    """The first value of a string array of the field data, decoded; None if absent."""
    array = fields.GetAbstractArray(name)
    if array is None or not array.IsA("vtkStringArray") or array.GetNumberOfValues() < 1:
        return None
    value = array.GetValue(0)
    if isinstance(value, bytes):  # VTK returns bytes for text that is not UTF-8
        value = value.decode("utf-8", "replace")
    return value


def apply_material(prop, material):
    """Set prop (a vtkPhongProperty, or a vtkProperty without shininess and emission)
    from a dict of material_of. Keys the material lacks leave prop as it was; without a
    specular colour, or when it is 0, the file's shininess is not applied: assimp reports 0
    for materials that give none (an OBJ without Ns, glTF), and an exponent of 0 would
    light the whole lit side of a surface with the highlight's colour. An opacity of 0 is
    not applied either."""
    if not material:
        return
    colour_setters = (("ambient", prop.SetAmbientColor, prop.SetAmbient),
                      ("diffuse", prop.SetDiffuseColor, prop.SetDiffuse),
                      ("specular", prop.SetSpecularColor, prop.SetSpecular))
    for key, set_colour, set_coefficient in colour_setters:
        if key in material:
            set_colour([min(max(value, 0.0), 1.0) for value in material[key]])
            set_coefficient(1.0)
    if material.get("shininess", 0.0) > 0.0 and "specular" in material and \
            hasattr(prop, "SetShininess"):
        prop.SetShininess(material["shininess"])
    if "emission" in material and hasattr(prop, "SetEmission"):
        prop.SetEmission([max(value, 0.0) for value in material["emission"]])
    # An opacity of 0 would hide the part: exporters write it for "no transparency"
    # (3ds Max's COLLADA), so it is not applied.
    if material.get("opacity", 0.0) > 0.0:
        prop.SetOpacity(min(material["opacity"], 1.0))
