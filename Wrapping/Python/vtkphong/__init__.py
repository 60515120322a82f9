"""vtkphong: exact Phong / Blinn-Phong lighting for VTK polydata.

The classes are VTK's own Python wrappers of the vtkPhong C++ module and mix
freely with ``vtkmodules``::

    from vtkmodules.vtkRenderingCore import vtkActor
    from vtkphong import vtkPhongPolyDataMapper, vtkPhongProperty

    mapper = vtkPhongPolyDataMapper()
    material = vtkPhongProperty()
    material.SetLightingModelToBlinnPhong()
    material.SetShininess(2000.0)  # vtkProperty.SetSpecularPower stops at 128
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.SetProperty(material)

Besides the mapper and its material, the package holds
vtkPhongCompositePolyDataMapper (the same lighting for multiblock and
partitioned datasets, as ParaView draws them), vtkOpenMeshNormals (normals
for meshes without them), vtkPhongFloatRenderPass (float read-back), and the
measuring tools: vtkPhongReference (the model in double precision),
vtkPhongImageComparison and vtkPhongImageIO (OpenImageIO; the command line
writes its pictures with the latter).

The lighting equation is described in docs/lighting-model.md of the project.
"""

# The wrapped classes derive from VTK's OpenGL2 classes, and the OpenGL2
# object factory must be registered before a render window is made.
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

# One extension module per VTK module of the project (Module/<Kit>/<Name>).
from .vtkCommonPhong import *  # noqa: F401,F403
from .vtkFiltersOpenMesh import *  # noqa: F401,F403
from .vtkIOMesh import *  # noqa: F401,F403
from .vtkImagingPhong import *  # noqa: F401,F403
from .vtkRenderingPhong import *  # noqa: F401,F403
from .vtkReferencePhong import *  # noqa: F401,F403
