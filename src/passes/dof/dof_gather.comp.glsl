// Depth of field, step 4: the half-resolution gathers (Jimenez 2014, "Next Generation Post Processing in
// Call of Duty: Advanced Warfare"; scatter as gather). Samples lie on rings of a disc or hexagon
// (dof_common.h.glsl); a sample at distance d counts where its own CoC reaches this pixel (coverage
// clamp(r_s - d + 0.5, 0, 1)), so a pixel never gathers from one whose blur does not spread onto it.
//
// FAR: the pattern spans the centre's own far CoC; the result is the coverage-weighted mean. A sharp or
// near texel has far CoC 0 and covers nothing beyond itself: sharp objects do not bleed into the blurred
// background. A sample with a larger CoC than the centre lies behind it and counts only within the centre's
// own radius (Jimenez's depth comparison, on CoC since the far CoC grows with depth).
// NEAR: the pattern spans the dilated tile's largest near CoC, so a blurred foreground reaches over sharp
// pixels next to it. Each covering sample spreads its colour over its own disc (weight 1 / r_s^2, its energy
// per area); alpha is the covered fraction, sum(coverage A / (pi r_s^2)) with A the area each sample stands
// for, clamped to 1.
#include "passes/dof/dof_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, rgba16f) uniform readonly image2D uField; // rgb, a: CoC (half-resolution pixels)
layout(binding = 2, r16f) uniform readonly image2D uTiles; // NEAR: dilated tile maxima
layout(binding = 0, rgba16f) uniform writeonly image2D uOut;

/// Below this (half-resolution pixels, half a full-resolution pixel) a field is not blurred.
const float kMinCoc = 0.25;

// The 2 x 2 average before the gather and the bilinear fetches after it blur the far field already: about
// the variance of a disc of radius 1 (half-resolution pixels). The gather's own disc is shrunk to add only
// what is missing, r' = sqrt(r^2 - 1), so that a CoC of a few pixels comes out at its own width.
float gatherRadius(float r) { return sqrt(max(r * r - 1.0, 0.0)); }

void main() {
    ivec2 h = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(h, ivec2(uHalfSize)))) {
        return;
    }
    vec2 centre = vec2(h) + 0.5;
    vec4 own = imageLoad(uField, h);
#ifdef NEAR
    float reach = imageLoad(uTiles, h / uTileSize).r;
#else
    float reach = gatherRadius(own.a);
#endif
    if (!(reach >= kMinCoc)) {
#ifdef NEAR
        imageStore(uOut, h, vec4(own.rgb, 0.0));
#else
        imageStore(uOut, h, own);
#endif
        return;
    }
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    float covered = 0.0;
    for (int ring = 0; ring <= uRings; ++ring) {
        int count = ring == 0 ? 1 : 8 * ring;
        for (int j = 0; j < count; ++j) {
            float fraction = 0.0;
            vec2 offset = ring == 0 ? vec2(0.0) : apertureSample(ring, j, fraction);
            float d = fraction * reach;
            // Nearest texels: a bilinear fetch would mix a sharp texel's colour into a blurred one's CoC.
            ivec2 q = clamp(ivec2(floor(centre + offset * reach)), ivec2(0), ivec2(uHalfSize) - 1);
            vec4 s = imageLoad(uField, q);
            float r = s.a;
#ifdef NEAR
            float cover = r >= kMinCoc ? clamp(r - d + 0.5, 0.0, 1.0) : 0.0;
            float w = cover / max(r * r, kMinCoc * kMinCoc);
            covered += w;
#else
            // Behind the focus a larger CoC is a farther surface: it spreads no further than the centre's own
            // blur (it is hidden behind the centre's surface), a nearer one by its own CoC.
            float w = clamp(min(gatherRadius(r), reach) - d + 0.5, 0.0, 1.0);
#endif
            sum += w * s.rgb;
            weights += w;
        }
    }
    vec3 rgb = weights > 0.0 ? sum / weights : own.rgb;
#ifdef NEAR
    // Each sample stands for pi (reach / (2 rings))^2 of area; a covering sample's disc has pi r^2.
    float alpha = clamp(covered * reach * reach / float(4 * uRings * uRings), 0.0, 1.0);
    imageStore(uOut, h, vec4(rgb, alpha));
#else
    imageStore(uOut, h, vec4(rgb, own.a));
#endif
}
