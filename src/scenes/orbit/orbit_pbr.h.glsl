// The metallic-roughness BRDF of glTF 2.0 (specification, appendix B) and its image-based lighting: the one
// GLSL source of the orbit scene's shading, the twin of core/Brdf.h and core/Ibl.h (the CPU code the tests
// hold it to).
//
// References:
// - Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces" (GGX).
// - Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs" (Smith's
//   height-correlated visibility).
// - Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering" (Fresnel).
// - Karis 2013, "Real Shading in Unreal Engine 4" (alpha = roughness^2, the split-sum approximation).
// - Ramamoorthi & Hanrahan 2001, "An Efficient Representation for Irradiance Environment Maps" (SH9).
// - Lagarde & de Rousiers 2014, "Moving Frostbite to Physically Based Rendering 3.0", section 4.9.3 (the
//   dominant direction of the specular lobe, between the mirror direction and the normal).
//
// Conventions: world space, right-handed, +y up; n, v and l are unit vectors away from the surface (v to the
// viewer, l to the light). Colours are linear Rec.709. The IBL resources are bound by photopic::orbit::Ibl::
// bind() at the units and block binding that OrbitIbl.h's iblShaderDefines() injects.

#ifndef ORBIT_IBL_SPECULAR_BINDING
#error "orbit_pbr.h.glsl needs the defines of photopic::orbit::iblShaderDefines()"
#endif

#define ORBIT_PI 3.14159265358979
#define ORBIT_MIN_ROUGHNESS 0.045 // core/Brdf.h kMinRoughness: the narrowest lobe a point light evaluates
#define ORBIT_DIELECTRIC_F0 0.04  // core/Brdf.h kDielectricF0: index of refraction 1.5

// glTF's metallic-roughness inputs after texturing.
struct PbrMaterial {
    vec3 baseColor;  // linear RGB, [0, 1]
    float metallic;  // [0, 1]
    float roughness; // perceptual, [0, 1]; alpha = roughness^2
    float occlusion; // [0, 1], ambient occlusion: multiplies indirect (image-based) light only
    vec3 emissive;   // linear radiance added as is (not multiplied by any light or intensity)
};

// GGX normal distribution, alpha = roughness^2; 0 where n.h <= 0.
float pbrGgxDistribution(float NdotH, float alpha) {
    if (NdotH <= 0.0) {
        return 0.0;
    }
    float a2 = alpha * alpha;
    float c = min(NdotH, 1.0);
    float d = c * c * (a2 - 1.0) + 1.0;
    return a2 / (ORBIT_PI * d * d);
}

// Smith height-correlated masking-shadowing with 1 / (4 n.l n.v) folded in; 0 where n.l or n.v <= 0.
float pbrSmithVisibility(float NdotV, float NdotL, float alpha) {
    if (NdotV <= 0.0 || NdotL <= 0.0) {
        return 0.0;
    }
    float a2 = alpha * alpha;
    float ggxV = NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2);
    float ggxL = NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2);
    return 0.5 / (ggxV + ggxL);
}

// Schlick's weight of F90 = 1: F = F0 (1 - w) + w.
float pbrSchlickWeight(float VdotH) {
    float m = 1.0 - clamp(VdotH, 0.0, 1.0);
    float m2 = m * m;
    return m2 * m2 * m;
}

vec3 pbrSpecularF0(PbrMaterial m) {
    return mix(vec3(ORBIT_DIELECTRIC_F0), m.baseColor, m.metallic);
}

vec3 pbrDiffuseColor(PbrMaterial m) {
    return mix(m.baseColor, vec3(0.0), m.metallic);
}

// The BRDF, f = F D V + (1 - F) c_diff / pi (1/sr), at roughness max(roughness, ORBIT_MIN_ROUGHNESS); 0
// where n.l <= 0 or n.v <= 0. The twin of core/Brdf.h's brdf().
vec3 pbrBrdf(PbrMaterial m, vec3 n, vec3 v, vec3 l) {
    float NdotV = dot(n, v);
    float NdotL = dot(n, l);
    if (NdotV <= 0.0 || NdotL <= 0.0) {
        return vec3(0.0);
    }
    vec3 h = normalize(v + l);
    float roughness = max(m.roughness, ORBIT_MIN_ROUGHNESS);
    float alpha = roughness * roughness;
    vec3 f0 = pbrSpecularF0(m);
    vec3 f = f0 + (vec3(1.0) - f0) * pbrSchlickWeight(dot(v, h));
    float dv = pbrGgxDistribution(dot(n, h), alpha) * pbrSmithVisibility(NdotV, NdotL, alpha);
    return f * dv + (vec3(1.0) - f) * pbrDiffuseColor(m) / ORBIT_PI;
}

// Light reflected towards v by a light from direction l whose irradiance on a surface facing it is
// `radiance` (a sun's illuminance, or a point light's intensity / distance^2): f (n.l) E. Occlusion does not
// apply (shadowing of direct light is the shadow map's).
vec3 pbrDirect(PbrMaterial m, vec3 n, vec3 v, vec3 l, vec3 radiance) {
    return pbrBrdf(m, n, v, l) * max(dot(n, l), 0.0) * radiance;
}

// --- Image-based lighting (photopic::orbit::Ibl) ---

// The environment prefiltered with GGX lobes: level k holds roughness k / (levels - 1) (level 0 the mirror).
layout(binding = ORBIT_IBL_SPECULAR_BINDING) uniform samplerCube uIblSpecular;
// The split-sum table: texture(uIblLut, vec2(n.v, roughness)) = (A, B, W, 0) with the specular integral
// F0 A + B (Karis 2013) and W the diffuse lobe's Fresnel weight (core/Ibl.h diffuseSchlickWeight).
layout(binding = ORBIT_IBL_LUT_BINDING) uniform sampler2D uIblLut;
// OrbitIbl.h's GpuIblParameters.
layout(std140, binding = ORBIT_IBL_BLOCK_BINDING) uniform OrbitIblBlock {
    // Irradiance as nine spherical harmonics, already convolved with the clamped cosine and divided by pi:
    // the radiance a white Lambertian surface reflects is sum of uIblSh[i].rgb Y_i(n) (core/Ibl.h's order).
    vec4 uIblSh[9];
    vec4 uIblParams; // x: iblIntensity (multiplies all image-based light), y: the specular cube's last level
};

// The radiance a white Lambertian surface with normal n reflects: core/Ibl.h's shLambertRadiance.
vec3 pbrIblDiffuseRadiance(vec3 n) {
    vec3 e = uIblSh[0].rgb * 0.28209479;
    e += uIblSh[1].rgb * (0.48860251 * n.y);
    e += uIblSh[2].rgb * (0.48860251 * n.z);
    e += uIblSh[3].rgb * (0.48860251 * n.x);
    e += uIblSh[4].rgb * (1.09254843 * n.x * n.y);
    e += uIblSh[5].rgb * (1.09254843 * n.y * n.z);
    e += uIblSh[6].rgb * (0.31539157 * (3.0 * n.z * n.z - 1.0));
    e += uIblSh[7].rgb * (1.09254843 * n.x * n.z);
    e += uIblSh[8].rgb * (0.54627422 * (n.x * n.x - n.y * n.y));
    return max(e, vec3(0.0));
}

// The environment seen along r through a GGX lobe of the given roughness (the prefiltered cube, its level
// linear in roughness).
vec3 pbrIblSpecularRadiance(vec3 r, float roughness) {
    return textureLod(uIblSpecular, r, clamp(roughness, 0.0, 1.0) * uIblParams.y).rgb;
}

// (A, B, W) of the split-sum table at n.v and roughness.
vec3 pbrIblLut(float NdotV, float roughness) {
    return texture(uIblLut, vec2(NdotV, roughness)).rgb;
}

// Where the prefiltered cube is read for a lobe of this roughness: the mirror direction for a smooth surface,
// bending towards the normal as it roughens, since the BRDF's (n.l) and visibility pull a wide lobe off the
// mirror direction (Lagarde & de Rousiers 2014's fit in alpha = roughness^2; at roughness 1 the normal).
vec3 pbrIblDominantDirection(vec3 n, vec3 r, float roughness) {
    float alpha = roughness * roughness;
    float s = clamp(1.0 - alpha, 0.0, 1.0);
    float blend = s * (sqrt(s) + alpha);
    vec3 d = mix(n, r, blend);
    // A view from behind the surface (a normal map can give one) can cancel the two; never a NaN.
    return dot(d, d) > 1e-12 ? normalize(d) : n;
}

// Image-based light reflected towards v: the split-sum specular (prefiltered radiance along the lobe's
// dominant direction times F0 A + B) plus the diffuse lobe from SH9 irradiance, weighted by (1 - F0) (1 - W) as the
// BRDF's (1 - F) weighs it under uniform light; times occlusion and iblIntensity. Emission is not included.
vec3 pbrIbl(PbrMaterial m, vec3 n, vec3 v) {
    float NdotV = clamp(dot(n, v), 1e-4, 1.0);
    vec3 r = pbrIblDominantDirection(n, reflect(-v, n), m.roughness);
    vec3 lut = pbrIblLut(NdotV, m.roughness);
    vec3 f0 = pbrSpecularF0(m);
    vec3 specular = (f0 * lut.x + lut.y) * pbrIblSpecularRadiance(r, m.roughness);
    vec3 diffuse = pbrDiffuseColor(m) * (vec3(1.0) - f0) * (1.0 - lut.z) * pbrIblDiffuseRadiance(n);
    return (specular + diffuse) * (m.occlusion * uIblParams.x);
}
