// Depth of field, step 3: the near field's reach. Without DILATE: the largest near CoC in each tile of the
// half-resolution near field. With DILATE: the largest over the tiles within uDilation of each tile, so a
// blurred foreground is gathered wherever its blur reaches, also over sharp background (Jimenez 2014, "Next
// Generation Post Processing in Call of Duty: Advanced Warfare": scatter as gather from the tile's maximum).
#include "passes/dof/dof_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uSource; // DILATE: tile maxima; else the near field (a: CoC)
layout(binding = 0, r16f) uniform writeonly image2D uTiles;

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, uTileCount))) {
        return;
    }
    float largest = 0.0;
#ifdef DILATE
    for (int dy = -uDilation; dy <= uDilation; ++dy) {
        for (int dx = -uDilation; dx <= uDilation; ++dx) {
            ivec2 q = clamp(t + ivec2(dx, dy), ivec2(0), uTileCount - 1);
            largest = max(largest, texelFetch(uSource, q, 0).r);
        }
    }
#else
    ivec2 last = ivec2(uHalfSize) - 1;
    for (int y = 0; y < uTileSize; ++y) {
        for (int x = 0; x < uTileSize; ++x) {
            float r = texelFetch(uSource, min(t * uTileSize + ivec2(x, y), last), 0).a;
            largest = max(largest, isnan(r) ? 0.0 : r);
        }
    }
#endif
    imageStore(uTiles, t, vec4(largest));
}
