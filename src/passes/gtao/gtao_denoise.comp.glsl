// GTAO's spatial denoiser: a Gaussian over 3 x 3 AO texels (5 x 5 at half resolution), weighted by how far
// each neighbour's surface lies from the centre's tangent plane, how far it lies from the centre point and
// how its normal turns away, so occlusion does not bleed across depth discontinuities (no halos) and the
// half-resolution result is upsampled along surfaces. Sky pixels are 1.
#include "passes/gtao/gtao_common.h.glsl"
#include "passes/gtao/gtao_surface.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

// Full-resolution pixels per AO texel (1 or 2): a define, so that the taps' loops and their Gaussian weights
// are constants (a program per resolution).
const int kScale = GTAO_SCALE;

layout(binding = 2, rg32ui) uniform readonly uimage2D uRaw; // packAoTexel
layout(binding = 0, r16f) uniform writeonly image2D uVisibility;

// Neighbours farther from the centre point than this fraction of the radius weigh exp(-1) less, and so on:
// visibility changes over the radius. A plane seen at a grazing angle steps by a radius or more from one
// pixel row to the next, and without this the ground in front of a wall's foot took the wall's occlusion.
const float kReach = 0.5;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 full = imageSize(uVisibility);
    if (any(greaterThanEqual(p, full))) {
        return;
    }
    GtaoSurface surface = surfaceAt(p);
    float z = surface.z;
    if (!isSurface(z)) {
        imageStore(uVisibility, p, vec4(1.0));
        return;
    }
    vec3 normal = normalize(surface.n);
    vec3 position = viewPositionAtTexel(p, z);
    ivec2 rawSize = imageSize(uRaw);
    ivec2 centre = p / kScale;
    // Tolerance for the distance from the tangent plane: a few per cent of the depth.
    float invTolerance = 1.0 / (0.02 * z);
    float invReach = 1.0 / (kReach * uRadius);
    float sum = 0.0;
    float weights = 0.0;
    float centreVisibility = 1.0; // the centre tap's own, where no tap weighs anything
    // 3 x 3 texels at full resolution, 5 x 5 at half (where the upsampling needs texels 2 out). At full
    // resolution the ring 2 pixels out (weight under a third of the centre's) took 16 of the 25 taps and
    // bought no accuracy against either ray-traced truth, only a little steadiness under motion.
    const int reach = kScale == 1 ? 1 : 2;
    for (int dy = -reach; dy <= reach; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
            ivec2 q = centre + ivec2(dx, dy);
            bool inside = all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, rawSize));
            ivec2 source = aoSourcePixelAt(q, full, kScale);
            AoTexel neighbour = unpackAoTexel(imageLoad(uRaw, clamp(q, ivec2(0), rawSize - 1)).xy);
            vec3 offset = viewPositionAtTexel(source, neighbour.z) - position;
            float plane = dot(offset, normal) * invTolerance;
            float distance2 = dot(offset, offset) * (invReach * invReach);
            // A crease (a wall meeting the ground) lies in both faces' tangent planes; the normals tell the
            // faces apart, whose occlusion differs: the cosine between them to the fourth power (the
            // neighbour's normal is 127 times a unit vector).
            float along = max(dot(neighbour.n, normal), 0.0) * (1.0 / 127.0);
            float cosine2 = along * along;
            // The Gaussian is in full-resolution pixels: at half resolution it spans the same area of the
            // image, not twice as much.
            // At full resolution an inside tap's source is q itself, (dx, dy) from p: a constant.
            vec2 d = kScale == 1 ? vec2(dx, dy) : vec2(source - p);
            float w = exp(-0.5 * dot(d, d) / 2.25 - plane * plane - distance2) * (cosine2 * cosine2);
            w = inside && isSurface(neighbour.z) ? w : 0.0;
            sum += w * neighbour.visibility;
            centreVisibility = dx == 0 && dy == 0 ? neighbour.visibility : centreVisibility;
            weights += w;
        }
    }
    float visibility = weights > 1e-6 ? sum / weights : centreVisibility;
    imageStore(uVisibility, p, vec4(clamp(visibility, 0.0, 1.0)));
}
