// Motion blur, step 1: each pixel's blur radius in pixels (half the streak its point draws while the shutter
// is open), from its motion over one frame interval: motion x size x shutter fraction / 2 x intensity,
// clamped to maxBlur. Non-finite motion is no motion.
#include "passes/motionblur/motion_blur_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uMotion;
layout(binding = 0, rg16f) uniform writeonly image2D uVelocity;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(uFullSize)))) {
        return;
    }
    vec2 v = texelFetch(uMotion, p, 0).rg * uFullSize * uRadiusScale;
    if (any(isnan(v)) || any(isinf(v))) {
        v = vec2(0.0);
    }
    float len = length(v);
    if (len > uMaxBlur) {
        v *= uMaxBlur / len;
    }
    imageStore(uVelocity, p, vec4(v, 0.0, 0.0));
}
