//============================================================================
// vtkPhong vertex shader pieces for per-vertex Gouraud: the lighting equation
// is evaluated at each vertex and the light sums are interpolated. Injected
// at VTK's polydata vertex shader tags by vtkPhongShaderTemplate (same
// //PHONG_IF template rules as vtkPhongLightingLib.glsl). VTK's Normal::Impl
// and PositionVC::Impl have set normalVCVSOutput and vertexVCVSOutput.
//
// With DIFFUSE_PER_FRAGMENT the directional diffuse sum is left to the fragments.
//
// The sections Dots* are for per-fragment lighting instead (or that diffuse sum): they
// evaluate at each vertex the directional lights' dot products that interpolate exactly
// (INTERPOLATED_DOTS in vtkPhongLightingLib.glsl).
//============================================================================

//PHONG_SECTION Dec
//PHONG_IF SPECULAR
uniform float specularPowerUniform;
//PHONG_IF TWO_SIDED
uniform float phongShininessBF; // the back material's n
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF POSITIONAL_AMBIENT
out vec3 phongAmbientLightVSOutput;
//PHONG_ENDIF
//PHONG_IF DIFFUSE
//PHONG_IF !DIFFUSE_PER_FRAGMENT
out vec3 phongDiffuseLightVSOutput;
//PHONG_IF TWO_SIDED
out vec3 phongDiffuseLightBFVSOutput;
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF SPECULAR
out vec3 phongSpecularLightVSOutput;
//PHONG_IF TWO_SIDED
out vec3 phongSpecularLightBFVSOutput;
//PHONG_ENDIF
//PHONG_ENDIF

//PHONG_SECTION Impl
//PHONG_IF PARALLEL
  vec3 phongViewVC = vec3(0.0, 0.0, 1.0);
//PHONG_ENDIF
//PHONG_IF !PARALLEL
  vec3 phongViewVC = normalize(-vertexVCVSOutput.xyz);
//PHONG_ENDIF
  // A zero-length, infinite or NaN vertex normal has no direction: such a
  // vertex is lit as if it faced the eye.
  float phongNormalLength2 = dot(normalVCVSOutput, normalVCVSOutput);
  vec3 phongNormalVC = (phongNormalLength2 > 0.0 && phongNormalLength2 < 1.0e30)
    ? normalVCVSOutput * inversesqrt(phongNormalLength2) : phongViewVC;
//PHONG_IF SPECULAR
  float phongShininess = specularPowerUniform;
//PHONG_ENDIF
//PHONG_IF !SPECULAR
  float phongShininess = 0.0;
//PHONG_ENDIF
  phongLightSums phongFront = phongSumLights(vertexVCVSOutput.xyz, phongNormalVC, phongViewVC, phongShininess);
//PHONG_IF POSITIONAL_AMBIENT
  phongAmbientLightVSOutput = phongFront.ambient;
//PHONG_ENDIF
//PHONG_IF DIFFUSE
//PHONG_IF !DIFFUSE_PER_FRAGMENT
  phongDiffuseLightVSOutput = phongFront.diffuse;
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF SPECULAR
  phongSpecularLightVSOutput = phongFront.specular;
//PHONG_ENDIF
//PHONG_IF TWO_SIDED
//PHONG_IF DIFFUSE_OR_SPECULAR
  // Back faces are lit with the reversed normal and the back material.
//PHONG_IF SPECULAR
  phongLightSums phongBack = phongSumLights(vertexVCVSOutput.xyz, -phongNormalVC, phongViewVC, phongShininessBF);
//PHONG_ENDIF
//PHONG_IF !SPECULAR
  phongLightSums phongBack = phongSumLights(vertexVCVSOutput.xyz, -phongNormalVC, phongViewVC, 0.0);
//PHONG_ENDIF
//PHONG_IF DIFFUSE
//PHONG_IF !DIFFUSE_PER_FRAGMENT
  phongDiffuseLightBFVSOutput = phongBack.diffuse;
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF SPECULAR
  phongSpecularLightBFVSOutput = phongBack.specular;
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_ENDIF

//PHONG_SECTION DotsDec
//PHONG_IF !SUMS_PER_VERTEX
uniform vec3 phongDirectionalLightToLightVC[@DIRECTIONAL_COUNT@]; // unit L_i (else in Lights)
//PHONG_ENDIF
out vec4 phongDirectionalNormalDotLVSOutput[@DIRECTIONAL_VEC4_COUNT@];
//PHONG_IF !PARALLEL
out vec4 phongDirectionalPositionDotLVSOutput[@DIRECTIONAL_VEC4_COUNT@];
//PHONG_ENDIF

//PHONG_SECTION DotsImpl
  // n.L_i and P.L_i, with VTK's normal before normalization and position in view coordinates
  // (the unused components of the last vec4 are 0).
  phongDirectionalNormalDotLVSOutput[@DIRECTIONAL_VEC4_COUNT@ - 1] = vec4(0.0);
//PHONG_IF !PARALLEL
  phongDirectionalPositionDotLVSOutput[@DIRECTIONAL_VEC4_COUNT@ - 1] = vec4(0.0);
//PHONG_ENDIF
  for (int i = 0; i < @DIRECTIONAL_COUNT@; ++i) // unrolled (vtkPhongShaderTemplate)
  {
    phongDirectionalNormalDotLVSOutput[i / 4][i % 4] = dot(normalVCVSOutput, phongDirectionalLightToLightVC[i]);
//PHONG_IF !PARALLEL
    phongDirectionalPositionDotLVSOutput[i / 4][i % 4] = dot(vertexVCVSOutput.xyz, phongDirectionalLightToLightVC[i]);
//PHONG_ENDIF
  }
