// GTAO's horizon search and analytic integral (Jimenez et al. 2016, "Practical Real-Time Strategies for
// Accurate Indirect Occlusion", section 4 and eq. 10), one invocation per AO texel. Output: the raw,
// cosine-weighted visibility in [0, 1], noisy (a few slices per pixel), packed with the surface it was
// computed at (packAoTexel); gtao_denoise.comp.glsl filters it.
#include "passes/gtao/gtao_common.h.glsl"
#include "passes/gtao/gtao_surface.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

// The preset's slices and steps a side and the resolution (full-resolution pixels per AO texel) are defines,
// a program per preset and resolution, so that the loops unroll and their constants fold.
const int kSlices = GTAO_SLICES;
const int kSteps = GTAO_STEPS;
const int kScale = GTAO_SCALE;

layout(binding = 0, rg32ui) uniform writeonly uimage2D uRaw;

const float kPi = 3.14159265358979;
// The thickness heuristic of Jimenez et al. 2016: a sample within the radius but below the horizon found so
// far pulls the horizon this far towards itself. Depth has no thickness, so a thin pole or wire in front of
// the point reads as a wall; the ground seen past it, below the horizon it set, says otherwise. Partial,
// because past the top of a solid box the samples fall below its horizon as well.
const float kThickness = 0.3;
#if GTAO_SAMPLE_MIPS
// A step `offset` pixels from the centre reads level round(log2(offset) - 3.3) = floor(log2(offset * 2^-2.8))
// of the surface pyramid.
const float kMipScale = 0.14358729; // 2^-2.8
#endif

// The slice angles' noise: interleaved gradient noise (Jimenez 2014, "Next Generation Post Processing in Call
// of Duty: Advanced Warfare"), which spreads its values evenly over every 3 x 3 neighbourhood the denoiser
// averages, shifted per frame so a temporal filter sees other slice angles each frame.
float interleavedGradientNoise(vec2 p, uint frame) {
    p += 5.588238 * float(frame % 64u);
    return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715))));
}

// The step positions' noise from the slice angle's u: 4u modulo 1. Over a 3 x 3 neighbourhood u takes values
// near k/9 + c (k = 0..8), so the nine (slice, step) pairs lie near the rank-1 lattice (k/9, 4k/9) modulo 1,
// spread over the whole square, one in each ninth of either axis. Step noise that differs from u by about a
// constant (interleaved gradient noise at an offset) puts the nine pairs on one line instead: a neighbourhood's
// slices and steps land on an occluder together or miss it together, and open ground near objects shows
// hard-edged bands.
float stepNoiseFrom(float sliceNoise) { return fract(4.0 * sliceNoise + 0.5); }

// Coordinates within a slice: the slice plane holds the view vector v and the screen direction; e is that
// direction made perpendicular to v. A point x relative to the origin is (dot(x, e), dot(x, v)), and its
// horizon cosine is the second coordinate over its length.
struct SliceFrame {
    vec3 e;
    vec3 v;
};

// A sample's surface continued along its tangent plane within the slice: the surface may cross the radius
// between two samples (a plane seen at a grazing angle, whose part within the radius is narrower than a
// pixel: the ground at the foot of a wall). The plane is cut with the slice plane itself, not followed from
// the sample: a sample sits up to half a texel off the slice, and on a plane seen edge-on (the ground far
// away) a line through it, parallel to the slice, passes beside the centre and reads as a steep horizon on
// the wrong side of the centre's own tangent plane. In slice coordinates the trace is the line
// dot(m, x) = c, m the normal's slice coordinates and c = dot(delta, n); it meets the radius at
// x0 +- sqrt(R^2 m.m - c^2) perp(m) / m.m with x0 = m c / m.m. Returns the point of the trace's part
// within the radius on side `sign` (+1: along +e) with the highest second coordinate, or (0, -R).
// Only planes the origin lies in front of count (c <= 0: a surface behind the point cannot reach it).
vec2 planeHorizon(vec3 delta, vec3 sampleNormal, SliceFrame f, float sign) {
    vec2 none = vec2(0.0, -uRadius);
    float c = dot(delta, sampleNormal);
    vec2 m = vec2(dot(sampleNormal, f.e), dot(sampleNormal, f.v));
    float m2 = dot(m, m);
    float disc = uRadius * uRadius * m2 - c * c;
    float inv = 1.0 / max(m2, 1e-9);
    vec2 x0 = m * (c * inv);
    vec2 d = vec2(-m.y, m.x) * (sqrt(max(disc, 0.0)) * inv);
    vec2 a = x0 + d;
    vec2 b = x0 - d;
    a = sign * a.x > 0.0 ? a : none;
    b = sign * b.x > 0.0 ? b : none;
    vec2 best = a.y >= b.y ? a : b;
    return c <= 0.0 && m2 > 1e-9 && disc > 0.0 ? best : none;
}

// Whether the depth buffer allows a continued surface to reach `point` (view space): false where the visible
// surface at its pixel lies behind the point by more than a twentieth of the radius (the continued surface
// would hide it) or where the sky shows. A tangent plane continued past its surface's edge fails it (a
// sphere's lower tangent plane, which rises in front of the sphere over the ground at its foot); the ground
// continued to the foot of a wall passes (it lies on the ground the pixels there show).
bool depthAgrees(vec3 point) {
    // Clip x, y and w by the projection's rows, with the zeros viewPositionAtTexel's form assumes (no shear).
    vec3 clip = vec3(uProjection[0][0] * point.x + uProjection[2][0] * point.z + uProjection[3][0],
                     uProjection[1][1] * point.y + uProjection[2][1] * point.z + uProjection[3][1],
                     uProjection[2][3] * point.z + uProjection[3][3]);
    ivec2 full = ivec2(uFullSize);
    ivec2 texel = ivec2(floor((clip.xy / clip.z * 0.5 + 0.5) * uFullSize));
    bool unknown = !(clip.z > 0.0) || any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, full));
    GtaoSurface s = surfaceAt(clamp(texel, ivec2(0), full - 1));
    vec3 visible = viewPositionAtTexel(texel, s.z);
    return unknown || (isSurface(s.z) && dot(point - visible, s.n) <= 0.05 * uRadius * length(s.n));
}

// The highest horizon cosine on one side of a slice (sign +1: along +omega), starting from `low` (the
// tangent plane's): the samples' own cosines within the radius, with the thickness heuristic, and the best
// tangent-plane continuation of any sample, checked against the depth buffer once.
float sideHorizon(vec2 centre, vec2 omega, float sign, vec3 origin, SliceFrame f, float low, float radiusPixels,
                  float jitter) {
    ivec2 full = ivec2(uFullSize);
    float radius2 = uRadius * uRadius;
    float best = low;
    vec2 plane = vec2(0.0, -uRadius);
    const float stepScale = 1.0 / float(kSteps);
    for (int s = 0; s < kSteps; ++s) {
        // Quadratic spacing: denser near the centre, where occluders subtend the largest angles.
        float t = (float(s) + jitter) * stepScale;
        float offset = mix(1.0, radiusPixels, t * t);
        ivec2 texel = ivec2(floor(centre + sign * omega * offset));
        bool inside = all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, full));
#if GTAO_SAMPLE_MIPS
        // The level whose cells are about a tenth of the step's distance (XeGTAO's rule: log2 of the offset
        // less 3.3, rounded; the floor of log2 read off the float's exponent), and the pixel its cell keeps:
        // a real surface point near the sample.
        int level = clamp((floatBitsToInt(offset * kMipScale) >> 23) - 127, 0, kSurfaceLevels);
        ivec2 cell = clamp(texel, ivec2(0), full - 1) >> level;
        uvec2 stored = imageLoad(uSurface, surfaceLevelOrigin(level, full) + cell).xy;
        texel = coarseTexelPixel(stored.x, cell, level);
        GtaoSurface hit = unpackSurface(stored);
#else
        GtaoSurface hit = surfaceAt(clamp(texel, ivec2(0), full - 1));
#endif
        vec3 delta = viewPositionAtTexel(texel, hit.z) - origin;
        float dist2 = dot(delta, delta);
        bool valid = inside && isSurface(hit.z) && dist2 >= 1e-12;
        float c = dot(delta, f.v) * inversesqrt(dist2);
        float moved = c > best ? c : mix(best, c, kThickness);
        best = valid && dist2 <= radius2 ? moved : best;
        vec2 candidate = planeHorizon(delta, hit.n, f, sign);
        plane = valid && candidate.y > plane.y ? candidate : plane;
    }
    float planeCos = plane.y / uRadius;
    bool agrees = depthAgrees(origin + plane.x * f.e + plane.y * f.v);
    best = planeCos > best && agrees ? planeCos : best;
    return max(best, low);
}

// The inner integral (eq. 10) of one side: the cosine-weighted visible arc between the view vector and the
// horizon at angle h = sign * acos(horizonCos), for a projected normal at angle n (cos n, sin n), written
// with cos(2h - n) = cos 2h cos n + sin 2h sin n so that only h itself takes an inverse cosine.
float visibleArc(float horizonCos, float sign, float cosN, float sinN) {
    float c = clamp(horizonCos, -1.0, 1.0);
    float h = sign * acos(c);
    float cos2h = 2.0 * c * c - 1.0;
    float sin2h = sign * 2.0 * c * sqrt(max(1.0 - c * c, 0.0));
    return 0.25 * (-(cos2h * cosN + sin2h * sinN) + cosN + 2.0 * h * sinN);
}

// The output texel: `visibility` beside the surface texel it was computed at.
void store(ivec2 q, uvec2 surfaceTexel, float visibility) {
    imageStore(uRaw, q, uvec4(packAoTexel(surfaceTexel.x, surfaceTexel.y, visibility), 0u, 0u));
}

void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uRaw);
    if (any(greaterThanEqual(q, size))) {
        return;
    }
    ivec2 p = aoSourcePixelAt(q, ivec2(uFullSize), kScale);
    uvec2 centreTexel = imageLoad(uSurface, p).xy;
    GtaoSurface surface = unpackSurface(centreTexel);
    if (!isSurface(surface.z)) {
        store(q, centreTexel, 1.0);
        return;
    }
    vec2 centre = vec2(p) + 0.5;
    vec3 position = viewPositionAtTexel(p, surface.z);
    vec3 normal = normalize(surface.n);
    vec3 viewVec = normalize(-position);
    vec3 origin = position + uBias * normal;

    // The radius in pixels at this depth: clip w is the view depth for a perspective projection, 1 for an
    // orthographic one.
    float clipW = uProjection[2][3] * position.z + uProjection[3][3];
    float radiusPixels = uRadius * 0.5 * uFullSize.y * uProjection[1][1] / max(clipW, 1e-6);
    if (radiusPixels < 1.0) {
        store(q, centreTexel, 1.0); // no texel lies within the radius
        return;
    }

    float sliceNoise = interleavedGradientNoise(vec2(p), uFrame);
    float stepNoise = stepNoiseFrom(sliceNoise);
    float visibility = 0.0;
    for (int slice = 0; slice < kSlices; ++slice) {
        float phi = (float(slice) + sliceNoise) * kPi / float(kSlices);
        vec2 omega = vec2(cos(phi), sin(phi)); // screen direction, pixels (y up, as view space)
        vec3 direction = vec3(omega, 0.0);
        SliceFrame f = SliceFrame(normalize(direction - dot(direction, viewVec) * viewVec), viewVec);

        // The normal projected into the slice plane: its length weighs the slice, its angle n from the view
        // vector (towards +e) bounds the hemisphere: the horizons lie no lower than the tangent plane, whose
        // cosines are cos(n +- pi/2) = -+ sin n.
        vec2 projected = vec2(dot(normal, f.e), dot(normal, f.v));
        float projectedLength = length(projected);
        float sinN = projected.x / max(projectedLength, 1e-4);
        float cosN = projected.y / max(projectedLength, 1e-4);
        float jitter = fract(stepNoise + 0.618034 * float(slice));
        float jitterBack = fract(jitter + 0.5);
        float cos0 = sideHorizon(centre, omega, 1.0, origin, f, -sinN, radiusPixels, jitter);
        float cos1 = sideHorizon(centre, omega, -1.0, origin, f, sinN, radiusPixels, jitterBack);
        float arcs = visibleArc(cos0, 1.0, cosN, sinN) + visibleArc(cos1, -1.0, cosN, sinN);
        visibility += projectedLength < 1e-4 ? 0.0 : projectedLength * arcs;
    }
    visibility = clamp(visibility / float(kSlices), 0.0, 1.0);
    store(q, centreTexel, visibility);
}
