// The orbit scene's material shader: glTF metallic-roughness with base-colour, metal-rough, normal,
// occlusion and emissive textures (colour textures are GL_SRGB8_ALPHA8, decoded by the sampler; data
// textures linear), shaded by orbit_pbr.h.glsl: the sun (its illuminance, the planet's occlusion of the
// disc, the ship's shadow map and the lighting stage's contact shadows: direct light only), the amb and
// hemi fills and the image-based light (the material's occlusion and the lighting stage's ambient
// occlusion: indirect light only; uEnv.x, the material's stored baseline, times the global intensity in
// OrbitIblBlock).
#include "orbit_pbr.h.glsl"
#include "orbit_frame.h.glsl"
#include "orbit_draw.h.glsl"
#include "orbit_shadow.h.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vTexCoord;
in vec4 vClipNow;
in vec4 vClipBefore;

layout(binding = 0) uniform sampler2D uBaseColorTexture;  // sRGB
layout(binding = 1) uniform sampler2D uMetalRoughTexture; // linear: G roughness, B metallic
layout(binding = 2) uniform sampler2D uNormalTexture;     // linear, tangent space
layout(binding = 3) uniform sampler2D uOcclusionTexture;  // linear, R
layout(binding = 4) uniform sampler2D uEmissiveTexture;   // sRGB
layout(binding = 5) uniform sampler2D uAmbientOcclusion;  // lighting stage: R visibility of indirect light
layout(binding = 6) uniform sampler2D uContactShadows;    // lighting stage: R visibility of the sun

layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oNormal;
layout(location = 2) out vec2 oMotion;
layout(location = 3) out uint oObjectId;
layout(location = 4) out vec4 oMaterial; // rgb: specular weight F0, a: roughness

vec3 shadingNormal(vec3 ng) {
    if (uSurface.z == 0.0 || vTangent.w == 0.0) {
        return ng;
    }
    vec3 t = vTangent.xyz - ng * dot(ng, vTangent.xyz);
    if (dot(t, t) < 1e-12) {
        return ng;
    }
    t = normalize(t);
    vec3 b = cross(ng, t) * (vTangent.w < 0.0 ? -1.0 : 1.0);
    vec3 m = texture(uNormalTexture, vTexCoord).xyz * 2.0 - 1.0;
    m.xy *= uSurface.z;
    return normalize(t * m.x + b * m.y + ng * max(m.z, 1e-3));
}

void main() {
    vec4 base = uBaseColorFactor * texture(uBaseColorTexture, vTexCoord);
    if (uEmissiveFactor.w > 0.0 && base.a < uEmissiveFactor.w) {
        discard;
    }
    vec4 mr = texture(uMetalRoughTexture, vTexCoord);
    float metallic = clamp(uSurface.x * mr.b, 0.0, 1.0);
    float roughness = clamp(uSurface.y * mr.g, 0.03, 1.0);
    float occlusion = 1.0 + uSurface.w * (texture(uOcclusionTexture, vTexCoord).r - 1.0);
    vec3 emissive = uEmissiveFactor.rgb * texture(uEmissiveTexture, vTexCoord).rgb;

    vec3 ng = normalize(vNormal);
    if (!gl_FrontFacing) {
        ng = -ng; // double-sided: the back face's normal faces the viewer
    }
    vec3 n = shadingNormal(ng);
    vec3 v = normalize(uCameraPos.xyz - vWorld);
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float sunVisibility = orbitSunVisibility(uEarth, vWorld) * orbitSunVisibility(uMars, vWorld);
    if (uFlags.y != 0) {
        sunVisibility *= texelFetch(uContactShadows, pixel, 0).r;
    }
    if (uFlags.z != 0) {
        sunVisibility *= sunShadowVisibility(vWorld, ng);
    }
    float indirectVisibility = occlusion;
    if (uFlags.x != 0) {
        indirectVisibility *= pow(texelFetch(uAmbientOcclusion, pixel, 0).r, uAoPower.x);
    }
    PbrMaterial material = PbrMaterial(base.rgb, metallic, roughness, indirectVisibility, emissive);
    vec3 direct = pbrDirect(material, n, v, uSunDirection.xyz, uSunIlluminance.rgb * sunVisibility);
    float up = 0.5 + 0.5 * dot(n, uHemiUp.xyz);
    vec3 fill = pbrDiffuseColor(material) * (uAmbient.rgb + mix(uHemiGround.rgb, uHemiSky.rgb, up)) / ORBIT_PI;
    vec3 ibl = uEnv.x * pbrIbl(material, n, v);
    oColor = vec4(direct + fill * indirectVisibility + ibl + emissive, 1.0);
    oNormal = vec4(normalize(mat3(uView) * n), 0.0);
    oMotion = 0.5 * (vClipNow.xy / vClipNow.w - vClipBefore.xy / vClipBefore.w);
    oObjectId = uint(uEnv.y);
    oMaterial = vec4(pbrSpecularF0(material), roughness);
}
