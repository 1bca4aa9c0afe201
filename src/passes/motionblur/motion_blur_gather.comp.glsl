// Motion blur, step 4: the gather. After McGuire, Hennessy, Bukowski and Osman 2012, "A Reconstruction
// Filter for Plausible Motion Blur" (samples along the neighbourhood's longest velocity, classified by depth)
// and Guertin, McGuire and Nowrouzezahrai 2014, "A Fast and Stable Feature-Aware Motion Blur Filter"
// (per-pixel jittered sample positions, mirrored in pairs through the pixel). The weights here are coverage rather than the paper's cones: the
// N samples spread evenly over the streak [-vmax, vmax], each standing for `spacing` = 2 |vmax| / N pixels
// of it, and a sample at distance d whose own streak (radius rY) reaches this pixel X covers X for
// spacing / (2 rY) of the shutter. d is the distance of the point the sample stands for, not of its pixel's
// centre: the nearest-pixel lookup already gives a streak's end pixels their partial share, and weighing
// them down again by their centres' distance made every streak half a pixel short of motion x shutter.
// The pixel is composited front to back:
//   samples nearer than X that reach it cover it by their summed coverage (at most all of it);
//   X's own layer fills the rest. Still, that is its colour. Moving, X sees over the shutter the points its
//   streak sweeps, the samples within rX of it, each for an equal share: a sample at X's depth is its
//   surface there, one behind it is what X's motion uncovers, and a nearer one that does not reach X hides
//   X's surface there, which is taken to go on behind it (X's colour: an object moving out from behind a
//   still one keeps its colour). A nearer sample that reaches X is left out of the layer, since X's layer is
//   not seen while it covers X; so when every velocity is the same the result is the box average along the
//   streak whatever the depths, as a uniform pan must give.
// A pixel whose neighbourhood moves less than half a pixel is copied unchanged. The gather runs over the tiles
// listed moving; the program built with MOTION_BLUR_STILL copies the tiles listed still
// (motion_blur_lists.h.glsl), so the still ones do not run the gather's code under a mask on a SIMD CPU.
#include "passes/common/noise.h.glsl"
#include "passes/motionblur/motion_blur_common.h.glsl"
#include "passes/motionblur/motion_blur_lists.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 2, rgba16f) uniform readonly image2D uScene;
layout(binding = 3, rg16f) uniform readonly image2D uVelocity;
layout(binding = 4, r32f) uniform readonly image2D uDepth;
layout(binding = 5, rg16f) uniform readonly image2D uNeighbourMax;
layout(binding = 0, rgba16f) uniform writeonly image2D uOut;
layout(binding = 1, rgba16f) uniform writeonly image2D uTiles;

const float kSkyDepth = 1e30;  // the sky (+inf) and broken depths: behind everything, finite for the ratios
const float kSameSurface = 0.01; // relative depth difference within which two samples are one surface
const float kDepthRamp = 0.02;   // ... over which "the same" turns into "in front" (a soft compare)

float depthAt(ivec2 p) {
    float z = imageLoad(uDepth, p).r;
    return (z > 0.0 && z < kSkyDepth) ? z : kSkyDepth;
}

// 1 when depth `a` is in front of depth `b` by more than the same-surface band, 0 within it, a ramp between.
float inFront(float a, float b) {
    float relative = (b - a) / min(a, b);
    return clamp((relative - kSameSurface) / kDepthRamp, 0.0, 1.0);
}

void main() {
    // This invocation's pixel in the listed tile gl_WorkGroupID.z.
#ifdef MOTION_BLUR_STILL
    uint tile = listTiles[uint(uTileCount.x * uTileCount.y) + gl_WorkGroupID.z];
#else
    uint tile = listTiles[gl_WorkGroupID.z];
#endif
    ivec2 inTile = ivec2(gl_GlobalInvocationID.xy);
    ivec2 p = ivec2(int(tile % uint(uTileCount.x)), int(tile / uint(uTileCount.x))) * uTileSize + inTile;
    ivec2 size = ivec2(uFullSize);
    if (any(greaterThanEqual(inTile, ivec2(uTileSize))) || any(greaterThanEqual(p, size))) {
        return;
    }
    vec4 c0 = imageLoad(uScene, p);
    vec2 vmax = imageLoad(uNeighbourMax, p / uTileSize).rg;
    float lenMax = length(vmax);
    if (uWriteTiles != 0) {
        imageStore(uTiles, p, vec4(vmax, lenMax, 1.0));
    }
#ifdef MOTION_BLUR_STILL
    imageStore(uOut, p, c0);
}
#else
    if (!(lenMax >= 0.5)) {
        imageStore(uOut, p, c0);
        return;
    }
    float rX = length(imageLoad(uVelocity, p).rg);
    bool movingX = rX >= 0.5;
    float zX = depthAt(p);
    vec2 centre = vec2(p) + 0.5;
    float n = float(uSampleCount);
    float spacing = 2.0 * lenMax / n;
    float jitter = hashUniform(p, uFrame, 0u) - 0.5;

    vec3 front = vec3(0.0), layer = vec3(0.0);
    float frontCover = 0.0, layerWeight = 0.0;
    for (int i = 0; i < uSampleCount; ++i) {
        // Mirrored pairs (Guertin et al. 2014): the second half of the samples are the first half's mirror
        // images through the pixel, so the streak is sampled symmetrically whatever the jitter.
        bool mirror = i >= (uSampleCount + 1) / 2;
        float t = -1.0 + 2.0 * (float(mirror ? uSampleCount - 1 - i : i) + 0.5 + jitter) / n;
        t = mirror ? -t : t;
        ivec2 q = clamp(ivec2(floor(centre + t * vmax)), ivec2(0), size - 1);
        // The sample's distance along the streak: the point it stands for, not its pixel's centre (the
        // pixel lookup already gives the streak's end pixels their partial share).
        float d = abs(t) * lenMax;
        float rY = length(imageLoad(uVelocity, q).rg);
        float zY = depthAt(q);
        vec3 cY = imageLoad(uScene, q).rgb;
        float f = inFront(zY, zX);
        float b = inFront(zX, zY);
        // Y's streak reaches X (anti-aliased over a pixel at its end: the rasterised edge is only known to
        // a pixel); then it covers X for spacing / (2 rY) of the shutter. Still samples reach nothing.
        float reachY = rY >= 0.5 ? clamp(rY - d + 0.5, 0.0, 1.0) : 0.0;
        float coverY = reachY * spacing / (2.0 * max(rY, 0.5));
        if (movingX) {
            front += f * coverY * cY;
            frontCover += f * coverY;
            if (d <= rX) {
                float shown = 1.0 - f; // X's own surface there, or what its motion uncovers
                float hidden = f * (1.0 - reachY);
                layer += shown * cY + hidden * c0.rgb;
                layerWeight += shown + hidden;
            }
        } else {
            // A still pixel: only moving samples not behind it pass over it.
            float w = (1.0 - b) * coverY;
            front += w * cY;
            frontCover += w;
        }
    }
    vec3 own = layerWeight > 0.0 ? layer / layerWeight : c0.rgb;
    vec3 result = frontCover >= 1.0 ? front / frontCover : front + (1.0 - frontCover) * own;
    imageStore(uOut, p, vec4(result, c0.a));
}
#endif
