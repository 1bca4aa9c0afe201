// One level of the GGX-prefiltered specular cube (photopic::orbit::Ibl): for each texel's direction n, with
// v = r = n (Karis 2013's assumption), the (n.l)-weighted mean of the environment over sampleCount
// GGX-importance-sampled directions, each read at the mip level whose texels cover the solid angle the
// sample stands for (filtered importance sampling, Colbert & Krivanek 2007; core/Ibl.h filteredSampleLod).
#include "orbit_ibl_sampling.h.glsl"
#include "orbit_pbr.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform samplerCube uEnvironment; // the environment cube with its full mip chain
layout(binding = 0, rgba16f) writeonly uniform imageCube uTarget;
uniform int uFaceSize;              // of the target level
uniform float uRoughness;
uniform int uSampleCount;
uniform float uSourceTexelSolidAngle; // of uEnvironment's level 0
uniform float uLodBias;
uniform float uSourceMaxLod;

void main() {
    ivec3 p = ivec3(gl_GlobalInvocationID);
    if (p.x >= uFaceSize || p.y >= uFaceSize) {
        return;
    }
    vec2 st = (vec2(p.xy) + 0.5) / float(uFaceSize) * 2.0 - 1.0;
    vec3 n = normalize(iblCubeDirection(p.z, st));
    float alpha = uRoughness * uRoughness;
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    uint count = uint(uSampleCount);
    for (uint i = 0u; i < count; ++i) {
        vec3 h = iblImportanceSampleGgx(iblHammersley(i, count), uRoughness, n);
        float NdotH = max(dot(n, h), 0.0);
        vec3 l = 2.0 * NdotH * h - n; // reflect(-v, h) with v = n, so v.h = n.h
        float NdotL = dot(n, l);
        if (NdotL <= 0.0) {
            continue;
        }
        // Density of l: D (n.h) / (4 v.h) = D / 4 here.
        float pdf = pbrGgxDistribution(NdotH, alpha) * 0.25;
        float omegaSample = 1.0 / (float(count) * pdf);
        float lod = max(0.0, 0.5 * log2(omegaSample / uSourceTexelSolidAngle) + uLodBias);
        sum += textureLod(uEnvironment, l, min(lod, uSourceMaxLod)).rgb * NdotL;
        weight += NdotL;
    }
    imageStore(uTarget, p, vec4(weight > 0.0 ? sum / weight : vec3(0.0), 1.0));
}
