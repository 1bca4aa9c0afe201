// Volumetric light, step 4: the accumulated half-resolution light, upsampled bilinearly (it is smooth: a
// shaft's edge is as soft as the march's samples make it) and scaled by intensity x weight x exposure x the
// sun's fade, is added to the scene colour. The light in the air lies in front of every surface, so it is
// added to occluders too, as in the paper. The debug view gets the light added.
#include "passes/volumetriclight/volumetric_light_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uScene;
layout(binding = 6) uniform sampler2D uLight; // half resolution, bilinear
layout(binding = 0, rgba16f) uniform writeonly image2D uOut;
layout(binding = 1, rgba16f) uniform writeonly image2D uView;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uOut);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    vec4 c = texelFetch(uScene, p, 0);
    vec3 added = vec3(0.0);
    if (uActive != 0) {
        vec2 uv = (vec2(p) + 0.5) / uFullSize;
        added = sanitizeLight(uScale * textureLod(uLight, uv, 0.0).rgb);
    }
    imageStore(uOut, p, vec4(min(sanitizeLight(c.rgb) + added, vec3(kHalfMax)), c.a));
    if (uWriteView != 0) {
        imageStore(uView, p, vec4(added, 1.0));
    }
}
