"""No include runs upwards: the layers of docs/dev/ARCHITECTURE.md, checked on the sources.

Two levels, tests aside (a test may reach into its own module's private headers):

- Modules. Each module (Module/<Kit>/<Name>, the ParaView plugin's representation) has a
  rank; a source file includes vtkPhong headers of its own module or of lower-ranked ones
  only, and never a private header of another module (one listed as private in that module's
  CMakeLists.txt, or a .txx).
- Files of the rendering module. Each private piece has a rank (the shader path's foundation,
  its parts, the mapper core, the lighting mapper template, the mappers, the composite mapper,
  the factory); a file includes its own header and headers of lower rank only.

Prints each violation and exits non-zero when there is one.

    vtkPhongLayerCheck.py <source root>
"""

import os
import re
import sys

# Lower ranks are included by higher ones, never the reverse.
MODULE_RANKS = {
    "Module/Common/Phong": 0,
    "Module/Filters/OpenMesh": 1,
    "Module/IO/Mesh": 1,
    "Module/Imaging/Phong": 1,
    "Module/Rendering/Phong": 2,
    "Module/Rendering/PhongOverrides": 3,
    "Module/Reference/Phong": 3,
    "ParaView/PhongLighting/Representation": 4,
}

# The rendering module's files by class (file name without extension).
RENDERING_RANKS = {
    # foundation: no vtkPhong include but each other
    "vtkPhongCompatibility": 0, "vtkPhongOpenGL": 0, "vtkPhongProblemLog": 0, "vtkPhongShaderFeatures": 0,
    "vtkPhongLightingSettings": 0, "vtkPhongProperty": 0, "vtkPhongUniformValue": 0,
    "vtkPhongBackgroundTask": 0,
    # foundation over the problem log: its LargestAttenuation
    "vtkPhongAttenuation": 0.5,
    # the plan, shared maths, small helpers
    "vtkPhongShaderPlan": 1, "vtkPhongMaterial": 1, "vtkPhongLightGeometry": 1,
    "vtkPhongShaderCode": 1, "vtkPhongBufferBlocks": 1, "vtkPhongScopedCulling": 1,
    "vtkPhongValidBlocks": 1, "vtkPhongGouraudBound": 1,
    # shader path parts and visibility parts, in the order they use each other
    "vtkPhongLightCulling": 2.0, "vtkPhongShadowMaps": 2.0, "vtkPhongDepthPrePass": 2.0,
    "vtkPhongErrorBudget": 2.05,
    "vtkPhongShaderPlanner": 2.1, "vtkPhongShaderTemplate": 2.1, "vtkPhongLightUniforms": 2.1,
    "vtkPhongMaterialUniforms": 2.1, "vtkPhongVisibleClusters": 2.1,
    "vtkPhongClosedSurface": 2.2,
    # the core over the shader path, the one lighting mapper over the core and visibility
    "vtkPhongMapperCore": 3,
    "vtkPhongLightingMapper": 4,
    # the mappers made from it, then what makes and registers them
    "vtkPhongPolyDataMapper": 5, "vtkPhongBlockMapper": 5, "vtkPhongFloatRenderPass": 5,
    "vtkPhongCompositeDelegator": 6,
    "vtkPhongCompositePolyDataMapper": 7,
    "vtkPhongObjectFactory": 8,
}

INCLUDE = re.compile(r'^\s*#\s*include\s+"((?:vtkPhong|vtkOpenMesh)\w*)\.(h|txx)"', re.M)
SOURCE_SUFFIXES = (".h", ".cxx", ".txx")


def module_files(root, module):
    for folder, subfolders, names in os.walk(os.path.join(root, module)):
        subfolders[:] = sorted(name for name in subfolders if name != "Testing")
        for name in sorted(names):
            if name.endswith(SOURCE_SUFFIXES):
                yield os.path.join(folder, name)


def private_headers(root, module):
    """Headers a module keeps to itself: its PRIVATE_HEADERS and private_headers lists."""
    text = open(os.path.join(root, module, "CMakeLists.txt")).read()
    names = set()
    for block in re.findall(r"(?:set\(private_headers|PRIVATE_HEADERS)([^)]*)\)", text):
        names.update(re.findall(r"(vtk\w+)\.(?:h|txx)", block))
    return names


def owners(root):
    """Each vtkPhong header's module, and the module's private headers."""
    owner, private = {}, {}
    for module in MODULE_RANKS:
        private[module] = private_headers(root, module)
        for path in module_files(root, module):
            name, suffix = os.path.splitext(os.path.basename(path))
            if suffix in (".h", ".txx"):
                owner[name] = module
    return owner, private


def check(root):
    owner, private = owners(root)
    problems = []
    for module, rank in MODULE_RANKS.items():
        for path in module_files(root, module):
            own = os.path.splitext(os.path.basename(path))[0]
            for name, suffix in INCLUDE.findall(open(path).read()):
                where = owner.get(name)
                relative = os.path.relpath(path, root)
                if where is None or name == own:
                    continue  # generated (embedded GLSL) or the file's own header
                if where != module:
                    if MODULE_RANKS[where] >= rank:
                        problems.append("%s includes %s of %s, a module not below it"
                                        % (relative, name, where))
                    if name in private[where] or suffix == "txx":
                        problems.append("%s includes %s, private to %s" % (relative, name, where))
                elif module == "Module/Rendering/Phong":
                    mine, theirs = RENDERING_RANKS.get(own), RENDERING_RANKS.get(name)
                    if mine is None or theirs is None:
                        problems.append("%s or %s has no layer in vtkPhongLayerCheck.py"
                                        % (own, name))
                    elif theirs >= mine:
                        problems.append("%s (layer %s) includes %s (layer %s)"
                                        % (relative, mine, name, theirs))
    return problems


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.getcwd()
    problems = check(root)
    for problem in problems:
        print("ERROR: " + problem)
    print("%d upward includes" % len(problems))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
