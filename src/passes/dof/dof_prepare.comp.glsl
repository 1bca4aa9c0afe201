// Depth of field, step 2: the half-resolution near and far fields. Each half-resolution texel splits its
// 2 x 2 full-resolution pixels by the sign of their CoC: the far field averages the colour of the pixels
// behind the focus (so a sharp or near object's colour does not enter the background's blur) and keeps their
// mean CoC; the near field averages the pixels in front and keeps their largest CoC (a foreground edge keeps
// its blur). Colour stays scene-referred HDR: a bright point spreads into a bright bokeh disc. CoCs are in
// half-resolution pixels from here on.
#include "passes/dof/dof_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 2, rgba16f) uniform readonly image2D uColor; // sceneColor
layout(binding = 3, r16f) uniform readonly image2D uCoc;   // signed, full-resolution pixels
layout(binding = 0, rgba16f) uniform writeonly image2D uFar;  // rgb, a: far CoC
layout(binding = 1, rgba16f) uniform writeonly image2D uNear; // rgb, a: near CoC (positive)

void main() {
    ivec2 h = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(h, ivec2(uHalfSize)))) {
        return;
    }
    ivec2 last = ivec2(uFullSize) - 1;
    vec3 all = vec3(0.0), far = vec3(0.0), near = vec3(0.0);
    float farCount = 0.0, nearCount = 0.0, farCoc = 0.0, nearCoc = 0.0;
    for (int i = 0; i < 4; ++i) {
        ivec2 q = min(2 * h + ivec2(i & 1, i >> 1), last);
        vec4 c = imageLoad(uColor, q);
        c.rgb = finite4(c) ? max(c.rgb, vec3(0.0)) : vec3(0.0);
        float r = 0.5 * imageLoad(uCoc, q).r;
        all += c.rgb;
        if (r >= 0.0) {
            far += c.rgb;
            farCoc += r;
            farCount += 1.0;
        } else {
            near += c.rgb;
            nearCoc = max(nearCoc, -r);
            nearCount += 1.0;
        }
    }
    vec4 farOut = farCount > 0.0 ? vec4(far / farCount, farCoc / farCount) : vec4(all * 0.25, 0.0);
    vec4 nearOut = nearCount > 0.0 ? vec4(near / nearCount, nearCoc) : vec4(all * 0.25, 0.0);
    imageStore(uFar, h, farOut);
    imageStore(uNear, h, nearOut);
}
