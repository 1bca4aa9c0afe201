// Sun visibility from the orbit scene's shadow map (scenes/orbit/OrbitShadowMap.h renders it and fills the
// block). Multiply the sun's direct light by sunShadowVisibility(); image-based and fill light are left alone.
//
// Bindings: the depth texture on texture unit ORBIT_SHADOW_TEXTURE_UNIT and the OrbitSunShadow block on
// uniform-block binding ORBIT_SHADOW_BLOCK, both 7 unless the program is built with other values
// (ShadowMap::shaderDefines(unit, block) gives the defines), as ShadowMap::bind(unit, block) binds them.
//
// Filtering: a rotated Poisson disc of `samples` taps of `softness` texels radius, each tap a hardware
// 2x2 depth comparison (sampler2DShadow), i.e. percentage-closer filtering (Reeves, Salesin & Cook 1987).
// The disc's rotation is a hash (passes/common/noise.h.glsl) of the receiver's texel in a light-space grid
// fixed to the world, so it does not depend on the camera or the frame: a surface point keeps its rotation,
// and its visibility, while the camera moves.
//
// Bias (every term in scene units, set from texels on the CPU): the lookup point moves `normal` along the
// surface normal; the reference depth moves towards the sun by `constant + slope tan(theta)` (theta the
// angle between normal and sun, tan capped); and each tap's reference follows the receiver's plane, its
// depth gradient in light space taken from the normal (receiver-plane depth bias: Isidoro, "Shadow mapping:
// GPU-based tips and techniques", GDC 2006), so taps away from the centre do not cut into a sloped surface.
// The normal, not screen derivatives, gives the gradient, so the result does not depend on the camera.

#include "passes/common/noise.h.glsl"

#ifndef ORBIT_SHADOW_TEXTURE_UNIT
#define ORBIT_SHADOW_TEXTURE_UNIT 7
#endif
#ifndef ORBIT_SHADOW_BLOCK
#define ORBIT_SHADOW_BLOCK 7
#endif

layout(binding = ORBIT_SHADOW_TEXTURE_UNIT) uniform sampler2DShadow uOrbitSunShadowMap;

layout(std140, binding = ORBIT_SHADOW_BLOCK) uniform OrbitSunShadow {
    mat4 worldToShadow; // world -> (u, v, depth) in [0, 1]
    vec4 right;         // xyz: light x axis; w: texel size
    vec4 up;            // xyz: light y axis; w: 1 / depth range
    vec4 toSun;         // xyz: towards the sun; w: 1 enabled, 0 disabled
    vec4 bias;          // x: constant, y: normal, z: slope per tan; w: tan cap
    vec4 pcf;           // x: radius (texels), y: taps, z: 1 / resolution, w: resolution
    vec4 grid;          // xy: the map's lower-left texel in the world-fixed grid
    vec4 disc[16];      // Poisson disc, two points per vec4
} uOrbitShadow;

vec2 orbitShadowDiscPoint(int i) {
    vec4 pair = uOrbitShadow.disc[i >> 1];
    return (i & 1) == 0 ? pair.xy : pair.zw;
}

/// Sun visibility in [0, 1] of a surface point with (any-length) normal `worldNormal`.
float sunShadowVisibility(vec3 worldPos, vec3 worldNormal) {
    if (uOrbitShadow.toSun.w == 0.0) {
        return 1.0;
    }
    vec3 n = normalize(worldNormal);
    float cosTheta = dot(n, uOrbitShadow.toSun.xyz);
    float tanCap = uOrbitShadow.bias.w;
    float c = max(abs(cosTheta), 1.0 / tanCap);
    float tanTheta = min(sqrt(max(1.0 - c * c, 0.0)) / c, tanCap);

    vec3 lookup = worldPos + n * uOrbitShadow.bias.y;
    vec3 s = (uOrbitShadow.worldToShadow * vec4(lookup, 1.0)).xyz;
    float invRange = uOrbitShadow.up.w;
    float reference = s.z - (uOrbitShadow.bias.x + uOrbitShadow.bias.z * tanTheta) * invRange;
    // Depth change per scene unit along the light's x and y on the receiver's plane.
    vec2 nxy = vec2(dot(n, uOrbitShadow.right.xyz), dot(n, uOrbitShadow.up.xyz));
    vec2 gradient = nxy / max(cosTheta, max(length(nxy) / tanCap, 1e-4)) * invRange;

    float resolution = uOrbitShadow.pcf.w;
    ivec2 texel = ivec2(floor(s.xy * resolution + uOrbitShadow.grid.xy));
    float angle = 6.2831853 * hashUniform(texel, 0u, 0u);
    mat2 rotation = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));

    int taps = int(uOrbitShadow.pcf.y);
    float radius = uOrbitShadow.pcf.x;
    float texelSize = uOrbitShadow.right.w;
    float sum = 0.0;
    for (int i = 0; i < taps; ++i) {
        vec2 offset = rotation * orbitShadowDiscPoint(i) * radius; // texels
        float tapReference = reference + dot(offset * texelSize, gradient);
        sum += texture(uOrbitSunShadowMap,
                       vec3(s.xy + offset * uOrbitShadow.pcf.z, min(tapReference, 1.0)));
    }
    return sum / float(taps);
}
