//============================================================================
// vtkPhong fragment shader pieces, injected at VTK's polydata fragment shader
// tags by vtkPhongShaderTemplate (same //PHONG_IF template rules as
// vtkPhongLightingLib.glsl). VTK's Color::Impl has already defined
// ambientColor (ka*Ca), diffuseColor (kd*Cd), specularColor (ks*Cs),
// specularPower (n) and opacity, with the back material on back faces, and
// Normal::Impl has defined normalVCVSOutput (unit, facing the viewer on back
// faces).
//============================================================================

//PHONG_SECTION Dec
//PHONG_IF SHADING_NORMAL
// Whether n has unit length, up to what float can normalize: false for zero, infinite and
// NaN normals. NaN is caught on the bits: shader compilers rewrite a negated comparison
// (!(x < y) becomes x >= y, Mesa 25's llvmpipe does), which NaN does not survive.
bool phongIsUnitLength(vec3 n)
{
  float length2 = dot(n, n);
  bool finite = (floatBitsToUint(length2) & 0x7f800000u) != 0x7f800000u;
  return finite && abs(length2 - 1.0) < 0.5;
}
//PHONG_ENDIF
//PHONG_IF SPECULAR_ANTI_ALIASING
// The shininess of the lobe averaged over the pixel's box. The lobe cos^n is about
// exp(-n a^2 / 2) in the angle a from its axis: a Gaussian of variance 1/n per axis. The
// shading normal N varies over the pixel by its screen derivatives, and their box adds
// (|dN/dx|^2 + |dN/dy|^2) / 24 per axis (the Phong lobe's reflection vector turns twice as
// fast: four times that). Capped where derivatives spike (silhouettes, a triangle's edge
// against the background): a lobe keeps a shininess of 11 at least. Called from main's
// uniform control flow, as derivatives must be.
float phongFilteredShininess(float shininess, vec3 N)
{
  vec3 alongX = dFdx(N);
  vec3 alongY = dFdy(N);
  float spread = (dot(alongX, alongX) + dot(alongY, alongY)) / 24.0;
//PHONG_IF LOBE_PHONG
  spread *= 4.0;
//PHONG_ENDIF
  return shininess / (1.0 + shininess * min(spread, 0.09));
}
//PHONG_ENDIF
// MATERIAL_UNIFORMS: VTK's material colours are uniform (no mapped scalars, no back
// material). The products the shader needs are then uploaded ready-made: every uniform
// read costs each fragment, and VTK's ambientIntensity * ambientColorUniform, ... would
// read two per colour.
//PHONG_IF AMBIENT
//PHONG_IF MATERIAL_UNIFORMS
uniform vec3 phongAmbientTerm; // ka*Ca*(Ia + ambient light of directional lights)
//PHONG_IF POSITIONAL_AMBIENT
uniform vec3 phongMaterialAmbient; // ka*Ca
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF !MATERIAL_UNIFORMS
uniform vec3 phongAmbientLight; // Ia plus the ambient light of directional lights
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF MATERIAL_UNIFORMS
//PHONG_IF DIFFUSE
uniform vec3 phongMaterialDiffuse; // kd*Cd
//PHONG_ENDIF
//PHONG_IF SPECULAR
uniform vec3 phongMaterialSpecular; // ks*Cs, times the normalized lobe's factor
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF DEBUG_BUDGET
uniform vec3 phongBudgetUse; // the BudgetUse view's colour (vtkPhongMaterialUniforms)
//PHONG_ENDIF
//PHONG_IF EMISSION
uniform vec3 phongEmission;
//PHONG_IF BACK_MATERIAL
uniform vec3 phongEmissionBF;
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF SUMS_PER_VERTEX
//PHONG_IF POSITIONAL_AMBIENT
in vec3 phongAmbientLightVSOutput;
//PHONG_ENDIF
//PHONG_IF DIFFUSE
//PHONG_IF !DIFFUSE_PER_FRAGMENT
in vec3 phongDiffuseLightVSOutput;
//PHONG_IF TWO_SIDED
in vec3 phongDiffuseLightBFVSOutput;
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF SPECULAR
in vec3 phongSpecularLightVSOutput;
//PHONG_IF TWO_SIDED
in vec3 phongSpecularLightBFVSOutput;
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_ENDIF

//PHONG_SECTION UniformFlow
//PHONG_IF INTERPOLATED_DOTS
  // The normal as interpolated, before VTK's normal code makes it unit length.
  vec3 phongInterpolatedNormalVC = normalVCVSOutput;
//PHONG_ENDIF
//PHONG_IF NORMAL_FALLBACK
  // The face's geometric normal, for fragments whose normal is zero or NaN.
  // Derivatives need uniform control flow, so it is computed for every fragment. Each
  // derivative is scaled to its largest component first, so that the cross product neither
  // overflows (coordinates of 1e20) nor underflows (1e-20) in float.
  vec3 phongDxVC = dFdx(vertexVC.xyz);
  vec3 phongDyVC = dFdy(vertexVC.xyz);
  float phongDxMax = max(max(abs(phongDxVC.x), abs(phongDxVC.y)), abs(phongDxVC.z));
  float phongDyMax = max(max(abs(phongDyVC.x), abs(phongDyVC.y)), abs(phongDyVC.z));
  vec3 phongGeometricNormalVC = cross(phongDxMax > 0.0 ? phongDxVC / phongDxMax : phongDxVC,
    phongDyMax > 0.0 ? phongDyVC / phongDyMax : phongDyVC);
//PHONG_ENDIF

//PHONG_SECTION Impl
  // vtkPhong lighting. Textures (applied by VTK right after this block)
  // multiply the ambient and diffuse light written here; emission and
  // specular are added after them.
//PHONG_IF VIEW_VECTOR
//PHONG_IF PARALLEL
  vec3 phongViewVC = vec3(0.0, 0.0, 1.0);
//PHONG_ENDIF
//PHONG_IF !PARALLEL
  vec3 phongViewVC = normalize(-vertexVC.xyz);
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF SHADING_NORMAL
  vec3 phongNormalVC = normalVCVSOutput;
//PHONG_IF !NORMAL_FALLBACK
//PHONG_IF INTERPOLATED_DOTS
  bool phongNormalIsView = false;
//PHONG_ENDIF
  // Normalized, a usable normal has length 1: normals that cancel out when interpolated, or
  // too short or too long to normalize in float, come out 0, infinite or NaN.
  if (!phongIsUnitLength(phongNormalVC))
  {
    phongNormalVC = phongViewVC;
//PHONG_IF INTERPOLATED_DOTS
    phongNormalIsView = true;
//PHONG_ENDIF
  }
//PHONG_ENDIF
//PHONG_IF NORMAL_FALLBACK
  if (!phongIsUnitLength(phongNormalVC))
  {
    float geometricLength = length(phongGeometricNormalVC);
    phongNormalVC = geometricLength > 0.0 ? phongGeometricNormalVC / geometricLength : phongViewVC;
    if (dot(phongNormalVC, phongViewVC) < 0.0)
    {
      phongNormalVC = -phongNormalVC; // face the viewer, as VTK's normals do on back faces
    }
    if (!phongIsUnitLength(phongNormalVC))
    {
      phongNormalVC = phongViewVC;
    }
  }
//PHONG_ENDIF
//PHONG_IF ONE_SIDED
  // Without two-sided lighting a back face keeps its own, averted, normal.
  if (gl_FrontFacing == false)
  {
    phongNormalVC = -phongNormalVC;
  }
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF INTERPOLATED_DOTS
  // The shading normal as a multiple of the interpolated normal (VTK's normalization and
  // sides' flips), or of the view vector (vtkPhongLightingLib.glsl).
  phongInterpolatedNormalScale = phongNormalIsView ? 0.0
    : dot(phongNormalVC, phongInterpolatedNormalVC) / dot(phongInterpolatedNormalVC, phongInterpolatedNormalVC);
  phongViewWeight = phongNormalIsView ? dot(phongNormalVC, phongViewVC) : 0.0;
//PHONG_IF !PARALLEL
  phongMinusInverseDistance = -inversesqrt(dot(vertexVC.xyz, vertexVC.xyz));
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF SUMS_PER_FRAGMENT
//PHONG_IF !SPECULAR_ANTI_ALIASING
  phongLightSums phongSums = phongSumLights(vertexVC.xyz, phongNormalVC, phongViewVC, specularPower);
//PHONG_ENDIF
//PHONG_IF SPECULAR_ANTI_ALIASING
  // The lobe averaged over the pixel, scaled to keep its energy (2 pi / (n + 1) on the sphere).
  float phongShininess = phongFilteredShininess(specularPower, phongNormalVC);
  phongLightSums phongSums = phongSumLights(vertexVC.xyz, phongNormalVC, phongViewVC, phongShininess);
  phongSums.specular *= (phongShininess + 1.0) / (specularPower + 1.0);
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF SUMS_PER_VERTEX
  phongLightSums phongSums;
//PHONG_IF POSITIONAL_AMBIENT
  phongSums.ambient = phongAmbientLightVSOutput;
//PHONG_ENDIF
//PHONG_IF DIFFUSE
//PHONG_IF !DIFFUSE_PER_FRAGMENT
  phongSums.diffuse = phongDiffuseLightVSOutput;
//PHONG_ENDIF
//PHONG_IF DIFFUSE_PER_FRAGMENT
  phongSums.diffuse = phongDirectionalDiffuse(phongNormalVC);
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF SPECULAR
  phongSums.specular = phongSpecularLightVSOutput;
//PHONG_ENDIF
//PHONG_IF TWO_SIDED
  if (gl_FrontFacing == false)
  {
//PHONG_IF DIFFUSE
//PHONG_IF !DIFFUSE_PER_FRAGMENT
    phongSums.diffuse = phongDiffuseLightBFVSOutput;
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF SPECULAR
    phongSums.specular = phongSpecularLightBFVSOutput;
//PHONG_ENDIF
  }
//PHONG_ENDIF
//PHONG_ENDIF
  vec3 phongTexturedLight = vec3(0.0);
//PHONG_IF AMBIENT
//PHONG_IF MATERIAL_UNIFORMS
  phongTexturedLight += phongAmbientTerm;
//PHONG_IF POSITIONAL_AMBIENT
  phongTexturedLight += phongMaterialAmbient * phongSums.ambient;
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF !MATERIAL_UNIFORMS
//PHONG_IF POSITIONAL_AMBIENT
  phongTexturedLight += ambientColor * (phongAmbientLight + phongSums.ambient);
//PHONG_ENDIF
//PHONG_IF !POSITIONAL_AMBIENT
  phongTexturedLight += ambientColor * phongAmbientLight;
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF DIFFUSE
//PHONG_IF MATERIAL_UNIFORMS
  phongTexturedLight += phongMaterialDiffuse * phongSums.diffuse;
//PHONG_ENDIF
//PHONG_IF !MATERIAL_UNIFORMS
  phongTexturedLight += diffuseColor * phongSums.diffuse;
//PHONG_ENDIF
//PHONG_ENDIF
  // VTK's own names for the lit diffuse and specular colours: user replacements of
  // VTK's light tag read them (VTK's cube-map and sphere-map examples write
  // ambientColor + diffuse + specular). Unused, the compiler drops them.
  // (No comment here may name the tag: a user's replacement would land in it.)
  vec3 diffuse = vec3(0.0);
  vec3 specular = vec3(0.0);
//PHONG_IF DIFFUSE
//PHONG_IF MATERIAL_UNIFORMS
  diffuse = phongMaterialDiffuse * phongSums.diffuse;
//PHONG_ENDIF
//PHONG_IF !MATERIAL_UNIFORMS
  diffuse = diffuseColor * phongSums.diffuse;
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF SPECULAR
//PHONG_IF MATERIAL_UNIFORMS
  specular = phongMaterialSpecular * phongSums.specular;
//PHONG_ENDIF
//PHONG_IF !MATERIAL_UNIFORMS
  specular = specularColor * phongSums.specular;
//PHONG_ENDIF
//PHONG_ENDIF
  gl_FragData[0] = vec4(phongTexturedLight, opacity);

//PHONG_SECTION PostTexture
  // vtkPhong after the texture (left out when a user replacement writes the colour)
//PHONG_IF EMISSION
//PHONG_IF BACK_MATERIAL
  gl_FragData[0].rgb += gl_FrontFacing ? phongEmission : phongEmissionBF;
//PHONG_ENDIF
//PHONG_IF !BACK_MATERIAL
  gl_FragData[0].rgb += phongEmission;
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF SPECULAR
//PHONG_IF MATERIAL_UNIFORMS
  gl_FragData[0].rgb += phongMaterialSpecular * phongSums.specular;
//PHONG_ENDIF
//PHONG_IF !MATERIAL_UNIFORMS
  gl_FragData[0].rgb += specularColor * phongSums.specular;
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF DEBUG_BUDGET
  gl_FragData[0] = vec4(phongBudgetUse, 1.0);
//PHONG_ENDIF
//PHONG_IF DEBUG_NORMAL
  gl_FragData[0] = vec4(0.5 * phongNormalVC + 0.5, 1.0);
//PHONG_ENDIF
//PHONG_IF DEBUG_NORMAL_VC
  // G-buffer: the shading normal as is, for a float target; alpha tells the side.
  gl_FragData[0] = vec4(phongNormalVC, gl_FrontFacing ? 1.0 : 0.5);
//PHONG_ENDIF
//PHONG_IF DEBUG_POSITION_VC
  // G-buffer: the shaded point in view coordinates, for a float target.
  gl_FragData[0] = vec4(vertexVC.xyz, gl_FrontFacing ? 1.0 : 0.5);
//PHONG_ENDIF
  // vtkPhong after the texture: end
