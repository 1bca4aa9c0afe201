// Lens flare features: ghosts and a halo, after J. Chapman, "Pseudo Lens Flare" (2013). A lens reflects bright
// sources into ghosts along the line through the image centre, mirrored; a halo ring appears around the
// centre. Each ghost samples the thresholded buffer at uv + i * spacing * (centre - uv), weighted to fade
// towards the edges (ghosts of sources near the rim are dim); the halo samples a fixed distance along the
// same direction, weighted by closeness to the ring. The buffer is small and each ghost reads it through a
// round Gaussian footprint, which blurs the ghosts enough that no separate blur pass is needed.
layout(local_size_x = 8, local_size_y = 8) in; // a compute pass: 8x8 groups, image store

layout(binding = 0) uniform sampler2D uSource;
layout(binding = 0, rgba16f) uniform writeonly image2D uTarget;
// Mirrors photopic::LensFlareFeaturesParameters (passes/lensflare/LensFlarePass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform LensFlareFeaturesParameters {
    vec2 uTargetTexel;
    int uGhosts;
    float uGhostSpacing;
    float uHaloRadius;
    float uIntensity;
    float uAspect; // width / height, keeps the halo round
};

// A ghost sees the source through a round footprint: a Gaussian of one texel (sigma) taken as a centre tap
// and eight on a ring 1.25 texels out, each bilinear. One bilinear tap is a tent whose contours are squares,
// and a bright source's ghost then shows the buffer's grid as a square.
const float kCentreWeight = 0.21447;
const float kRingWeight = 0.09819; // exp(-1.25^2 / 2) times the centre's, the nine summing to 1
const float kRingRadius = 1.25;
const float kDiagonal = 0.70710678;
const vec2 kRing[8] = vec2[8](vec2(1.0, 0.0), vec2(kDiagonal, kDiagonal), vec2(0.0, 1.0),
                              vec2(-kDiagonal, kDiagonal), vec2(-1.0, 0.0), vec2(-kDiagonal, -kDiagonal),
                              vec2(0.0, -1.0), vec2(kDiagonal, -kDiagonal));

vec3 sampleRound(vec2 uv) {
    vec3 c = textureLod(uSource, uv, 0.0).rgb * kCentreWeight;
    for (int k = 0; k < 8; ++k) {
        c += textureLod(uSource, uv + kRing[k] * kRingRadius * uTargetTexel, 0.0).rgb * kRingWeight;
    }
    return c;
}

vec3 sampleFaded(vec2 uv) {
    float fade = 1.0 - clamp(length(uv - 0.5) / 0.70710678, 0.0, 1.0);
    return sampleRound(uv) * fade * fade;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(uTarget)))) {
        return;
    }
    vec2 uv = (vec2(p) + 0.5) * uTargetTexel;
    // Mirrored through the centre: a source at the top-left throws its ghosts towards the bottom-right.
    vec2 flipped = vec2(1.0) - uv;
    vec2 ghostVec = (vec2(0.5) - flipped) * uGhostSpacing;
    vec3 color = vec3(0.0);
    for (int i = 0; i < uGhosts; ++i) {
        color += sampleFaded(flipped + ghostVec * float(i));
    }
    vec2 dir = vec2(0.5) - flipped;
    float len = length(dir * vec2(uAspect, 1.0));
    if (len > 1e-4 && uHaloRadius > 0.0) {
        vec2 haloVec = dir / len * uHaloRadius;
        vec2 haloUv = flipped + haloVec;
        float ring = 1.0 - clamp(abs(length((haloUv - 0.5) * vec2(uAspect, 1.0)) - uHaloRadius) / 0.1, 0.0, 1.0);
        color += sampleFaded(haloUv) * ring;
    }
    imageStore(uTarget, p, vec4(color * uIntensity, 1.0));
}
