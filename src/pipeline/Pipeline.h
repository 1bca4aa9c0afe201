#pragma once
// The orchestrator: owns the passes and the frame's resources and runs them in the frame order below. It
// sequences; pass logic lives in src/passes/<name>/.
//
// Frame order (DESIGN.md, normative). Implemented steps are marked [x]; steps 2, 3 and 5 need depth, motion
// vectors and a camera from the host (3D scenes) and are not built yet.
//   HDR domain (scene-referred, linear, RGBA16F):
//   [x] 1. sanitise the host's colour (NaN, +-Inf, negatives -> 0; clamp below the half-float maximum)
//   [ ] 2. scene-space effects (SSAO, contact shadows, SSR, volumetric light)
//   [ ] 3. TAA
//   [x] 4. subject probes (one dispatch for every scheduled subject; results into a readback ring), then
//          metering and exposure adaptation (GPU-resident, same frame; with auto exposure off the adaptation
//          pass writes 2^manualEV to the same state; state, histogram and min/max go into the readback ring)
//   [ ] 5. depth of field, motion blur
//   [x] 6. bloom on exposed colour (prefilter + Karis, 13-tap downsample chain, tent upsample chain)
//   [x] 7. composite: colour x exposure + bloom; colour grading in HDR   } one "uber" pass with step 9
//   [x] 8. scene-value debug views (exposure, luma, ev, metering, bloom): they replace the image and skip 9
//   Display domain:
//   [x] 9. tone mapping, exactly once, + sRGB output transform + dither
//   [x] 10. FXAA
//   [x] 11. lens flare (its own HDR buffers), then chromatic aberration, flare composite, dazzle, vignette,
//           grain fused into one pass
//   [x] 12. overlays (histogram)
// Quality tiers (core/Quality.h) choose sizes and which steps run; `legacy`, and any GPU without RGBA16F
// render targets, take the LDR path: steps 1, 6 and the lens flare are skipped; with bloom.enabled, step 7
// adds a single cheap glow of the input's bright parts instead of the bloom chain.

#include "core/Camera.h"
#include "core/Image.h"
#include "core/OutdoorsMask.h"
#include "core/Settings.h"
#include "core/Subjects.h"
#include "gl/Capabilities.h"
#include "gl/GpuTimers.h"
#include "gl/Objects.h"
#include "gl/ReadbackRing.h"

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace photopic {

/// How a depth input encodes distance (docs/architecture.md, "Inputs").
enum class DepthKind {
    Standard,   ///< window depth in [0, 1] of a GL perspective projection: near -> 0, far -> 1
    Reversed,   ///< reversed-Z window depth (glClipControl zero-to-one): near -> 1, far or infinity -> 0
    LinearView, ///< R32F/R16F: positive distance along the view axis in scene units; >= far or inf = sky
};

/// How a normals input is stored. Normals are view-space unit vectors (right-handed, +z towards the viewer).
enum class NormalEncoding {
    ViewXyz,    ///< RGB(A)16F/32F holding x, y, z in [-1, 1]
    Octahedral, ///< RG16F/RG32F: octahedral encoding in [-1, 1]^2
};

/// What the host hands the pipeline each frame. Textures are the host's: adopted, never owned. Everything
/// but colour is optional; a pass that needs an input the frame lacks is skipped and reported in
/// PipelineStatus::skipped. Every texture has colour's extent.
struct FrameInputs {
    const Texture* color = nullptr; ///< scene-referred linear Rec.709 colour, any float format
    const Texture* depth = nullptr; ///< depth buffer or linear view depth, see depthKind
    DepthKind depthKind = DepthKind::Standard;
    const Texture* normals = nullptr; ///< view-space unit normals, see normalEncoding
    NormalEncoding normalEncoding = NormalEncoding::ViewXyz;
    /// RG16F/RG32F: UV-space displacement of each pixel's surface point, current minus previous frame, with
    /// both frames' jitter removed (uv_prev = uv - motion). Static scene, static camera: 0.
    const Texture* motion = nullptr;
    const Camera* camera = nullptr; ///< view, unjittered projection, previous view-projection, lens
    /// This frame's subjects (seed 000), in the host's order; read during execute(), not kept. Empty: no
    /// subject (subject metering holds exposure, or probes the screen centre with subjects.fallback =
    /// center).
    std::span<const Subject> subjects{};
    glm::vec2 viewCentreWorld{0.0f}; ///< world position under the screen centre (the centre subject's)
};

/// Time comes from the caller, never from a wall clock (seed 000's TimeManager rule).
struct FrameTime {
    float dt = 1.0f / 30.0f;      ///< seconds since the previous frame
    std::uint64_t frameIndex = 0; ///< monotonically increasing; drives dither/grain patterns
};

/// What the pipeline is doing, for hosts, logs and the CLI (DESIGN.md: degradations are never silent).
struct PipelineStatus {
    ColorPath path = ColorPath::Hdr; ///< the path frames take now (quality=legacy forces LDR)
    std::string pathReason;          ///< why
    Quality quality = Quality::High;
    int bloomLevels = 0;            ///< levels the last frame's bloom chain ran (0: no bloom)
    std::vector<PassTiming> passes; ///< the most recent frame with GPU timings available
};

/// What the lighting stage hands the host for shading. Each is null when its pass did not run this frame.
struct LightingOutputs {
    /// R8/R16F visibility in [0, 1] for indirect (ambient, IBL) light only.
    const Texture* ambientOcclusion = nullptr;
    /// R8/R16F visibility in [0, 1] for the sun's direct light only.
    const Texture* contactShadows = nullptr;
};

struct PipelineCreateInfo {
    Settings settings;
    bool forceLdr = false; ///< take the LDR path whatever the GPU can do
    /// Keep every frame's telemetry until drainTelemetry() (offline sequences: one CSV row per frame). Off
    /// for interactive hosts, which read only the newest through telemetry().
    bool keepTelemetryHistory = false;
};

/// One frame's exposure as the GPU computed it, read back through the ring (never blocking the frame).
struct ExposureTelemetry {
    bool valid = false;         ///< false until the first frame's record has arrived
    std::uint64_t frame = 0;    ///< FrameTime::frameIndex of the frame it came from
    float frameLuminance = 0;   ///< this frame's metered luminance, 0 when it had no reading
    float meteredLuminance = 0; ///< the last valid reading (what the target follows)
    float targetLog2 = 0;       ///< EV, auto exposure's target
    float appliedLog2 = 0;      ///< EV, auto exposure's adapted value
    float exposure = 1;         ///< total multiplier applied to the frame (manual x auto)
    float manualEV = 0;
    bool autoEnabled = false;
    bool adapting = false;
    bool initialized = false;
    float minLuminance = 0; ///< smallest meterable pixel luminance (0 when nothing was metered)
    float maxLuminance = 0;
    std::uint32_t histogramCount = 0; ///< pixels binned (0: no histogram this frame)
    float histogramLowLog2 = 0;       ///< percentile window, bin centres
    float histogramHighLog2 = 0;
    float histogramAverageLog2 = 0;
    std::array<std::uint32_t, 256> histogram{}; ///< this frame's bins (replaced whole, never accumulated)
};

class Pipeline {
public:
    /// Needs a current GL 4.5 context (the host's or a HeadlessContext). Throws GlError on set-up failure.
    explicit Pipeline(const PipelineCreateInfo& info = {});
    ~Pipeline();
    Pipeline(const Pipeline&) = delete;
    Pipeline& operator=(const Pipeline&) = delete;

    void setSettings(const Settings& settings);
    [[nodiscard]] const Settings& settings() const { return mSettings; }
    [[nodiscard]] const Capabilities& capabilities() const { return mCaps; }

    /// Starts a frame (two-stage use by 3D hosts): returns the sub-pixel jitter, in pixels (x right, y up),
    /// that the host adds to its projection for this frame (jitteredProjection in core/Camera.h): Halton(2,
    /// 3) with the configured cycle while a temporal pass is on, zero otherwise. `camera` may be null.
    glm::vec2 beginFrame(const FrameTime& time, const Camera* camera = nullptr);

    /// Lighting stage (3D hosts, after beginFrame, before the host shades): runs the passes whose outputs the
    /// host consumes while lighting and hands back their textures (null when that pass is off or lacks its
    /// inputs). Valid until the next call.
    const LightingOutputs& renderLighting(const FrameInputs& inputs, const FrameTime& time);

    /// Runs one frame; returns the display image (RGBA8 holding sRGB-encoded values), valid until the next
    /// call.
    const Texture& execute(const FrameInputs& inputs, const FrameTime& time);
    /// The last frame's exposed scene-referred image just before tone mapping (RGBA32F), rendered on demand.
    const Texture& sceneReferred();

    /// Per-pass GPU timings, collected without stalling.
    [[nodiscard]] GpuTimers& timers() { return mTimers; }
    /// The path, tier and latest pass timings (what `photopic info` and the bench report).
    [[nodiscard]] PipelineStatus status() const;

    /// Camera cut, teleport: the next frame's exposure snaps to its target (resize does the same).
    void resetExposure() { mResetExposure = true; }

    /// The newest exposure telemetry that has arrived, without blocking. When nothing new has finished, the
    /// last result is returned again (seed 004's continuity cache); `valid` is false before the first.
    const ExposureTelemetry& telemetry();
    /// Blocks until every frame in flight has reported; returns every frame's record not yet drained, oldest
    /// first (with keepTelemetryHistory, one per frame since the last drain; else only those still in
    /// flight).
    std::vector<ExposureTelemetry> drainTelemetry();
    /// Frames whose telemetry was dropped because every ring slot was in flight.
    [[nodiscard]] std::uint64_t droppedTelemetry() const { return mRing.dropped(); }
    /// Test hook (seed 004): while `ready` returns false, finished readbacks stay in flight.
    void setTelemetryReadyOverride(std::function<bool()> ready) { mRing.setReadyOverride(std::move(ready)); }

    // Subjects (seed 000's context API). Contexts are this frame's registrations with the newest probe
    // results that have come back through the readback ring (a frame or more old; never waited on). The
    // pointers are valid until the next execute() or setSettings().

    /// Registers this frame's subjects for the next execute() (for hosts that prepare the pipeline before the
    /// caller runs it, like scenes); copied into storage sized at set-up (subjects.maxSubjects), so it does
    /// not allocate. FrameInputs::subjects, when not empty, takes precedence. Cleared by execute().
    void setSubjects(std::span<const Subject> subjects, glm::vec2 viewCentreWorld = glm::vec2(0.0f)) noexcept;
    /// Outdoors values for subjects that bring none (seed 000's roof mask). Not owned; nullptr clears it.
    void setOutdoorsMask(const OutdoorsMask* mask) noexcept { mSubjects.setOutdoorsMask(mask); }
    /// Seed 000's getContextForToken: nullptr when the id was not registered this frame.
    [[nodiscard]] const SubjectContext* contextForSubject(std::uint32_t id) const noexcept {
        return mSubjects.contextForSubject(id);
    }
    /// Seed 000's getSubjectContext: the subject of the view, nullptr when there is none.
    [[nodiscard]] const SubjectContext* subjectContext() const noexcept { return mSubjects.subjectContext(); }
    /// Seed 000's getOutdoorsAtWorld: the outdoors mask at a world position, 0 without a mask.
    [[nodiscard]] float outdoorsAtWorld(float x, float y) const noexcept {
        return mSubjects.outdoorsAtWorld(x, y);
    }
    /// The tracker behind the context API (selection, every context of this frame).
    [[nodiscard]] const SubjectTracker& subjects() const { return mSubjects; }
    /// Probe results dropped because every probe readback slot was in flight.
    [[nodiscard]] std::uint64_t droppedProbes() const { return mProbeRing.dropped(); }

    /// The GPU exposure state buffer (GpuExposureState), for passes a host adds after the pipeline's.
    [[nodiscard]] const Buffer& exposureState() const { return mExposureState; }

private:
    struct Passes;
    void resize(Extent extent);
    void loadMask();
    /// The LDR path's single cheap glow runs instead of the bloom chain (legacy tier, bloom.enabled).
    [[nodiscard]] bool legacyGlow() const;
    void pollTelemetry();
    void keep(const ExposureTelemetry& record);
    void pollProbes() noexcept;
    /// Registers the frame's subjects, schedules and dispatches the probes; returns the auto exposure
    /// settings for this frame (outdoors coupling of the subject of the view applied).
    const AutoExposureSettings& runSubjects(const FrameInputs& inputs, const FrameTime& time,
                                            const Texture& scene, const Buffer& metering);
    void configureSubjects();

    Settings mSettings;
    Capabilities mCaps;
    std::unique_ptr<Passes> mPasses;
    Buffer mExposureState;
    Buffer mTelemetryRecord; ///< GpuExposureState + bins, copied on the GPU, then into the ring
    ReadbackRing mRing;
    ExposureTelemetry mTelemetry;
    std::deque<ExposureTelemetry> mHistory;
    bool mKeepHistory = false;
    bool mResetExposure = true;
    Texture mMask;
    std::string mMaskPath;
    GpuTimers mTimers;
    Extent mExtent;
    const Texture* mLastScene = nullptr;
    const Texture* mLastBloom = nullptr;
    int mBloomLevels = 0;
    std::uint64_t mLastFrame = 0;
    SubjectTracker mSubjects;
    ReadbackRing mProbeRing;
    std::vector<Subject> mPending; ///< setSubjects(), capacity subjects.maxSubjects
    std::size_t mPendingCount = 0;
    glm::vec2 mPendingCentre{0.0f};
    LightingOutputs mLighting;
    AutoExposureSettings mCoupled; ///< this frame's outdoors-coupled auto exposure (subject metering)
};

/// Convenience for offline use (CLI, tests, examples): one image through the pipeline, read back.
Image8 processImage(Pipeline& pipeline, const ImageF& image, const FrameTime& time = {});

} // namespace photopic
