// Motion blur, step 4: the gather. After McGuire, Hennessy, Bukowski and Osman 2012, "A Reconstruction
// Filter for Plausible Motion Blur" (samples along the neighbourhood's longest velocity, classified by depth)
// and Guertin, McGuire and Nowrouzezahrai 2014, "A Fast and Stable Feature-Aware Motion Blur Filter"
// (per-pixel jittered sample positions). The weights here are coverage rather than the paper's cones: the
// N samples spread over the streak [-vmax, vmax], so each stands for `spacing` = 2 |vmax| / N pixels of it,
// and a sample Y whose own streak (radius rY) reaches this pixel X covers it for spacing / (2 rY) of the
// shutter. The pixel's colour is then composited front to back:
//   samples nearer than X cover it by their summed coverage (at most all of it);
//   X's own surface fills the rest: still, its colour; moving, the samples of its own depth that reach it
//   (itself among them), and for the share of the shutter its surface has moved off X, the samples behind
//   it within X's own streak (what its motion uncovers).
// A pixel whose neighbourhood moves less than half a pixel is copied unchanged.
#include "passes/common/noise.h.glsl"
#include "passes/motionblur/motion_blur_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uScene;
layout(binding = 1) uniform sampler2D uVelocity;
layout(binding = 2) uniform sampler2D uDepth;
layout(binding = 3) uniform sampler2D uNeighbourMax;
layout(binding = 0, rgba16f) uniform writeonly image2D uOut;
layout(binding = 1, rgba16f) uniform writeonly image2D uTiles;

const float kSkyDepth = 1e30;  // the sky (+inf) and broken depths: behind everything, finite for the ratios
const float kSameSurface = 0.01; // relative depth difference within which two samples are one surface
const float kDepthRamp = 0.02;   // ... over which "the same" turns into "in front" (a soft compare)

float depthAt(ivec2 p) {
    float z = texelFetch(uDepth, p, 0).r;
    return (z > 0.0 && z < kSkyDepth) ? z : kSkyDepth;
}

// 1 when depth `a` is in front of depth `b` by more than the same-surface band, 0 within it, a ramp between.
float inFront(float a, float b) {
    float relative = (b - a) / min(a, b);
    return clamp((relative - kSameSurface) / kDepthRamp, 0.0, 1.0);
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(uFullSize);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    vec4 c0 = texelFetch(uScene, p, 0);
    vec2 vmax = texelFetch(uNeighbourMax, p / uTileSize, 0).rg;
    float lenMax = length(vmax);
    if (uWriteTiles != 0) {
        imageStore(uTiles, p, vec4(vmax, lenMax, 1.0));
    }
    if (!(lenMax >= 0.5)) {
        imageStore(uOut, p, c0);
        return;
    }
    float rX = length(texelFetch(uVelocity, p, 0).rg);
    bool movingX = rX >= 0.5;
    float zX = depthAt(p);
    vec2 centre = vec2(p) + 0.5;
    float n = float(uSampleCount);
    float spacing = 2.0 * lenMax / n;
    float jitter = hashUniform(p, uFrame, 0u) - 0.5;

    vec3 front = vec3(0.0), layer = vec3(0.0), behind = vec3(0.0);
    float frontCover = 0.0, layerCover = 0.0, behindWeight = 0.0;
    for (int i = 0; i < uSampleCount; ++i) {
        float t = -1.0 + 2.0 * (float(i) + 0.5 + jitter) / n;
        ivec2 q = clamp(ivec2(floor(centre + t * vmax)), ivec2(0), size - 1);
        float d = length(vec2(q) + 0.5 - centre);
        float rY = length(texelFetch(uVelocity, q, 0).rg);
        float zY = depthAt(q);
        vec3 cY = texelFetch(uScene, q, 0).rgb;
        float f = inFront(zY, zX);
        float b = inFront(zX, zY);
        // Y's streak reaches X (anti-aliased at its end), for spacing / (2 rY) of the shutter.
        float reachY = clamp(rY - d + 0.5, 0.0, 1.0) * spacing / (2.0 * max(rY, 0.5));
        if (movingX) {
            front += f * reachY * cY;
            frontCover += f * reachY;
            float same = 1.0 - f - b;
            layer += same * reachY * cY;
            layerCover += same * reachY;
            float reachX = b * clamp(rX - d + 0.5, 0.0, 1.0);
            behind += reachX * cY;
            behindWeight += reachX;
        } else {
            // A still pixel: only moving samples not behind it pass over it.
            float w = (1.0 - b) * reachY * step(0.5, rY);
            front += w * cY;
            frontCover += w;
        }
    }
    vec3 own = c0.rgb;
    if (movingX) {
        if (layerCover >= 1.0 || behindWeight <= 0.0) {
            own = layerCover > 0.0 ? layer / layerCover : c0.rgb;
        } else {
            own = layer + (1.0 - layerCover) * behind / behindWeight;
        }
    }
    vec3 result = frontCover >= 1.0 ? front / frontCover : front + (1.0 - frontCover) * own;
    imageStore(uOut, p, vec4(result, c0.a));
}
