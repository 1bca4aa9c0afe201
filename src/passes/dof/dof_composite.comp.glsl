// Depth of field, step 5: the full-resolution composite. The far field replaces the sharp pixel as its own
// CoC grows past half a pixel (fully at 1.5 px), so pixels in focus keep their sharp value exactly; the near
// field then goes over the result with its coverage, which reaches past the foreground's silhouette onto
// sharp background. Built with DOF_LISTED it runs over the tiles dof_changed_tiles.comp.glsl listed (one work
// group a tile), the rest of the image an image copy of the sharp colour; without, over every pixel.
#include "passes/dof/dof_common.h.glsl"
#ifdef DOF_LISTED
#include "passes/dof/dof_changed_tiles.h.glsl"
#endif

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, rgba16f) uniform readonly image2D uColor; // sceneColor
layout(binding = 2, r16f) uniform readonly image2D uCoc;   // signed, full-resolution pixels
layout(binding = 3, rgba16f) uniform readonly image2D uFar;   // half resolution, rgb + far CoC
layout(binding = 3) uniform sampler2D uNear;  // half resolution, rgb + coverage
layout(binding = 0, rgba16f) uniform writeonly image2D uOut;

// The far field at a full-resolution pixel: a bilinear upsample whose weights drop the half-resolution
// texels that are not blurred (a sharp object's), so it does not bleed into the background around it.
vec4 farUpsample(vec2 uv) {
    vec2 t = uv * uHalfSize - 0.5;
    ivec2 base = ivec2(floor(t));
    vec2 f = t - vec2(base);
    ivec2 last = ivec2(uHalfSize) - 1;
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int i = 0; i < 4; ++i) {
        ivec2 o = ivec2(i & 1, i >> 1);
        vec4 s = imageLoad(uFar, clamp(base + o, ivec2(0), last));
        float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
        w *= s.a >= 0.25 ? 1.0 : 1e-4;
        sum += w * s;
        weights += w;
    }
    return sum / max(weights, 1e-8);
}

void main() {
#ifdef DOF_LISTED
    uint tile = changedTiles[gl_WorkGroupID.z];
    ivec2 p = ivec2(int(tile % uint(compositeTileCount().x)), int(tile / uint(compositeTileCount().x))) *
                  kCompositeTile +
              ivec2(gl_LocalInvocationID.xy);
#else
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
#endif
    if (any(greaterThanEqual(p, ivec2(uFullSize)))) {
        return;
    }
    vec4 sharp = imageLoad(uColor, p);
    float coc = imageLoad(uCoc, p).r;
    vec2 uv = (vec2(p) + 0.5) / uFullSize;
    vec4 result = sharp;
    float t = clamp(coc - 0.5, 0.0, 1.0);
    if (t > 0.0) {
        vec4 far = farUpsample(uv);
        if (finite4(far)) {
            result.rgb = mix(sharp.rgb, far.rgb, t);
        }
    }
    vec4 near = textureLod(uNear, uv, 0.0);
    if (near.a > 0.0 && finite4(near)) {
        result.rgb = mix(result.rgb, near.rgb, near.a);
    }
    imageStore(uOut, p, result);
}
