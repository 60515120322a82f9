//============================================================================
// vtkPhong geometry shader pieces: when VTK draws through a geometry shader
// (wide lines, surface with edges) the per-vertex light sums pass through it.
// VTK renames the fragment shader's ...VSOutput inputs to ...GSOutput then.
// Injected at the geometry shader's Light tags inside its per-vertex loop,
// where i is the input vertex.
//============================================================================

//PHONG_SECTION Dec
//PHONG_IF POSITIONAL_AMBIENT
in vec3 phongAmbientLightVSOutput[];
out vec3 phongAmbientLightGSOutput;
//PHONG_ENDIF
//PHONG_IF DIFFUSE
in vec3 phongDiffuseLightVSOutput[];
out vec3 phongDiffuseLightGSOutput;
//PHONG_IF TWO_SIDED
in vec3 phongDiffuseLightBFVSOutput[];
out vec3 phongDiffuseLightBFGSOutput;
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF SPECULAR
in vec3 phongSpecularLightVSOutput[];
out vec3 phongSpecularLightGSOutput;
//PHONG_IF TWO_SIDED
in vec3 phongSpecularLightBFVSOutput[];
out vec3 phongSpecularLightBFGSOutput;
//PHONG_ENDIF
//PHONG_ENDIF

//PHONG_SECTION Impl
//PHONG_IF POSITIONAL_AMBIENT
    phongAmbientLightGSOutput = phongAmbientLightVSOutput[i];
//PHONG_ENDIF
//PHONG_IF DIFFUSE
    phongDiffuseLightGSOutput = phongDiffuseLightVSOutput[i];
//PHONG_IF TWO_SIDED
    phongDiffuseLightBFGSOutput = phongDiffuseLightBFVSOutput[i];
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF SPECULAR
    phongSpecularLightGSOutput = phongSpecularLightVSOutput[i];
//PHONG_IF TWO_SIDED
    phongSpecularLightBFGSOutput = phongSpecularLightBFVSOutput[i];
//PHONG_ENDIF
//PHONG_ENDIF
