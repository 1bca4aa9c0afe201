// Evaluates orbit_pbr.h.glsl's image-based lighting at a list of points (photopic::orbit::iblProbe): what the
// tests compare with the CPU twins, one query per invocation.
#include "orbit_pbr.h.glsl"

layout(local_size_x = 64) in;

#define IBL_PROBE_SHADE 0    // pbrIbl(material, n, v)
#define IBL_PROBE_DIFFUSE 1  // pbrIblDiffuseRadiance(n)
#define IBL_PROBE_LUT 2      // pbrIblLut(view.x, view.y)
#define IBL_PROBE_SPECULAR 3 // the specular cube along n at level view.w
#define IBL_PROBE_DIRECT 4   // pbrDirect(material, n, v, l = light.xyz, radiance = light.w)

// OrbitIbl.h's GpuIblProbeQuery.
struct IblProbeQuery {
    vec4 normalMode;        // xyz: n, w: IBL_PROBE_*
    vec4 view;              // xyz: v, w: level (IBL_PROBE_SPECULAR)
    vec4 baseColorMetallic; // rgb: base colour, w: metallic
    vec4 surface;           // x: roughness, y: occlusion
    vec4 light;             // xyz: l, w: irradiance (IBL_PROBE_DIRECT)
};

layout(std430, binding = 0) readonly buffer IblProbeQueries {
    IblProbeQuery uQueries[];
};
layout(std430, binding = 1) writeonly buffer IblProbeResults {
    vec4 uResults[];
};
uniform uint uCount;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uCount) {
        return;
    }
    IblProbeQuery q = uQueries[i];
    PbrMaterial m;
    m.baseColor = q.baseColorMetallic.rgb;
    m.metallic = q.baseColorMetallic.w;
    m.roughness = q.surface.x;
    m.occlusion = q.surface.y;
    m.emissive = vec3(0.0);
    int mode = int(q.normalMode.w);
    vec3 n = q.normalMode.xyz;
    vec3 result = vec3(0.0);
    if (mode == IBL_PROBE_SHADE) {
        result = pbrIbl(m, n, q.view.xyz);
    } else if (mode == IBL_PROBE_DIFFUSE) {
        result = pbrIblDiffuseRadiance(n);
    } else if (mode == IBL_PROBE_LUT) {
        result = pbrIblLut(q.view.x, q.view.y);
    } else if (mode == IBL_PROBE_SPECULAR) {
        result = textureLod(uIblSpecular, n, q.view.w).rgb;
    } else if (mode == IBL_PROBE_DIRECT) {
        result = pbrDirect(m, n, q.view.xyz, q.light.xyz, vec3(q.light.w));
    }
    uResults[i] = vec4(result, 1.0);
}
