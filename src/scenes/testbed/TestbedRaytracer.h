#pragma once
// Ground truth for the testbed: a CPU ray tracer of the analytic scene (TestbedGeometry), no GL. Each kind
// is an ImageF (rows top to bottom, like every CPU image here) at a given size and frame; rows are shared
// out over std::thread workers. Conventions are the pipeline's inputs' (core/Camera.h, pipeline/Pipeline.h):
//
//   kind        channels          what
//   color       RGB, A = 1        N x N stratified supersampled colour of the local shading model
//   depth       R                 linear view depth (+inf: sky)                       } at the pixel
//   normals     RGB               view-space unit normal (0: sky)                     } centre (see
//   motion      RG                UV displacement, current minus previous (v up)      } TruthOptions::
//   objectid    R                 the object's id (0: sky)                            } jitter)
//   ao          RGB = visibility  cosine-weighted fraction of the hemisphere above the pixel-centre point
//                                 that no surface within aoRadius occludes (1: open; sky 1)
//   sun         RGB = visibility  fraction of shadow rays towards the sun's disc (sunSamples^2 of them, or
//                                 its centre) that reach it, occluders counted within sunMaxDistance (0:
//                                 any distance); 0 where the surface faces away from the sun; sky 1
//   shutter     RGB, A = 1        colour averaged over the shutter interval centred on the frame's time
//                                 (camera and objects moving), shutterTimes instants per colour sub-sample
//   thinlens    RGB, A = 1        colour through a thin lens (the camera's focus distance and f-number)
//   reflection  RGB, A = mask     radiance along the mirror direction at the pixel centre on surfaces
//                                 with metallic > 0 (A = 1 there, RGB = A = 0 elsewhere); the mirror term's
//                                 weight is the Fresnel F0 = mix(0.04, albedo, metallic)
//
// color, shutter and thinlens share their sub-pixel sample positions, so with no motion `shutter` equals
// `color` exactly, and `thinlens` tends to `color` as the aperture closes.

#include "core/Camera.h"
#include "core/Image.h"
#include "scenes/testbed/TestbedGeometry.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace photopic::testbed {

enum class TruthKind { Color, Depth, Normals, Motion, ObjectId, Ao, Sun, Shutter, ThinLens, Reflection };

[[nodiscard]] std::string_view truthKindName(TruthKind kind);
[[nodiscard]] std::optional<TruthKind> parseTruthKind(std::string_view name);
[[nodiscard]] const std::vector<TruthKind>& allTruthKinds();

/// A still camera at `eye` looking at `target` (y up), in place of the camera path.
struct FixedView {
    glm::vec3 eye{0.0f};
    glm::vec3 target{0.0f, 0.0f, -1.0f};
};

struct TruthOptions {
    int width = 160;
    int height = 90;
    FrameTimes times;       ///< the frame (frameTimes())
    double dt = 1.0 / 30.0; ///< s, the frame interval (the shutter's length follows it)
    Lens lens;              ///< f-number, shutter angle or exposure time (focal length, focus: the path's)
    float focusDistance = 0.0f; ///< scene units; 0: the camera path's (the target's, with a fixed view)
    std::optional<FixedView> fixedView; ///< a still camera instead of the path's
    /// Colour, shutter, thin lens: samples x samples per pixel; 1: one sample at the pixel centre (moved by
    /// the jitter), the rasteriser's colour.
    int samples = 16;
    /// Shutter: instants per sub-pixel position, each its own stratum of the shutter (samples^2 x
    /// shutterTimes strata in all). With samples = 1 the truth is time-supersampled at the pixel centre only:
    /// what a rasteriser's one sample per pixel sees over the shutter, with no spatial anti-aliasing.
    int shutterTimes = 1;
    float aoRadius = 1.0f;       ///< scene units
    int aoSamples = 16;          ///< aoSamples x aoSamples cosine-weighted rays per pixel
    float sunMaxDistance = 0.0f; ///< scene units; 0: any distance
    int sunSamples = 1;          ///< 1: one ray to the sun's centre; n: n x n over its disc
    int threads = 0;             ///< 0: one per hardware thread
    /// Pixels, x right, y up (Pipeline::beginFrame's): the pixel-centre kinds take the samples a rasteriser
    /// rendering with jitteredProjection(projection, jitter) takes: the image moves by the jitter, so each
    /// pixel centre sees the unjittered image at centre - jitter.
    glm::vec2 jitter{0.0f};
};

/// The Camera the truth and the rasteriser see for `options` (the path's, at the frame's camera time).
[[nodiscard]] Camera truthCamera(const TruthOptions& options);

/// The scene `offset` seconds of frame time after the frame's time, as the truth sees it (its camera, still
/// or on the path, and every object). The shutter truth's instants are the centres of shutterTimes equal
/// strata of [-shutterSeconds / 2, shutterSeconds / 2].
struct TruthInstant {
    Camera camera;
    std::vector<Primitive> primitives;
};
[[nodiscard]] TruthInstant truthInstant(const TruthOptions& options, double offset);
/// The shutter's open time in seconds: the lens's exposure time, else its shutter angle x dt.
[[nodiscard]] double shutterSeconds(const TruthOptions& options);

/// Ambient occlusion at a surface point p with unit normal n (the `ao` kind's value): the cosine-weighted
/// fraction of samples x samples stratified rays that no primitive within `radius` blocks. `salt` varies the
/// offsets within the strata.
[[nodiscard]] float ambientOcclusionAt(const std::vector<Primitive>& prims, const glm::vec3& p,
                                       const glm::vec3& n, float radius, int samples, std::uint32_t salt = 0);
/// Sun visibility at a surface point (the `sun` kind's value): 0 when n faces away from the sun, else the
/// fraction of shadow rays (one to the disc's centre, or samples x samples over it) that no primitive within
/// `maxDistance` (0: any) blocks.
[[nodiscard]] float sunVisibilityAt(const std::vector<Primitive>& prims, const glm::vec3& p,
                                    const glm::vec3& n, float maxDistance, int samples,
                                    std::uint32_t salt = 0);

/// Renders one truth kind.
[[nodiscard]] ImageF renderTruth(TruthKind kind, const TruthOptions& options);

} // namespace photopic::testbed
