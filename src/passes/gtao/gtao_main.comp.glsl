// GTAO's horizon search and analytic integral (Jimenez et al. 2016, "Practical Real-Time Strategies for
// Accurate Indirect Occlusion", section 4 and eq. 10), one invocation per AO texel. Output: the raw,
// cosine-weighted visibility in [0, 1], noisy (a few slices per pixel); gtao_denoise.comp.glsl filters it.
#include "passes/gtao/gtao_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uLinearDepth; // R32F, +inf: sky
layout(binding = 1) uniform sampler2D uNormals;     // view space (or octahedral)
layout(binding = 0, r16f) uniform writeonly image2D uRaw;

const float kPi = 3.14159265358979;
const float kHalfPi = 1.57079632679490;
// The thickness heuristic of Jimenez et al. 2016: a sample within the radius but below the horizon found so
// far pulls the horizon this far towards itself. Depth has no thickness, so a thin pole or wire in front of
// the point reads as a wall; the ground seen past it, below the horizon it set, says otherwise. Partial,
// because past the top of a solid box the samples fall below its horizon as well.
const float kThickness = 0.3;

// Interleaved gradient noise (Jimenez 2014, "Next Generation Post Processing in Call of Duty: Advanced
// Warfare"), shifted per frame so a temporal filter sees other slice angles each frame.
float interleavedGradientNoise(vec2 p, uint frame) {
    p += 5.588238 * float(frame % 64u);
    return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715))));
}

vec3 viewNormalAt(ivec2 p) {
    vec4 t = texelFetch(uNormals, p, 0);
    return normalize(uOctahedral != 0 ? octahedralDecode(t.rg) : t.xyz);
}

// A sample's surface continued along its tangent plane within the slice: the surface may cross the radius
// between two samples (a plane seen at a grazing angle, whose part within the radius is narrower than a
// pixel: the ground at the foot of a wall). The plane is cut with the slice plane itself, not followed from
// the sample: a sample sits up to half a texel off the slice, and on a plane seen edge-on (the ground far
// away) a line through it, parallel to the slice, passes beside the centre and reads as a steep horizon on
// the wrong side of the centre's own tangent plane. Returns the highest cosine to the view vector of the
// trace's part within the radius on this side, or -1, and where that part meets the radius (view space) in
// `point`. Only planes the centre point lies in front of count (a surface behind the point cannot reach it).
float planeHorizon(vec3 hit, vec3 sampleNormal, vec3 origin, vec3 axis, vec3 sideVec, vec3 viewVec,
                   out vec3 point) {
    point = vec3(0.0);
    if (dot(origin - hit, sampleNormal) < 0.0) {
        return -1.0;
    }
    // The plane's trace on the slice plane: the points x (relative to origin) with dot(x, axis) = 0 and
    // dot(x - o, sampleNormal) = 0; m is the normal projected into the slice plane.
    vec3 o = hit - origin;
    vec3 m = sampleNormal - axis * dot(sampleNormal, axis);
    float m2 = dot(m, m);
    if (m2 < 1e-8) {
        return -1.0;
    }
    vec3 x0 = m * (dot(o, sampleNormal) / m2);
    vec3 d = normalize(cross(axis, sampleNormal));
    float disc = uRadius * uRadius - dot(x0, x0);
    if (disc <= 0.0) {
        return -1.0;
    }
    float best = -1.0;
    for (int k = 0; k < 2; ++k) {
        vec3 p = x0 + (k == 0 ? -1.0 : 1.0) * sqrt(disc) * d;
        float c = dot(p, viewVec) / uRadius;
        if (dot(p, sideVec) > 0.0 && c > best) {
            best = c;
            point = origin + p;
        }
    }
    return best;
}

// Whether the depth buffer allows a continued surface to reach `point` (view space): false where the visible
// surface at its pixel lies behind the point by more than a twentieth of the radius (the continued surface
// would hide it) or where the sky shows. A tangent plane continued past its surface's edge fails it (a
// sphere's lower tangent plane, which rises in front of the sphere over the ground at its foot); the ground
// continued to the foot of a wall passes (it lies on the ground the pixels there show).
bool depthAgrees(vec3 point) {
    vec4 clip = uProjection * vec4(point, 1.0);
    if (!(clip.w > 0.0)) {
        return true;
    }
    ivec2 texel = ivec2(floor((clip.xy / clip.w * 0.5 + 0.5) * uFullSize));
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, ivec2(uFullSize)))) {
        return true;
    }
    float z = texelFetch(uLinearDepth, texel, 0).r;
    if (isinf(z) || !(z > 0.0)) {
        return false;
    }
    vec3 visible = viewPositionAt(vec2(texel) + 0.5, z);
    return dot(point - visible, viewNormalAt(texel)) <= 0.05 * uRadius;
}

void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uRaw);
    if (any(greaterThanEqual(q, size))) {
        return;
    }
    ivec2 full = ivec2(uFullSize);
    ivec2 p = aoSourcePixel(q, full);
    float z = texelFetch(uLinearDepth, p, 0).r;
    if (isinf(z) || !(z > 0.0)) {
        imageStore(uRaw, q, vec4(1.0));
        return;
    }
    vec2 centre = vec2(p) + 0.5;
    vec3 position = viewPositionAt(centre, z);
    vec3 normal = viewNormalAt(p);
    vec3 viewVec = normalize(-position);
    vec3 origin = position + uBias * normal;

    // The radius in pixels at this depth: clip w is the view depth for a perspective projection, 1 for an
    // orthographic one.
    float clipW = uProjection[2][3] * position.z + uProjection[3][3];
    float radiusPixels = uRadius * 0.5 * uFullSize.y * uProjection[1][1] / max(clipW, 1e-6);
    if (radiusPixels < 1.0) {
        imageStore(uRaw, q, vec4(1.0)); // no texel lies within the radius
        return;
    }

    float sliceNoise = interleavedGradientNoise(vec2(p), uFrame);
    float stepNoise = interleavedGradientNoise(vec2(p) + vec2(37.0, 11.0), uFrame + 17u);
    float visibility = 0.0;
    for (int slice = 0; slice < uSlices; ++slice) {
        float phi = (float(slice) + sliceNoise) * kPi / float(uSlices);
        vec2 omega = vec2(cos(phi), sin(phi)); // screen direction, pixels (y up, as view space)

        // The slice plane holds the view vector and the direction; the normal projected into it sets the
        // hemisphere the horizons are clamped to (angle n from the view vector, signed towards +omega).
        vec3 direction = vec3(omega, 0.0);
        vec3 orthoDirection = direction - dot(direction, viewVec) * viewVec;
        vec3 axis = normalize(cross(orthoDirection, viewVec));
        vec3 projectedNormal = normal - axis * dot(normal, axis);
        float projectedLength = length(projectedNormal);
        if (projectedLength < 1e-4) {
            visibility += 0.0;
            continue;
        }
        float cosN = clamp(dot(projectedNormal, viewVec) / projectedLength, -1.0, 1.0);
        float n = (dot(orthoDirection, projectedNormal) < 0.0 ? -1.0 : 1.0) * acos(cosN);

        // Horizons: the largest cosine to the view vector of any surface point within the radius, on each
        // side; starting at the tangent plane (the lowest horizon the normal's hemisphere allows).
        float lowCos0 = cos(n + kHalfPi); // +omega side
        float lowCos1 = cos(n - kHalfPi); // -omega side
        float horizonCos0 = lowCos0;
        float horizonCos1 = lowCos1;
        for (int side = 0; side < 2; ++side) {
            vec2 sideDir = side == 0 ? omega : -omega;
            float best = side == 0 ? lowCos0 : lowCos1;
            vec3 sideVec = side == 0 ? orthoDirection : -orthoDirection;
            float planeBest = -1.0;
            vec3 planePoint = vec3(0.0);
            for (int s = 0; s < uSteps; ++s) {
                // Quadratic spacing: denser near the centre, where occluders subtend the largest angles.
                float jitter = fract(stepNoise + 0.618034 * float(slice) + 0.5 * float(side));
                float t = (float(s) + jitter) / float(uSteps);
                float offset = mix(1.0, radiusPixels, t * t);
                vec2 window = centre + sideDir * offset;
                ivec2 texel = ivec2(floor(window));
                if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, full))) {
                    break;
                }
                float sz = texelFetch(uLinearDepth, texel, 0).r;
                if (isinf(sz) || !(sz > 0.0)) {
                    continue; // the sky occludes nothing
                }
                vec3 hit = viewPositionAt(vec2(texel) + 0.5, sz);
                vec3 delta = hit - origin;
                float dist = length(delta);
                if (dist < 1e-6) {
                    continue;
                }
                vec3 sampleNormal = viewNormalAt(texel);
                if (dist <= uRadius) {
                    float c = dot(delta / dist, viewVec);
                    best = c > best ? c : mix(best, c, kThickness);
                }
                vec3 point;
                float c = planeHorizon(hit, sampleNormal, origin, axis, sideVec, viewVec, point);
                if (c > planeBest) {
                    planeBest = c;
                    planePoint = point;
                }
            }
            if (planeBest > best && depthAgrees(planePoint)) {
                best = planeBest;
            }
            if (side == 0) {
                horizonCos0 = best;
            } else {
                horizonCos1 = best;
            }
        }
        // Horizon angles from the view vector, clamped to the normal's hemisphere.
        float h0 = acos(clamp(horizonCos0, -1.0, 1.0));
        float h1 = -acos(clamp(horizonCos1, -1.0, 1.0));
        h0 = n + min(h0 - n, kHalfPi);
        h1 = n + max(h1 - n, -kHalfPi);
        // The inner integral (eq. 10): cosine-weighted visible arc on each side of the view vector.
        float sinN = sin(n);
        float arc0 = 0.25 * (-cos(2.0 * h0 - n) + cosN + 2.0 * h0 * sinN);
        float arc1 = 0.25 * (-cos(2.0 * h1 - n) + cosN + 2.0 * h1 * sinN);
        visibility += projectedLength * (arc0 + arc1);
    }
    visibility = clamp(visibility / float(uSlices), 0.0, 1.0);
    imageStore(uRaw, q, vec4(visibility));
}
