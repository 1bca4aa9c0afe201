// Temporal anti-aliasing resolve in the HDR domain, before metering.
// References: Karis 2014, "High Quality Temporal Supersampling" (reprojection with motion vectors, YCoCg
// neighbourhood clamp, luma weighting 1/(1 + luma) as a reversible tone map); Salvi 2016, "An Excursion in
// Temporal Supersampling" (variance clipping: mean +- gamma * sigma); Pedersen 2016 (Playdead's INSIDE: clip
// toward the box centre, closest-depth motion, feedback that rises where the history agrees); Jimenez 2016,
// "Filmic SMAA" (Catmull-Rom history with five bilinear taps).
//
// Colours are blended in a working space c' = c E / (1 + luma(c E)), E the exposure the frame will be shown at
// (last frame's: metering follows TAA): a blend there weights each sample by 1 / (1 + luma), so a firefly
// cannot dominate the history, and the clamp box is measured as the eye will see it.
#include "passes/common/color.h.glsl"
#include "passes/common/exposure.h.glsl"
#include "passes/common/sanitize.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

// The history filter and whether the frame has depth and a camera are defines, a program per combination:
// a SIMD implementation that runs every side of a branch does not pay for both filters or for tests it
// cannot make.
const bool kBilinearHistory = TAA_BILINEAR != 0;
const bool kHasDepth = TAA_DEPTH != 0;
const bool kHasCamera = TAA_CAMERA != 0;
// The 3x3 neighbourhood from a shared 10 x 10 tile that the work group loads and converts once (each texel
// loaded and converted by one invocation instead of by nine), or with TAA_SHARED_TILE 0 from direct loads: a
// software renderer runs the barrier slower than the loads. Both give the same bits.
const bool kSharedTile = TAA_SHARED_TILE != 0;

// The inputs read texel by texel are images: a load skips the sampler's level and filtering logic. The
// motion input is the host's, declared in its texture's format (TAA_MOTION_FORMAT, a program per format).
layout(binding = 3, rgba16f) uniform readonly image2D uCurrent; // sceneColor: sanitised HDR, jittered samples
layout(binding = 1) uniform sampler2D uHistory; // last frame's resolve (filtered reads)
// Last frame's per pixel: r = the farthest linear depth of its 3 x 3 neighbourhood, g = stability.
layout(binding = 4, rg16f) uniform readonly image2D uHistoryAux;
layout(binding = 5, TAA_MOTION_FORMAT) uniform readonly image2D uMotion; // UV, current - previous
layout(binding = 6, r32f) uniform readonly image2D uDepth; // linear view depth (with TAA_DEPTH)
layout(binding = 0, rgba16f) writeonly uniform image2D uOutput;
layout(binding = 2, rg16f) writeonly uniform image2D uOutputAux;
layout(binding = 1, rg8) writeonly uniform image2D uDebug; // r: history weight, g: disoccluded

// Mirrors photopic::TaaParameters (passes/taa/TaaPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform TaaParameters {
    mat4 uInvProjection;      // this frame's, unjittered (with TAA_CAMERA)
    mat4 uViewToPreviousClip; // this frame's view space -> last frame's clip space
    float uBlend;
    float uGamma;
    float uFeedbackMin;
    float uFeedbackMax;
    float uStillPixels; // motion (pixels per frame) below which a neighbourhood counts as still
    int uHasHistory;
    int uHasDepth;
    int uHasCamera;
    int uWriteDebug;
    int uAdaptive;
    int uBilinearHistory;
};

// Frames a neighbourhood must hold still before its history is trusted without clipping.
const float kStableFrames = 8.0;

vec3 toWorking(vec3 c, float exposure) {
    c *= exposure;
    return c / (1.0 + luma709(c));
}

vec3 fromWorking(vec3 w, float exposure) { return w / (max(1.0 - luma709(w), 1e-4) * exposure); }

// Motion may be negative; only NaN and infinity are dropped (a broken motion input must not smear).
vec2 finiteMotion(vec2 m) {
    return vec2(isnan(m.x) || isinf(m.x) ? 0.0 : m.x, isnan(m.y) || isinf(m.y) ? 0.0 : m.y);
}

vec3 rgbToYCoCg(vec3 c) {
    return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b, -0.25 * c.r + 0.5 * c.g - 0.25 * c.b);
}

vec3 yCoCgToRgb(vec3 c) { return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

// Catmull-Rom through five bilinear taps: the four corner taps of the 4x4 kernel carry little weight and
// are dropped, the rest are merged pairwise into bilinear fetches (weights renormalised).
vec3 sampleHistoryCatmullRom(vec2 uv, vec2 size) {
    vec2 position = uv * size;
    vec2 centre = floor(position - 0.5) + 0.5;
    vec2 f = position - centre;
    vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
    vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
    vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
    vec2 w3 = f * f * (-0.5 + 0.5 * f);
    vec2 w12 = w1 + w2;
    vec2 tc12 = (centre + w2 / w12) / size;
    vec2 tc0 = (centre - 1.0) / size;
    vec2 tc3 = (centre + 2.0) / size;
    vec3 sum = textureLod(uHistory, vec2(tc12.x, tc0.y), 0.0).rgb * (w12.x * w0.y) +
               textureLod(uHistory, vec2(tc0.x, tc12.y), 0.0).rgb * (w0.x * w12.y) +
               textureLod(uHistory, vec2(tc12.x, tc12.y), 0.0).rgb * (w12.x * w12.y) +
               textureLod(uHistory, vec2(tc3.x, tc12.y), 0.0).rgb * (w3.x * w12.y) +
               textureLod(uHistory, vec2(tc12.x, tc3.y), 0.0).rgb * (w12.x * w3.y);
    float weight = w12.x * w0.y + w0.x * w12.y + w12.x * w12.y + w3.x * w12.y + w12.x * w3.y;
    // The lobes overshoot at hard edges: no negative light.
    return max(sum / weight, vec3(0.0));
}

// Moves `h` toward the box centre until it lies in the box (a ray-box clip, not a per-channel clamp, so the
// hue of a clipped history stays on the line to the centre).
vec3 clipToBox(vec3 boxMin, vec3 boxMax, vec3 h) {
    vec3 centre = 0.5 * (boxMax + boxMin);
    vec3 extent = 0.5 * (boxMax - boxMin) + 1e-6;
    vec3 v = h - centre;
    vec3 a = abs(v / extent);
    float m = max(a.x, max(a.y, a.z));
    return m > 1.0 ? centre + v / m : h;
}

// A texel of the neighbourhood: colour in working YCoCg, motion (UV, finite) and linear depth.
struct Neighbour {
    vec3 colour;
    vec2 motion;
    float depth;
};

Neighbour loadNeighbour(ivec2 q, float exposure) {
    return Neighbour(rgbToYCoCg(toWorking(imageLoad(uCurrent, q).rgb, exposure)),
                     finiteMotion(imageLoad(uMotion, q).rg), kHasDepth ? imageLoad(uDepth, q).r : 0.0);
}

// The work group's 8 x 8 pixels and a one-pixel border, each at its image-clamped position.
const int kTile = 10;
shared vec3 sColour[kTile * kTile];
shared vec2 sMotion[kTile * kTile];
shared float sDepth[kTile * kTile];

// Pixel p's neighbour p + o, clamped to the image, from the tile or loaded.
Neighbour neighbour(ivec2 p, ivec2 o, ivec2 size, float exposure) {
    if (kSharedTile) {
        ivec2 t = ivec2(gl_LocalInvocationID.xy) + 1 + o;
        int i = t.y * kTile + t.x;
        return Neighbour(sColour[i], sMotion[i], sDepth[i]);
    }
    return loadNeighbour(clamp(p + o, ivec2(0), size - 1), exposure);
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uOutput);
    float exposure = max(gExposure.exposure, 1e-8);
    if (kSharedTile) { // every invocation, inside the image or not, before the barrier
        ivec2 origin = ivec2(gl_WorkGroupID.xy) * 8 - 1;
        for (int i = int(gl_LocalInvocationIndex); i < kTile * kTile; i += 64) {
            ivec2 q = clamp(origin + ivec2(i % kTile, i / kTile), ivec2(0), size - 1);
            Neighbour n = loadNeighbour(q, exposure);
            sColour[i] = n.colour;
            sMotion[i] = n.motion;
            sDepth[i] = n.depth;
        }
        barrier();
    }
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    // The centre, read once: its raw colour (a frame without history is exactly it), and its working colour,
    // motion and depth from the tile or from one load each.
    vec3 current = imageLoad(uCurrent, p).rgb;
    Neighbour centre = kSharedTile ? neighbour(p, ivec2(0), size, exposure)
                                   : Neighbour(rgbToYCoCg(toWorking(current, exposure)),
                                               finiteMotion(imageLoad(uMotion, p).rg),
                                               kHasDepth ? imageLoad(uDepth, p).r : 0.0);
    float depth = centre.depth;

    // Neighbourhood statistics in working YCoCg, and the closest surface for the motion of edges.
    vec3 m1 = vec3(0.0), m2 = vec3(0.0);
    vec3 lo = vec3(1e9), hi = vec3(-1e9);
    float closestDepth = depth;
    vec2 closestMotion = centre.motion;
    float farthestDepth = depth; // for next frame's disocclusion test; NaN counts as the sky
    const float kInfinity = uintBitsToFloat(0x7f800000u);
    float fastest2 = 0.0; // the longest motion of the 3x3, in pixels, squared
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
            Neighbour n = (x == 0 && y == 0) ? centre : neighbour(p, ivec2(x, y), size, exposure);
            vec3 c = n.colour;
            m1 += c;
            m2 += c * c;
            lo = min(lo, c);
            hi = max(hi, c);
            vec2 m = n.motion * vec2(size);
            fastest2 = max(fastest2, dot(m, m));
            if (kHasDepth) {
                float d = n.depth;
                if (d < closestDepth) {
                    closestDepth = d;
                    closestMotion = n.motion;
                }
                farthestDepth = max(farthestDepth, isnan(d) ? kInfinity : d);
            }
        }
    }
    float fastest = sqrt(fastest2);
    vec3 mean = m1 / 9.0;
    vec3 sigma = sqrt(max(m2 / 9.0 - mean * mean, vec3(0.0)));
    vec3 boxMin = max(lo, mean - uGamma * sigma);
    vec3 boxMax = min(hi, mean + uGamma * sigma);

    vec2 motion = closestMotion;
    vec2 uv = (vec2(p) + 0.5) / vec2(size);
    vec2 prevUv = uv - motion;
    bool history = uHasHistory != 0 && all(greaterThanEqual(prevUv, vec2(0.0))) && all(lessThanEqual(prevUv, vec2(1.0)));

    // Last frame's farthest depth and stability where the history is read, one load.
    ivec2 hp = clamp(ivec2(prevUv * vec2(size)), ivec2(0), size - 1);
    vec2 previousAux = history ? imageLoad(uHistoryAux, hp).rg : vec2(0.0);

    // Disocclusion: the surface seen now was not where the history was, e.g. it was behind an object that
    // moved away. With depth and the camera, the point's depth last frame is predicted and compared with the
    // depth the history stored.
    bool disoccluded = false;
    if (history && kHasDepth && kHasCamera && !isinf(depth)) {
        vec4 near = uInvProjection * vec4(uv * 2.0 - 1.0, -1.0, 1.0);
        vec3 ray = near.xyz / near.w;
        float predicted = (uViewToPreviousClip * vec4(ray * (depth / -ray.z), 1.0)).w;
        // Disoccluded means hidden last frame: every depth around the point last frame was nearer than the
        // point was. Those depths come from jittered samples (at an edge, or on a wire thinner than a pixel,
        // a pixel holds either surface from frame to frame), hence the 3x3 neighbourhood, whose farthest
        // depth the history keeps (one fetch here); a history that is farther than the point (a thin feature
        // this frame's sample hit) is not disocclusion.
        disoccluded = previousAux.r < 0.9 * predicted;
    }

    vec4 result;
    float weight = 0.0;
    // Stability: how long this pixel's neighbourhood has held still with a usable history, in [0, 1] over
    // kStableFrames. Anything moving nearby, a disocclusion or no history resets it.
    float stability = 0.0;
    if (!history || disoccluded) {
        result = vec4(current, 1.0); // exactly the current sample: a cut frame equals the no-history frame
    } else {
        vec3 fetched = kBilinearHistory ? textureLod(uHistory, prevUv, 0.0).rgb
                                             : sampleHistoryCatmullRom(prevUv, vec2(size));
        vec3 h = rgbToYCoCg(toWorking(sanitize(fetched), exposure));
        vec3 c = centre.colour;
        // The variance box can exclude the centre sample itself (a thin dark pole among bright neighbours):
        // keep it inside, or a history equal to this frame would be pulled away from it.
        boxMin = min(boxMin, c);
        boxMax = max(boxMax, c);
        // Clip unless the neighbourhood has held still for a while. There the history is this surface's own,
        // and clipping it against one jittered frame would erase thin features that this frame's samples
        // happen to miss (poles and wires break into dashes). Where something moved lately (the trail a
        // moving object uncovers, its edges) the clip is full until the pixel has been still for
        // kStableFrames, so a ghost left in the history is clipped away first. Without depth there is no
        // disocclusion test to fall back on, so the clip stays full everywhere.
        float previousStability = previousAux.g;
        stability = fastest < uStillPixels ? min(previousStability + 1.0 / kStableFrames, 1.0) : 0.0;
        float clipStrength = (kHasDepth && kHasCamera) ? 1.0 - previousStability : 1.0;
        h = mix(h, clipToBox(boxMin, boxMax, h), clipStrength);
        weight = uBlend;
        if (uAdaptive != 0) {
            // Where the clipped history and the current sample agree in luma, keep the history longer.
            float difference = abs(c.x - h.x) / max(c.x, max(h.x, 0.2));
            float agreement = 1.0 - difference;
            weight = mix(uFeedbackMin, uFeedbackMax, agreement * agreement);
        }
        vec3 resolved = fromWorking(yCoCgToRgb(mix(c, h, weight)), exposure);
        result = vec4(sanitize(resolved), 1.0);
    }
    imageStore(uOutput, p, result);
    imageStore(uOutputAux, p, vec4(farthestDepth, stability, 0.0, 0.0));
    if (uWriteDebug != 0) {
        imageStore(uDebug, p, vec4(weight, disoccluded ? 1.0 : 0.0, 0.0, 0.0));
    }
}
