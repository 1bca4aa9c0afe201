// Screen-space reflection rays, marched through the min-depth pyramid (hierarchical Z: Uludag, "Hi-Z
// Screen-Space Cone-Traced Reflections", GPU Pro 5, 2014; the segment set-up and its clipping follow McGuire
// & Mara, "Efficient GPU Screen-Space Ray Tracing", JCGT 2014).
//
// The mirror ray from each pixel's point is clipped to maxDistance and the near plane, projected, and walked
// in window space with t in [0, 1] along the projected segment. 1/w and (view depth)/w are affine in t, so
// the ray's linear depth at any t is exact. A cell of level L (2^L pixels a side) whose nearest depth lies
// behind the ray's span over the cell cannot be hit there: the ray skips the cell and climbs a level;
// otherwise it moves to where it reaches that depth and descends. At level 0 the ray hits the pixel's
// surface when its span over the pixel overlaps [depth, depth + thickness] and the surface faces it (a
// surface seen from behind, the reflector itself among them, is passed). Out: the hit's window position, its
// confidence (0: no hit; faded at the image's border, for surfaces seen edge-on and towards the roughness
// cut-off) and the radius in pixels of the glossy cone at the hit.
#include "passes/ssr/ssr_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uLinearDepth; // R32F, +inf: sky
layout(binding = 1) uniform sampler2D uNormalTexture;
layout(binding = 2) uniform sampler2D uMaterial; // RGB F0, A roughness, when uHasMaterial != 0
layout(binding = 3) uniform sampler2D uPyramid;  // R32F min depth, uLevels levels
layout(binding = 0, rgba32f) uniform writeonly image2D uHits;

// The ray, in window space: s(t) = s0 + t d; linear depth(t) = (q0 + t dq) / (k0 + t dk).
struct Ray {
    vec2 s0, d;
    float q0, dq, k0, dk;
};

float depthAt(Ray r, float t) { return (r.q0 + t * r.dq) / (r.k0 + t * r.dk); }

// Where the ray reaches linear depth z (t may lie outside [0, 1]).
float tAtDepth(Ray r, float z) { return (z * r.k0 - r.q0) / (r.dq - z * r.dk); }

// Where the ray leaves the cell `cell` of size `cellSize` pixels (t units).
float cellExit(Ray r, ivec2 cell, float cellSize) {
    vec2 boundary = (vec2(cell) + step(vec2(0.0), r.d)) * cellSize;
    vec2 tt = (boundary - r.s0) / r.d; // a zero component of d gives +-inf or NaN: replaced below
    tt = mix(tt, vec2(1e30), equal(r.d, vec2(0.0)));
    return min(tt.x, tt.y);
}

// Where the segment leaves the image [0, size] (t units; 1e30 when it never does).
float screenExit(Ray r, vec2 size) {
    vec2 boundary = mix(vec2(0.0), size, step(vec2(0.0), r.d));
    vec2 tt = (boundary - r.s0) / r.d;
    tt = mix(tt, vec2(1e30), equal(r.d, vec2(0.0)));
    return min(tt.x, tt.y);
}

vec2 toWindow(vec4 clip) { return (clip.xy / clip.w * 0.5 + 0.5) * uFullSize; }

float edgeFade(vec2 window) {
    vec2 border = min(window, uFullSize - window);
    return uEdgeFade > 0.0 ? clamp(min(border.x, border.y) / uEdgeFade, 0.0, 1.0) : 1.0;
}

void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(q, ivec2(uTraceSize)))) {
        return;
    }
    ivec2 size = ivec2(uFullSize);
    ivec2 p = uHalf != 0 ? min(2 * q, size - 1) : q;
    vec4 miss = vec4(0.0);
    float z = texelFetch(uLinearDepth, p, 0).r;
    if (!validDepth(z)) {
        imageStore(uHits, q, miss);
        return;
    }
    float roughness = 0.0;
    if (uHasMaterial != 0) {
        roughness = texelFetch(uMaterial, p, 0).a;
        roughness = roughness >= 0.0 ? min(roughness, 1.0) : 1.0; // NaN: rough, no reflection
    }
    float roughnessFade = clamp((uRoughnessCutoff - roughness) / 0.1, 0.0, 1.0);
    if (uRoughnessCutoff >= 1.0) {
        roughnessFade = 1.0;
    }
    vec3 origin = viewPositionAt(vec2(p) + 0.5, z);
    vec3 n = surfaceNormal(uLinearDepth, uNormalTexture, p, origin, z);
    vec3 v = viewDirectionAt(vec2(p) + 0.5);
    if (roughnessFade <= 0.0 || dot(n, n) == 0.0 || dot(n, v) >= 0.0) {
        imageStore(uHits, q, miss);
        return;
    }
    vec3 r = reflect(v, n);

    // The segment: maxDistance long, ending just in front of the near plane when it comes towards the eye.
    float nearZ = uRayNear[0].z; // view z of the near plane (negative)
    float rayLength = uMaxDistance;
    if (r.z > 0.0) {
        rayLength = min(rayLength, (0.999 * nearZ - origin.z) / r.z);
    }
    if (!(rayLength > 0.0)) {
        imageStore(uHits, q, miss);
        return;
    }
    vec4 c0 = uProjection * vec4(origin, 1.0);
    vec4 c1 = uProjection * vec4(origin + rayLength * r, 1.0);
    Ray ray;
    ray.k0 = 1.0 / c0.w;
    ray.dk = 1.0 / c1.w - ray.k0;
    ray.q0 = -origin.z * ray.k0;
    ray.dq = -(origin.z + rayLength * r.z) / c1.w - ray.q0;
    ray.s0 = toWindow(c0);
    ray.d = toWindow(c1) - ray.s0;
    float pixels = max(abs(ray.d.x), abs(ray.d.y));
    if (!(pixels > 0.5)) { // the ray runs along the view axis: less than a pixel to march
        imageStore(uHits, q, miss);
        return;
    }
    float tEnd = min(1.0, screenExit(ray, uFullSize));
    float eps = 0.01 / pixels; // a hundredth of a pixel: steps off a cell boundary
    float t = cellExit(ray, ivec2(floor(ray.s0)), 1.0) + eps;
    int level = 0;
    for (int i = 0; i < uMaxSteps && t < tEnd; ++i) {
        vec2 s = ray.s0 + t * ray.d;
        float cellSize = float(1 << level);
        ivec2 cell = clamp(ivec2(floor(s / cellSize)), ivec2(0), textureSize(uPyramid, level) - 1);
        float tExit = min(cellExit(ray, cell, cellSize), tEnd);
        float zCell = texelFetch(uPyramid, cell, level).r;
        float zA = depthAt(ray, t);
        float zB = depthAt(ray, tExit);
        if (max(zA, zB) < zCell) { // in front of every surface in the cell
            t = tExit + eps;
            level = min(level + 1, uLevels - 1);
            continue;
        }
        if (level > 0) {
            if (zA < zCell) { // it reaches the cell's nearest depth inside the cell
                t = clamp(tAtDepth(ray, zCell), t, tExit);
            }
            --level;
            continue;
        }
        if (min(zA, zB) <= zCell + uThickness) {
            vec3 hitPoint = viewPositionAt(vec2(cell) + 0.5, zCell);
            vec3 hitNormal = surfaceNormal(uLinearDepth, uNormalTexture, cell, hitPoint, zCell);
            if (dot(hitNormal, r) < 0.0) {
                float tHit = clamp(tAtDepth(ray, zCell), t, tExit);
                float facing = clamp(-dot(hitNormal, r) / 0.1, 0.0, 1.0); // edge-on surfaces fade out
                vec2 window = clamp(ray.s0 + tHit * ray.d, vec2(0.0), uFullSize);
                float confidence = facing * edgeFade(window) * roughnessFade;
                // GGX's lobe widens with alpha = roughness^2; its tangent spread over the ray's length on
                // screen gives the cone's radius where the ray ends.
                float cone = roughness * roughness * tHit * length(ray.d);
                imageStore(uHits, q, vec4(window, confidence, cone));
                return;
            }
        }
        t = tExit + eps; // behind the surface by more than its thickness, or at its back: go on behind it
    }
    imageStore(uHits, q, miss);
}
