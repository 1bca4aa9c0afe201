// Screen-space reflection rays, marched through the min-max depth pyramid (hierarchical Z: Uludag, "Hi-Z
// Screen-Space Cone-Traced Reflections", GPU Pro 5, 2014; the segment set-up and its clipping follow McGuire
// & Mara, "Efficient GPU Screen-Space Ray Tracing", JCGT 2014).
//
// The mirror ray from each pixel's point is clipped to maxDistance and the near plane, projected, and walked
// in window space with t in [0, 1] along the projected segment. 1/w and (view depth)/w are affine in t, so
// the ray's linear depth at any t is exact. A cell of level L (2^L pixels a side) whose nearest depth lies
// behind the ray's span over the cell, or whose farthest depth lies in front of it by more than the
// thickness (the ray passes behind every surface there), cannot be hit there: the ray skips the cell and
// climbs a level; otherwise it moves to where it reaches the nearest depth and descends. At level 0 the ray
// hits the pixel's surface when its span over the pixel overlaps [depth, depth + thickness], the surface
// faces it (a surface seen from behind, the reflector itself among them, is passed) and, where the surface
// ends at that pixel (a silhouette), the ray meets it within a quarter pixel of the pixel's centre. Out: the
// hit's window position, its confidence (0: no hit; faded at the image's border, for surfaces seen edge-on
// and towards the roughness cut-off) and the radius in pixels of the glossy cone at the hit.
//
// What it leaves to no implementation's choice: every texel read is at lod 0 and in range; no value is
// divided by zero or by a component that may be a denormal; the march steps from a cell to its neighbour
// by index, so rounding (fused multiply-adds or not) never selects the cell just left or skips one; min,
// max and clamp never see a NaN, nor clamp a min above its max.
//
// The program built with REFINE is the second pass at half resolution (see its main).
#include "passes/ssr/ssr_common.h.glsl"
#include "passes/ssr/ssr_pyramid.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1) uniform sampler2D uNormalTexture;
layout(binding = 2) uniform sampler2D uMaterial; // RGB F0, A roughness, when uHasMaterial != 0
// Read texel by texel as images (a load skips the sampler's level and filtering logic).
layout(binding = 3, r32f) uniform readonly image2D uLinearDepth; // +inf: sky
// Nearest and farthest depth a cell, every level in one (ssr_pyramid.h.glsl).
layout(binding = 1, rg32f) uniform readonly image2D uPyramid;
layout(binding = 2, rgba32f) uniform readonly image2D uBlockHits; // REFINE: the blocks' hits (half resolution)
layout(binding = 0, rgba32f) uniform writeonly image2D uHits;

#include "passes/common/depth_neighbours.h.glsl"

// The unit view-space normal at pixel p (facing the camera), or zero when there is none to trust. Where
// the normals come from is the define SSR_NORMALS (uNormals' values), not the uniform: the program is
// built once per source, so a SIMD implementation that runs every side of a branch under a mask does not
// pay for the depth reconstruction when the host gives normals.
vec3 surfaceNormal(sampler2D normals, ivec2 p, vec3 centre, float z) {
#if SSR_NORMALS == 1
    vec3 n = texelFetch(normals, p, 0).xyz;
#elif SSR_NORMALS == 2
    vec3 n = octahedralDecode(texelFetch(normals, p, 0).rg);
#else
    vec3 dx, dy; // zero where there is no neighbouring depth to step to: no normal
    nearerNeighbourStep(p, ivec2(1, 0), centre, z, dx);
    nearerNeighbourStep(p, ivec2(0, 1), centre, z, dy);
    vec3 n = cross(dx, dy);
#endif
    float len2 = dot(n, n);
    if (!finitePositive(len2) || len2 <= 1e-12) { // NaN, zero, tiny or infinite
        return vec3(0.0);
    }
    n *= inversesqrt(len2);
    // Facing the camera: a reconstructed normal's sign is arbitrary; a host's may be flipped.
    return dot(n, centre) > 0.0 ? -n : n;
}

// The ray, in window space: s(t) = s0 + t d; linear depth(t) = (q0 + t dq) / (k0 + t dk), where k, 1/w,
// is positive over the whole segment (it ends in front of the near plane).
struct Ray {
    vec2 s0, d;
    float q0, dq, k0, dk;
};

// Whether the ray at t lies in front of linear depth z (+inf included), and whether it lies at most at z:
// depth(t) < z and depth(t) <= z without the division, since k(t) > 0.
bool inFront(Ray r, float t, float z) { return r.q0 + t * r.dq < z * (r.k0 + t * r.dk); }
bool reaches(Ray r, float t, float z) { return r.q0 + t * r.dq <= z * (r.k0 + t * r.dk); }

// Where the ray reaches linear depth z (finite; t may lie outside [0, 1]), or 1e30 where its depth does not
// change: never a division by zero (an infinity, or with 0 / 0 a NaN, which GLSL's min, max and clamp are
// not required to handle the same way everywhere).
float tAtDepth(Ray r, float z) {
    float rate = r.dq - z * r.dk;
    return abs(rate) > 1e-30 ? (z * r.k0 - r.q0) / rate : 1e30;
}

// A direction component of at most this many pixels over the whole segment never reaches a cell boundary
// (the segment starts at a pixel centre, half a pixel from any): it is not divided by, since a tiny or
// denormal divisor gives an infinity, or a NaN where the hardware flushes it to zero.
const float kStill = 1e-3;

// How far past a point on a cell boundary the cell ahead is looked up (pixels): well above the rounding
// error of a window position (under 1e-3 pixels up to 8192), and too small to matter to where a ray hits.
const float kNudge = 1.0 / 64.0;

// How far along its own ray on screen (pixels), either side of a neighbouring block's hit, a pixel looks
// for its hit at half resolution.
const float kRefineReach = 2.0;

// Where the ray's component (s0, d) crosses the line at b, or never (1e30).
float axisCrossing(float b, float s0, float d) { return abs(d) > kStill ? (b - s0) / d : 1e30; }

// Where the ray leaves the cell `cell` of a level whose cells are `size` pixels, and across which sides
// (both at a corner).
float cellExit(Ray r, ivec2 cell, float size, out bvec2 sides) {
    vec2 boundary = (vec2(cell) + vec2(greaterThan(r.d, vec2(0.0)))) * size;
    float tx = axisCrossing(boundary.x, r.s0.x, r.d.x);
    float ty = axisCrossing(boundary.y, r.s0.y, r.d.y);
    sides = bvec2(tx <= ty, ty <= tx);
    return min(tx, ty);
}

// Where the segment leaves the image [0, size] (1e30 when it never does).
float screenExit(Ray r, vec2 size) {
    vec2 boundary = mix(vec2(0.0), size, greaterThan(r.d, vec2(0.0)));
    return min(axisCrossing(boundary.x, r.s0.x, r.d.x), axisCrossing(boundary.y, r.s0.y, r.d.y));
}

// How far from a pixel's centre, towards a neighbour its surface does not continue into, a ray may meet the
// surface and hit it (pixels). The depth sample is the pixel centre's; at a silhouette the surface's edge
// lies somewhere between it and that neighbour, so past a quarter pixel the ray more likely passes beside
// the surface (a pole under a pixel wide, a wall's top edge) than over it: it goes on behind it instead.
const float kSilhouetteReach = 0.25;
// Inverse depths within this fraction of each other lie on one surface.
const float kContinuity = 0.05;

// Whether the surface seen at pixel c (linear depth zc) continues into its neighbour c + o (o a unit step):
// the neighbour's inverse depth is c's, or where the line through the opposite neighbour's and c's puts it
// (1/z is affine across a plane on screen: a floor seen at a grazing angle continues). Beyond the image's
// edge it is taken to continue; the sky is not the surface.
bool continuesInto(ivec2 c, ivec2 o, float zc) {
    ivec2 size = ivec2(uFullSize);
    ivec2 n = c + o;
    if (any(lessThan(n, ivec2(0))) || any(greaterThanEqual(n, size))) {
        return true;
    }
    float zn = imageLoad(uLinearDepth, n).r;
    if (!validDepth(zn)) {
        return false;
    }
    float zm = imageLoad(uLinearDepth, clamp(c - o, ivec2(0), size - 1)).r;
    float ic = 1.0 / zc;
    float tolerance = kContinuity * ic;
    return abs(1.0 / zn - ic) <= tolerance ||
           (validDepth(zm) && abs(1.0 / zn - 2.0 * ic + 1.0 / zm) <= tolerance);
}

// Whether a ray that meets the surface of pixel c at window position `meets` hits it (kSilhouetteReach).
bool withinSurface(ivec2 c, vec2 meets, float zc) {
    vec2 offset = meets - (vec2(c) + 0.5);
    ivec2 side = ivec2(greaterThan(offset, vec2(0.0))) * 2 - 1;
    return (abs(offset.x) <= kSilhouetteReach || continuesInto(c, ivec2(side.x, 0), zc)) &&
           (abs(offset.y) <= kSilhouetteReach || continuesInto(c, ivec2(0, side.y), zc));
}

vec2 toWindow(vec4 clip) { return (clip.xy / clip.w * 0.5 + 0.5) * uFullSize; }

float edgeFade(vec2 window) {
    vec2 border = min(window, uFullSize - window);
    return uEdgeFade > 0.0 ? clamp(min(border.x, border.y) / uEdgeFade, 0.0, 1.0) : 1.0;
}

// A pixel's mirror ray, with what the march and the hit need.
struct Mirror {
    Ray ray;
    vec3 r; // view-space direction
    float roughness;
    float roughnessFade;
    float tFirst;     // where the ray leaves the reflector's own pixel
    ivec2 firstCell;  // the pixel it enters there
    float tEnd;       // where it leaves the image, or ends (maxDistance, the near plane)
    ivec2 towards;    // the direction of its steps from cell to cell, per axis (0: it does not cross one)
};

// Sets up pixel p's mirror ray; false where p reflects nothing: the sky, a surface too rough, no normal,
// facing away, or a ray along the view axis (under a pixel on screen).
bool mirrorRay(ivec2 p, out Mirror m) {
    float z = imageLoad(uLinearDepth, p).r;
    if (!validDepth(z)) {
        return false;
    }
    m.roughness = 0.0;
    if (uHasMaterial != 0) {
        float a = texelFetch(uMaterial, p, 0).a;
        // +-0 is a mirror; NaN, negative and infinite values are rough: no reflection.
        m.roughness = finitePositive(a) ? min(a, 1.0) : (floatBitsToUint(a) & 0x7fffffffu) == 0u ? 0.0 : 1.0;
    }
    m.roughnessFade = uRoughnessCutoff >= 1.0 ? 1.0 : clamp((uRoughnessCutoff - m.roughness) / 0.1, 0.0, 1.0);
    vec3 origin = viewPositionAt(vec2(p) + 0.5, z);
    vec3 n = surfaceNormal(uNormalTexture, p, origin, z);
    vec3 v = viewDirectionAt(vec2(p) + 0.5);
    if (m.roughnessFade <= 0.0 || dot(n, n) == 0.0 || dot(n, v) >= 0.0) {
        return false;
    }
    m.r = reflect(v, n);

    // The segment: maxDistance long, ending just in front of the near plane when it comes towards the eye.
    float nearZ = uRayNear[0].z; // view z of the near plane (negative)
    float rayLength = uMaxDistance;
    if (m.r.z > 0.0) {
        rayLength = min(rayLength, (0.999 * nearZ - origin.z) / m.r.z);
    }
    if (!(rayLength > 0.0)) {
        return false;
    }
    vec4 c0 = uProjection * vec4(origin, 1.0);
    vec4 c1 = uProjection * vec4(origin + rayLength * m.r, 1.0);
    m.ray.k0 = 1.0 / c0.w;
    m.ray.dk = 1.0 / c1.w - m.ray.k0;
    m.ray.q0 = -origin.z * m.ray.k0;
    m.ray.dq = -(origin.z + rayLength * m.r.z) / c1.w - m.ray.q0;
    m.ray.s0 = toWindow(c0);
    m.ray.d = toWindow(c1) - m.ray.s0;
    if (!(max(abs(m.ray.d.x), abs(m.ray.d.y)) > 0.5)) {
        return false;
    }
    m.tEnd = min(1.0, screenExit(m.ray, uFullSize));
    // The march moves from cell to cell by index: the next cell is the neighbour across the side the ray
    // leaves by, not the cell a point nudged past the boundary falls in, so no rounding (fused or not) can
    // select the same cell again or skip one.
    m.towards = ivec2(greaterThan(m.ray.d, vec2(kStill))) - ivec2(lessThan(m.ray.d, vec2(-kStill)));
    bvec2 sides;
    m.tFirst = cellExit(m.ray, p, 1.0, sides);
    m.firstCell = p + ivec2(sides) * m.towards;
    return true;
}

// Where a march is: the cell (of level `level`) the ray is in from t, where it leaves it (tExit, across
// `sides`), the cell's nearest depth (at level 0 the pixel's), and the steps taken.
struct Walk {
    ivec2 cell;
    int level;
    float t;
    float tExit;
    bvec2 sides;
    float zCell;
    int steps;
};

// Walks w on from cell to cell up to tStop, climbing at most to level maxLevel, and stops at the next
// candidate: a pixel (level 0) whose depth the ray's span over it reaches within the thickness. False at
// the end of the stretch, off the pyramid or out of steps.
bool nextCandidate(Mirror m, inout Walk w, float tStop, int maxLevel) {
    Ray ray = m.ray;
    for (; w.steps < uMaxSteps && w.t < tStop; ++w.steps) {
        if (any(lessThan(w.cell, ivec2(0))) || any(greaterThanEqual(w.cell, uPyramidSize >> w.level))) {
            return false; // off the pyramid (the screen's edge, a rounding error before tEnd): a miss
        }
        // An exit a rounding error behind t (a cell the ray only grazes) is taken as t: never backwards,
        // and t <= tExit for the clamps (GLSL leaves clamp undefined for min > max).
        w.tExit = min(max(cellExit(ray, w.cell, float(1 << w.level), w.sides), w.t), tStop);
        vec2 bounds = imageLoad(uPyramid, pyramidLevelOrigin(uPyramidSize, w.level) + w.cell).rg;
        w.zCell = bounds.x;
        bool frontA = inFront(ray, w.t, w.zCell);
        // In front of every surface in the cell (the sky too), or behind every one by more than the thickness
        // (passing behind an object: without the farthest depth the walk would go on pixel by pixel there).
        float zBehind = bounds.y + uThickness;
        if ((frontA && inFront(ray, w.tExit, w.zCell)) ||
            (!reaches(ray, w.t, zBehind) && !reaches(ray, w.tExit, zBehind))) {
            w.t = w.tExit;
            w.cell += ivec2(w.sides) * m.towards;
            if (w.level < maxLevel) {
                ++w.level;
                w.cell >>= 1; // a cell off the pyramid stays negative and ends the walk above
            }
            continue;
        }
        if (w.level > 0) {
            if (frontA) { // it reaches the cell's nearest depth inside the cell
                w.t = clamp(tAtDepth(ray, w.zCell), w.t, w.tExit);
            }
            --w.level;
            // The one of the 2 x 2 cells below that the ray is in just after t: its point at t, moved kNudge
            // pixels on along each axis it moves on, so that at a boundary (t often is one: where the ray
            // left a cell and climbed) it is the cell ahead, never the one just left, which would be skipped
            // again, climbed from and descended into without end. The clamp keeps it to these four where t
            // is on the cell's own side.
            vec2 s = ray.s0 + w.t * ray.d + vec2(m.towards) * kNudge;
            w.cell = clamp(ivec2(floor(s / float(1 << w.level))), 2 * w.cell, 2 * w.cell + 1);
            continue;
        }
        // Level 0: a pixel of the image (the padding is sky, passed above) whose span of the ray overlaps
        // [depth, depth + thickness]: neither in front of the depth at both ends nor behind depth + thickness
        // at both (both passed above).
        if (all(lessThan(w.cell, ivec2(uFullSize)))) {
            ++w.steps;
            return true;
        }
        w.t = w.tExit;
        w.cell += ivec2(w.sides) * m.towards;
    }
    return false;
}

// Whether the candidate w is a hit: the surface faces the ray and the ray meets it within the surface
// (withinSurface). `hit`: its window position, confidence and cone radius.
bool isHit(Mirror m, Walk w, out vec4 hit) {
    vec3 hitPoint = viewPositionAt(vec2(w.cell) + 0.5, w.zCell);
    vec3 hitNormal = surfaceNormal(uNormalTexture, w.cell, hitPoint, w.zCell);
    // Where the ray meets the surface's depth in the pixel, or enters the pixel behind it.
    float tHit = clamp(tAtDepth(m.ray, w.zCell), w.t, w.tExit);
    vec2 window = clamp(m.ray.s0 + tHit * m.ray.d, vec2(0.0), uFullSize);
    float facing = -dot(hitNormal, m.r);
    // Surfaces met edge-on fade out. GGX's lobe widens with alpha = roughness^2; its tangent spread over the
    // ray's length on screen gives the cone's radius where the ray ends.
    hit = vec4(window, clamp(facing / 0.1, 0.0, 1.0) * edgeFade(window) * m.roughnessFade,
               m.roughness * m.roughness * tHit * length(m.ray.d));
    return facing > 0.0 && withinSurface(w.cell, window, w.zCell);
}

// The march along m's ray from `cell` (level 0) at t to tStop, climbing at most to level maxLevel: the hit
// (window position, confidence, cone radius), or 0 for a miss. nextCandidate only walks cells; the
// candidates are judged here, once each, and not (under a mask, on SIMD implementations that run both sides
// of a branch) at every step of the walk.
vec4 march(Mirror m, ivec2 cell, float t, float tStop, int maxLevel) {
    Walk w = Walk(cell, 0, t, t, bvec2(false), 0.0, 0);
    while (nextCandidate(m, w, tStop, maxLevel)) {
        vec4 hit;
        if (isHit(m, w, hit)) {
            return hit;
        }
        // At the surface's back, or beside its silhouette: go on behind it.
        w.t = w.tExit;
        w.cell += ivec2(w.sides) * m.towards;
    }
    return vec4(0.0);
}

// The pixel that traces for the 2 x 2 block `block` at half resolution.
ivec2 blockPixel(ivec2 block) { return min(2 * block, ivec2(uFullSize) - 1); }

#ifndef REFINE
// Every pixel, or at half resolution the first pixel of each 2 x 2 block (the block's hit).
void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(q, ivec2(uTraceSize)))) {
        return;
    }
    Mirror m;
    ivec2 p = uHalf != 0 ? blockPixel(q) : q;
    imageStore(uHits, q, mirrorRay(p, m) ? march(m, m.firstCell, m.tFirst, m.tEnd, uLevels - 1) : vec4(0.0));
}
#else
// REFINE (a program of its own: SIMD implementations that run both sides of a branch under a mask would
// otherwise pay for this path in the trace too): at half resolution, every pixel's hit from the blocks' hits.
// A block's own tracing pixel keeps its hit. Each other pixel marches its own ray over the stretch where it
// passes the hits of its block and of the next blocks right, up and diagonally (the blocks' rays around
// it), kRefineReach pixels longer at either end, and takes the first hit there.
void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(q, ivec2(uFullSize)))) {
        return;
    }
    ivec2 block = q / 2;
    vec4 hit = vec4(0.0);
    if (all(equal(q, blockPixel(block)))) {
        hit = imageLoad(uBlockHits, block);
    } else {
        vec4 seeds[4];
        bool seeded = false;
        for (int k = 0; k < 4; ++k) {
            seeds[k] = imageLoad(uBlockHits, min(block + ivec2(k & 1, k >> 1), ivec2(uTraceSize) - 1));
            seeded = seeded || seeds[k].z > 0.0;
        }
        // Where every block around missed, so does the pixel.
        Mirror m;
        if (seeded && mirrorRay(q, m)) {
            // Where the ray passes nearest each hit (t units along it).
            float tMin = 1e30;
            float tMax = -1e30;
            for (int k = 0; k < 4; ++k) {
                if (seeds[k].z > 0.0) {
                    float tNear = dot(seeds[k].xy - m.ray.s0, m.ray.d) / dot(m.ray.d, m.ray.d);
                    tMin = min(tMin, tNear);
                    tMax = max(tMax, tNear);
                }
            }
            float reach = kRefineReach / length(m.ray.d);
            float t = max(m.tFirst, tMin - reach);
            float tStop = min(m.tEnd, tMax + reach);
            if (t < tStop) {
                ivec2 cell = t > m.tFirst ? ivec2(floor(m.ray.s0 + t * m.ray.d)) : m.firstCell;
                hit = march(m, cell, t, tStop, uLevels - 1);
            }
        }
    }
    imageStore(uHits, q, hit);
}
#endif
