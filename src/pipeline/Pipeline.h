#pragma once
// The orchestrator: owns the passes and the frame's resources and runs them in the frame order below. It
// sequences; pass logic lives in src/passes/<name>/.
//
// Frame order (DESIGN.md, normative). Implemented steps are marked [x]; the rest arrive with their issues.
//   HDR domain (scene-referred, linear, RGBA16F):
//   [x] 1. sanitise the host's colour (NaN, +-Inf, negatives -> 0; clamp below the half-float maximum)
//   [ ] 2. scene-space effects (SSAO, contact shadows, SSR, volumetric light)
//   [ ] 3. TAA
//   [ ] 4. metering and exposure adaptation (GPU-resident; manual exposure is written to the same state)
//   [ ] 5. depth of field, motion blur
//   [x] 6. bloom on exposed colour (prefilter + Karis, 13-tap downsample chain, tent upsample chain)
//   [x] 7. composite: colour x exposure + bloom; colour grading in HDR   } one "uber" pass with step 9
//   [ ] 8. scene-value debug views
//   Display domain:
//   [x] 9. tone mapping, exactly once, + sRGB output transform + dither
//   [x] 10. FXAA
//   [x] 11. lens flare (its own HDR buffers), then chromatic aberration, flare composite, dazzle, vignette,
//           grain fused into one pass
//   [ ] 12. overlays
// Quality tiers (core/Quality.h) choose sizes and which steps run; `legacy`, and any GPU without RGBA16F
// render targets, take the LDR path: steps 1, 6 and the lens flare are skipped.

#include "core/Image.h"
#include "core/Settings.h"
#include "gl/Capabilities.h"
#include "gl/GpuTimers.h"
#include "gl/Objects.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace photopic {

/// What the host hands the pipeline each frame. Textures are the host's: adopted, never owned.
struct FrameInputs {
    const Texture* color = nullptr; ///< scene-referred linear Rec.709 colour, any float format
};

/// Time comes from the caller, never from a wall clock (seed 000's TimeManager rule).
struct FrameTime {
    float dt = 1.0f / 30.0f;      ///< seconds since the previous frame
    std::uint64_t frameIndex = 0; ///< monotonically increasing; drives dither/grain patterns
};

/// What the pipeline is doing, for hosts, logs and the CLI (DESIGN.md: degradations are never silent).
struct PipelineTelemetry {
    ColorPath path = ColorPath::Hdr; ///< the path frames take now (quality=legacy forces LDR)
    std::string pathReason;          ///< why
    Quality quality = Quality::High;
    int bloomLevels = 0;            ///< levels the last frame's bloom chain ran (0: no bloom)
    std::vector<PassTiming> passes; ///< the most recent frame with GPU timings available
};

struct PipelineCreateInfo {
    Settings settings;
    bool forceLdr = false; ///< take the LDR path whatever the GPU can do
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

    /// Runs one frame; returns the display image (RGBA8 holding sRGB-encoded values), valid until the next
    /// call.
    const Texture& execute(const FrameInputs& inputs, const FrameTime& time);
    /// The last frame's exposed scene-referred image just before tone mapping (RGBA32F), rendered on demand.
    const Texture& sceneReferred();

    /// Per-pass GPU timings, collected without stalling.
    [[nodiscard]] GpuTimers& timers() { return mTimers; }
    [[nodiscard]] PipelineTelemetry telemetry() const;

private:
    struct Passes;
    void resize(Extent extent);

    Settings mSettings;
    Capabilities mCaps;
    std::unique_ptr<Passes> mPasses;
    Buffer mExposureState;
    GpuTimers mTimers;
    Extent mExtent;
    const Texture* mLastScene = nullptr;
    const Texture* mLastBloom = nullptr;
    int mBloomLevels = 0;
    std::uint64_t mLastFrame = 0;
};

/// Convenience for offline use (CLI, tests, examples): one image through the pipeline, read back.
Image8 processImage(Pipeline& pipeline, const ImageF& image, const FrameTime& time = {});

} // namespace photopic
