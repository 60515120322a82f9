//============================================================================
// vtkPhong lighting library: the lights of the scene and the sum of their
// contributions (docs/lighting-model.md):
//
//   C = E + ka*Ca*Ia
//         + sum_i A_i * ( ka*Ca*La_i*I_i + kd*Cd*Ld_i*I_i*max(N.L_i, 0)
//                       + ks*Cs*Ls_i*I_i*S_i*G_i )
//
// This file is a template read by vtkPhongShaderTemplate. A line between
// "//PHONG_IF FLAG" and "//PHONG_ENDIF" is kept only when the scene needs FLAG
// ("!FLAG": when it does not), and @NAME@ is replaced by a number, so the
// shader carries only the light kinds and the terms in use. Light colours
// arrive premultiplied by the light's intensity. A light's specular colour is
// its diffuse colour unless set apart (vtkLight::SetSpecularColor); only then
// (SEPARATE_SPECULAR_COLORS) do the specular sums read arrays of their own, as
// every uniform read costs each fragment on llvmpipe. Directions and positions
// are in view coordinates (VC). The ambient light of directional lights does not
// depend on the surface and is folded into one uniform on the CPU.
//============================================================================

//PHONG_SECTION Sums
//PHONG_IF LIGHT_SUMS
// The light reaching a surface point, summed over lights, before the
// material's coefficients and colours multiply it.
struct phongLightSums
{
//PHONG_IF POSITIONAL_AMBIENT
  vec3 ambient; // sum over positional lights of A_i*La_i*I_i
//PHONG_ENDIF
//PHONG_IF DIFFUSE
  vec3 diffuse; // sum of A_i*Ld_i*I_i*max(N.L_i, 0)
//PHONG_ENDIF
//PHONG_IF SPECULAR
  vec3 specular; // sum of A_i*Ls_i*I_i*S_i*G_i
//PHONG_ENDIF
};
//PHONG_ENDIF

//PHONG_SECTION Lights
//PHONG_IF DIRECTIONAL
const int phongDirectionalLightCount = @DIRECTIONAL_COUNT@;
uniform vec3 phongDirectionalLightToLightVC[@DIRECTIONAL_COUNT@]; // unit L_i
//PHONG_IF DIFFUSE
uniform vec3 phongDirectionalLightDiffuse[@DIRECTIONAL_COUNT@]; // Ld_i*I_i
//PHONG_ENDIF
//PHONG_IF SEPARATE_SPECULAR_COLORS
uniform vec3 phongDirectionalLightSpecular[@DIRECTIONAL_COUNT@]; // Ls_i*I_i
//PHONG_ENDIF
//PHONG_ENDIF

//PHONG_IF INTERPOLATED_DOTS
// The dot products of the directional lights that are linear in what the rasterizer
// interpolates, evaluated at the vertices (vtkPhongVS.glsl, Dots): n.L_i, with n the normal
// before normalization, and P.L_i, with P the position in view coordinates. Interpolated
// with the same weights as n and P, they are n.L_i and P.L_i at the fragment, so
// N.L_i = s * n.L_i (N = s*n) and L_i.V = -P.L_i / |P| without the directions' uniform reads
// and dot products per fragment. Four lights per vec4.
in vec4 phongDirectionalNormalDotLVSOutput[@DIRECTIONAL_VEC4_COUNT@];
//PHONG_IF !PARALLEL
in vec4 phongDirectionalPositionDotLVSOutput[@DIRECTIONAL_VEC4_COUNT@];
//PHONG_ENDIF
// Set by the fragment's main (vtkPhongFS.glsl) once the shading normal N is known:
// N = phongInterpolatedNormalScale * n + phongViewWeight * V, one of the two weights 0.
float phongInterpolatedNormalScale = 0.0; // set in main; initialized so that no compiler warns
float phongViewWeight = 0.0;
//PHONG_IF !PARALLEL
float phongMinusInverseDistance = 0.0; // -1/|P|
//PHONG_ENDIF
//PHONG_ENDIF

//PHONG_IF POINT
const int phongPointLightCount = @POINT_COUNT@;
uniform vec3 phongPointLightPositionVC[@POINT_COUNT@];
//PHONG_IF POINT_ATTENUATION
uniform vec3 phongPointLightAttenuation[@POINT_COUNT@]; // (c, l, q)
//PHONG_ENDIF
//PHONG_IF POSITIONAL_AMBIENT
uniform vec3 phongPointLightAmbient[@POINT_COUNT@]; // La_i*I_i
//PHONG_ENDIF
//PHONG_IF DIFFUSE
uniform vec3 phongPointLightDiffuse[@POINT_COUNT@];
//PHONG_ENDIF
//PHONG_IF SEPARATE_SPECULAR_COLORS
uniform vec3 phongPointLightSpecular[@POINT_COUNT@];
//PHONG_ENDIF
//PHONG_ENDIF

//PHONG_IF SPOT
const int phongSpotLightCount = @SPOT_COUNT@;
uniform vec3 phongSpotLightPositionVC[@SPOT_COUNT@];
//PHONG_IF SPOT_ATTENUATION
uniform vec3 phongSpotLightAttenuation[@SPOT_COUNT@]; // (c, l, q)
//PHONG_ENDIF
uniform vec3 phongSpotLightAxisVC[@SPOT_COUNT@]; // unit, from the light to its focal point
uniform float phongSpotLightCosCutoff[@SPOT_COUNT@]; // cos(cone angle)
//PHONG_IF SPOT_FALLOFF
uniform float phongSpotLightExponent[@SPOT_COUNT@];
//PHONG_ENDIF
//PHONG_IF SOFT_SPOT_EDGE
uniform float phongSpotLightCosInner[@SPOT_COUNT@]; // cos(cone angle - edge width)
//PHONG_ENDIF
//PHONG_IF POSITIONAL_AMBIENT
uniform vec3 phongSpotLightAmbient[@SPOT_COUNT@];
//PHONG_ENDIF
//PHONG_IF DIFFUSE
uniform vec3 phongSpotLightDiffuse[@SPOT_COUNT@];
//PHONG_ENDIF
//PHONG_IF SEPARATE_SPECULAR_COLORS
uniform vec3 phongSpotLightSpecular[@SPOT_COUNT@];
//PHONG_ENDIF
//PHONG_ENDIF

//PHONG_IF SHADOW_MAPS
// vtkShadowMapPass: its factor for each light of the renderer (copied from its
// factor<i> at the top of the lighting code), and where each light finds its own
// (vtkPhongShadowMaps.h).
float phongShadowFactors[@SHADOW_FACTOR_COUNT@];
//PHONG_IF DIRECTIONAL
uniform int phongDirectionalLightShadow[@DIRECTIONAL_COUNT@];
//PHONG_ENDIF
//PHONG_IF POINT
uniform int phongPointLightShadow[@POINT_COUNT@];
//PHONG_ENDIF
//PHONG_IF SPOT
uniform int phongSpotLightShadow[@SPOT_COUNT@];
//PHONG_ENDIF
//PHONG_ENDIF

//PHONG_IF ATTENUATION
// Distance attenuation 1/(c + l*d + q*d^2). The denominator is kept above
// 1e-20 so a light on the surface, or coefficients that vanish, stay finite.
// Lights with (c, l, q) = (1, 0, 0), VTK's default, need none of it.
float phongDistanceAttenuation(vec3 coefficients, float d)
{
  return 1.0 / max(coefficients.x + d * (coefficients.y + d * coefficients.z), 1.0e-20);
}
//PHONG_ENDIF

//PHONG_IF POSITIONAL
// Unit vector from the surface point to a positional light, and the distance.
// A light exactly at the point has no direction; it lights the point head-on.
vec3 phongToPositionalLight(vec3 lightPositionVC, vec3 positionVC, vec3 N, out float d)
{
  vec3 toLight = lightPositionVC - positionVC;
  d = length(toLight);
  return d > 0.0 ? toLight / d : N;
}
//PHONG_ENDIF

//PHONG_IF SPECULAR
// S_i*G_i for one light from its lobe: gated off for a light behind the surface. NdotL is
// N.L before clamping.
float phongGate(float lobe, float NdotL)
{
//PHONG_IF SMOOTH_TERMINATOR
  return lobe * max(NdotL, 0.0);
//PHONG_ENDIF
//PHONG_IF !SMOOTH_TERMINATOR
  // The gate opens a little above N.L = 0: a light in the surface's plane (a box face
  // along an axis-aligned light) has N.L = 0 up to rounding, and a gate at exactly 0 would
  // scatter highlights over the face at random (docs/results/extremes.md).
  return NdotL > 1.0e-4 ? lobe : 0.0;
//PHONG_ENDIF
}

//PHONG_IF WHOLE_SHININESS
// Under an error budget, x^n for the plan's whole shininess n by squaring: a product per bit
// of n where pow takes a logarithm and an exponential; its rounding is charged to the budget
// (vtkPhongErrorBudget::WholePowerError).
float phongWholePower(float x)
{
  float power = 1.0;
  @WHOLE_POWER_STEPS@
  return power;
}
//PHONG_ENDIF

// The same from the cosine of the lobe. Shininess 0 gives a lobe of 1 wherever the gate is
// open, which GLSL's pow(0, 0) leaves undefined. A float cosine near 1 resolves 6e-8, which
// costs the lobe n * 6e-8 of itself: nothing up to n = 1e3 (NARROW_LOBE above).
float phongGatedLobe(float cosine, float NdotL, float shininess)
{
//PHONG_IF WHOLE_SHININESS
  return phongGate(phongWholePower(clamp(cosine, 0.0, 1.0)), NdotL);
//PHONG_ENDIF
//PHONG_IF !WHOLE_SHININESS
  return phongGate(shininess > 0.0 ? pow(clamp(cosine, 0.0, 1.0), shininess) : 1.0, NdotL);
//PHONG_ENDIF
}
//PHONG_IF NARROW_LOBE

// The same from the difference of the two unit vectors whose cosine the lobe raises (R - V
// for Phong, N - H for Blinn), for shininess above 1e3: t = 1 - cos = |A - B|^2 / 2 keeps
// its relative precision where the cosine itself rounds to 1 (the vectors' length error
// only scales t by 1 +- 1e-7), and log(1 - t) goes by its series where 1 - t would round.
// From the cosine the n = 1e6 highlight was 19 % off (docs/results/extremes.md).
float phongGatedNarrowLobe(vec3 difference, float NdotL, float shininess)
{
  float t = 0.5 * dot(difference, difference);
  float logCosine = t < 1.0e-3 ? -t * (1.0 + t * (0.5 + t * (1.0 / 3.0))) : log(max(1.0 - t, 0.0));
  return phongGate(t >= 1.0 ? 0.0 : exp(shininess * logCosine), NdotL);
}
//PHONG_ENDIF

// S_i*G_i for one light with unit vectors N, L (to the light) and V (to the eye).
float phongSpecular(vec3 N, vec3 L, vec3 V, float NdotL, float shininess)
{
//PHONG_IF LOBE_PHONG
  // R = reflect(-L, N) = 2(N.L)N - L
//PHONG_IF !NARROW_LOBE
  return phongGatedLobe(dot(2.0 * NdotL * N - L, V), NdotL, shininess);
//PHONG_ENDIF
//PHONG_IF NARROW_LOBE
  return phongGatedNarrowLobe(2.0 * NdotL * N - L - V, NdotL, shininess);
//PHONG_ENDIF
//PHONG_ENDIF
//PHONG_IF LOBE_BLINN
  // H = normalize(L + V); L = -V has no halfway vector and no highlight.
  vec3 halfway = L + V;
  float halfwayLength = length(halfway);
//PHONG_IF !NARROW_LOBE
  return halfwayLength > 0.0 ? phongGatedLobe(dot(N, halfway) / halfwayLength, NdotL, shininess) : 0.0;
//PHONG_ENDIF
//PHONG_IF NARROW_LOBE
  return halfwayLength > 0.0 ? phongGatedNarrowLobe(N - halfway / halfwayLength, NdotL, shininess) : 0.0;
//PHONG_ENDIF
//PHONG_ENDIF
}
//PHONG_IF INTERPOLATED_DOTS

// The same Phong lobe from dot products alone: R.V = 2(N.L)(N.V) - L.V.
float phongSpecularFromDots(float NdotL, float twoNdotV, float LdotV, float shininess)
{
  return phongGatedLobe(NdotL * twoNdotV - LdotV, NdotL, shininess);
}
//PHONG_ENDIF
//PHONG_ENDIF

//PHONG_IF INTERPOLATED_DOTS
// L_i.V and N.L_i of directional light i from the interpolated dot products.
float phongDirectionalLdotV(int i)
{
//PHONG_IF PARALLEL
  return phongDirectionalLightToLightVC[i].z;
//PHONG_ENDIF
//PHONG_IF !PARALLEL
  return phongDirectionalPositionDotLVSOutput[i / 4][i % 4] * phongMinusInverseDistance;
//PHONG_ENDIF
}

float phongDirectionalNdotL(int i, float LdotV)
{
  return phongDirectionalNormalDotLVSOutput[i / 4][i % 4] * phongInterpolatedNormalScale +
    phongViewWeight * LdotV;
}
//PHONG_ENDIF
//PHONG_IF DIFFUSE_PER_FRAGMENT

// The directional lights' diffuse sum at a fragment with shading normal N (unit), while the
// other sums come from the vertices: interpolated, max(N.L, 0) would cost the terminator's
// kink (vtkPhongGouraudBound).
vec3 phongDirectionalDiffuse(vec3 N)
{
  vec3 diffuse = vec3(0.0);
  for (int i = 0; i < @DIRECTIONAL_COUNT@; ++i) // unrolled up to 64 lights (vtkPhongShaderTemplate)
  {
//PHONG_IF INTERPOLATED_DOTS
    float NdotL = phongDirectionalNdotL(i, phongDirectionalLdotV(i));
//PHONG_ENDIF
//PHONG_IF !INTERPOLATED_DOTS
    float NdotL = dot(N, phongDirectionalLightToLightVC[i]);
//PHONG_ENDIF
    diffuse += phongDirectionalLightDiffuse[i] * max(NdotL, 0.0);
  }
  return diffuse;
}
//PHONG_ENDIF

//PHONG_IF LIGHT_SUMS
// Sums the switched-on lights at a surface point with shading normal N (unit)
// and unit vector V towards the eye.
phongLightSums phongSumLights(vec3 positionVC, vec3 N, vec3 V, float shininess)
{
  phongLightSums sums;
//PHONG_IF POSITIONAL_AMBIENT
  sums.ambient = vec3(0.0);
//PHONG_ENDIF
//PHONG_IF DIFFUSE
  sums.diffuse = vec3(0.0);
//PHONG_ENDIF
//PHONG_IF SPECULAR
  sums.specular = vec3(0.0);
//PHONG_ENDIF

//PHONG_IF DIRECTIONAL
//PHONG_IF INTERPOLATED_DOTS
//PHONG_IF SPECULAR
  float twoNdotV = 2.0 * dot(N, V);
//PHONG_ENDIF
//PHONG_ENDIF
  for (int i = 0; i < @DIRECTIONAL_COUNT@; ++i) // unrolled up to 64 lights (vtkPhongShaderTemplate)
  {
//PHONG_IF !INTERPOLATED_DOTS
    vec3 L = phongDirectionalLightToLightVC[i];
    float NdotL = dot(N, L);
//PHONG_ENDIF
//PHONG_IF INTERPOLATED_DOTS
    float LdotV = phongDirectionalLdotV(i);
    float NdotL = phongDirectionalNdotL(i, LdotV);
//PHONG_ENDIF
//PHONG_IF SHADOW_MAPS
    float shadow = phongShadowFactors[phongDirectionalLightShadow[i]];
//PHONG_ENDIF
//PHONG_IF !SHADOW_MAPS
    const float shadow = 1.0;
//PHONG_ENDIF
//PHONG_IF DIFFUSE
    sums.diffuse += phongDirectionalLightDiffuse[i] * (shadow * max(NdotL, 0.0));
//PHONG_ENDIF
//PHONG_IF SPECULAR
//PHONG_IF !INTERPOLATED_DOTS
    float specular = shadow * phongSpecular(N, L, V, NdotL, shininess);
//PHONG_ENDIF
//PHONG_IF INTERPOLATED_DOTS
    float specular = shadow * phongSpecularFromDots(NdotL, twoNdotV, LdotV, shininess);
//PHONG_ENDIF
//PHONG_IF SEPARATE_SPECULAR_COLORS
    sums.specular += phongDirectionalLightSpecular[i] * specular;
//PHONG_ENDIF
//PHONG_IF !SEPARATE_SPECULAR_COLORS
    sums.specular += phongDirectionalLightDiffuse[i] * specular;
//PHONG_ENDIF
//PHONG_ENDIF
  }
//PHONG_ENDIF

//PHONG_IF POINT
  for (int i = 0; i < @POINT_COUNT@; ++i) // unrolled up to 64 lights (vtkPhongShaderTemplate)
  {
    float d;
    vec3 L = phongToPositionalLight(phongPointLightPositionVC[i], positionVC, N, d);
//PHONG_IF POINT_ATTENUATION
    float A = phongDistanceAttenuation(phongPointLightAttenuation[i], d);
//PHONG_ENDIF
//PHONG_IF !POINT_ATTENUATION
    float A = 1.0;
//PHONG_ENDIF
    float NdotL = dot(N, L);
//PHONG_IF POSITIONAL_AMBIENT
    sums.ambient += A * phongPointLightAmbient[i];
//PHONG_ENDIF
//PHONG_IF SHADOW_MAPS
    A *= phongShadowFactors[phongPointLightShadow[i]]; // the shadow dims diffuse and specular only
//PHONG_ENDIF
//PHONG_IF DIFFUSE
    sums.diffuse += (A * max(NdotL, 0.0)) * phongPointLightDiffuse[i];
//PHONG_ENDIF
//PHONG_IF SPECULAR
//PHONG_IF SEPARATE_SPECULAR_COLORS
    sums.specular += (A * phongSpecular(N, L, V, NdotL, shininess)) * phongPointLightSpecular[i];
//PHONG_ENDIF
//PHONG_IF !SEPARATE_SPECULAR_COLORS
    sums.specular += (A * phongSpecular(N, L, V, NdotL, shininess)) * phongPointLightDiffuse[i];
//PHONG_ENDIF
//PHONG_ENDIF
  }
//PHONG_ENDIF

//PHONG_IF SPOT
  for (int i = 0; i < @SPOT_COUNT@; ++i) // unrolled up to 64 lights (vtkPhongShaderTemplate)
  {
    float d;
    vec3 L = phongToPositionalLight(phongSpotLightPositionVC[i], positionVC, N, d);
    // cos_phi: between the spot axis and the direction from the light to the point
    float cosPhi = dot(-L, phongSpotLightAxisVC[i]);
//PHONG_IF SPOT_FALLOFF
    float spot = cosPhi >= phongSpotLightCosCutoff[i] ? pow(max(cosPhi, 0.0), phongSpotLightExponent[i]) : 0.0;
//PHONG_ENDIF
//PHONG_IF !SPOT_FALLOFF
    // exponent 1 (VTK's default); inside a cone below 90 degrees cos_phi > 0
    float spot = cosPhi >= phongSpotLightCosCutoff[i] ? cosPhi : 0.0;
//PHONG_ENDIF
//PHONG_IF SOFT_SPOT_EDGE
    spot *= smoothstep(phongSpotLightCosCutoff[i], phongSpotLightCosInner[i], cosPhi);
//PHONG_ENDIF
//PHONG_IF SPOT_ATTENUATION
    float A = spot * phongDistanceAttenuation(phongSpotLightAttenuation[i], d);
//PHONG_ENDIF
//PHONG_IF !SPOT_ATTENUATION
    float A = spot;
//PHONG_ENDIF
    float NdotL = dot(N, L);
//PHONG_IF POSITIONAL_AMBIENT
    sums.ambient += A * phongSpotLightAmbient[i];
//PHONG_ENDIF
//PHONG_IF SHADOW_MAPS
    A *= phongShadowFactors[phongSpotLightShadow[i]]; // the shadow dims diffuse and specular only
//PHONG_ENDIF
//PHONG_IF DIFFUSE
    sums.diffuse += (A * max(NdotL, 0.0)) * phongSpotLightDiffuse[i];
//PHONG_ENDIF
//PHONG_IF SPECULAR
//PHONG_IF SEPARATE_SPECULAR_COLORS
    sums.specular += (A * phongSpecular(N, L, V, NdotL, shininess)) * phongSpotLightSpecular[i];
//PHONG_ENDIF
//PHONG_IF !SEPARATE_SPECULAR_COLORS
    sums.specular += (A * phongSpecular(N, L, V, NdotL, shininess)) * phongSpotLightDiffuse[i];
//PHONG_ENDIF
//PHONG_ENDIF
  }
//PHONG_ENDIF

  return sums;
}
//PHONG_ENDIF
