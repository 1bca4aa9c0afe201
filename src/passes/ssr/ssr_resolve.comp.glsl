// Screen-space reflections, resolved and composited: each pixel's hit (ssr_trace) is looked up in last
// frame's image, where the reflected point was then (its motion vector, or the camera's reprojection of its
// depth), at the mip level the glossy cone covers; without a usable history, this frame's image at the hit.
// The reflection, weighted by the material's specular weight F0, the confidence and ssr.intensity, is added
// to the scene colour (the host's colour holds no reflection of its own there). Out: the new scene colour
// and, with SSR_REFLECTIONS (the debug view shows them), the reflections (radiance, confidence).
#include "passes/common/sanitize.h.glsl"
#include "passes/ssr/ssr_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

// Which inputs the frame has are defines, a program per combination: a SIMD implementation that runs both
// sides of a branch does not pay for the reprojection when there is motion, or for a history it cannot use.
const bool kHasMotion = SSR_MOTION != 0;
const bool kHasHistory = SSR_HISTORY != 0;
const bool kHasMaterial = SSR_MATERIAL != 0;
const bool kWriteReflections = SSR_REFLECTIONS != 0;

layout(binding = 2, r32f) uniform readonly image2D uLinearDepth;
layout(binding = 3, rgba16f) uniform readonly image2D uScene;    // this frame's scene colour, before reflections
layout(binding = 2) uniform sampler2D uHistory;  // last frame's image (mip chain), with SSR_HISTORY
layout(binding = 4, rgba32f) uniform readonly image2D uHits;     // ssr_trace's output
layout(binding = 4) uniform sampler2D uMotion;   // with SSR_MOTION
layout(binding = 5) uniform sampler2D uMaterial; // with SSR_MATERIAL
layout(binding = 0, rgba16f) uniform writeonly image2D uOutScene;
layout(binding = 1, rgba16f) uniform writeonly image2D uOutReflections;

// Finite, non-negative and below the half-float maximum.
vec3 finiteColour(vec3 c) { return sanitize(c); }

// Where the reflected point at window position `window` was last frame, in UV; < 0 when unknown.
vec2 previousUv(vec2 window, ivec2 hitPixel) {
    vec2 uv = window / uFullSize;
    if (kHasMotion) {
        vec2 m = texelFetch(uMotion, hitPixel, 0).rg;
        return all(lessThan(abs(m), vec2(1e4))) ? uv - m : vec2(-1.0); // NaN fails too
    }
    float z = imageLoad(uLinearDepth, hitPixel).r;
    if (!validDepth(z)) {
        return vec2(-1.0);
    }
    vec4 clip = uReprojection * vec4(viewPositionAt(window, z), 1.0);
    return clip.w > 0.0 ? clip.xy / clip.w * 0.5 + 0.5 : vec2(-1.0);
}

vec3 reflectedRadiance(vec4 hit) {
    // The hit pixel's centre: the colour the depth buffer's sample there belongs to (a bilinear fetch at the
    // ray's exact crossing would blend in the neighbours, across a silhouette or a texture edge).
    ivec2 hitPixel = clamp(ivec2(hit.xy), ivec2(0), ivec2(uFullSize) - 1);
    vec2 window = vec2(hitPixel) + 0.5;
    if (kHasHistory) {
        vec2 uv = previousUv(window, hitPixel);
        if (all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)))) {
            // The cone's diameter in pixels picks the level whose texels cover it.
            float lod = log2(max(2.0 * hit.w, 1.0));
            return textureLod(uHistory, uv, lod).rgb;
        }
    }
    return imageLoad(uScene, hitPixel).rgb;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(uFullSize)))) {
        return;
    }
    vec3 scene = imageLoad(uScene, p).rgb;
    vec4 hit = imageLoad(uHits, p);
    float confidence = hit.z;
    vec3 radiance = vec3(0.0);
    if (confidence > 0.0 && all(lessThanEqual(abs(hit), vec4(1e6)))) {
        radiance = finiteColour(reflectedRadiance(hit));
    } else {
        confidence = 0.0;
    }
    vec3 f0 = vec3(0.04);
    if (kHasMaterial) {
        f0 = clamp(sanitize(texelFetch(uMaterial, p, 0).rgb), 0.0, 1.0);
    }
    vec3 colour = finiteColour(scene + uIntensity * confidence * f0 * radiance);
    imageStore(uOutScene, p, vec4(colour, 1.0));
    if (kWriteReflections) {
        imageStore(uOutReflections, p, vec4(radiance, confidence));
    }
}
