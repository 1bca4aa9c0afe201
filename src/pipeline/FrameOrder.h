#pragma once
// Every pass of the frame, owned in one place, and the frame order: the lists FrameOrder.cpp writes once, in
// the order the passes run (docs/architecture.md draws them with their reads and writes).

#include "gl/Capabilities.h"
#include "passes/FramePass.h"
#include "passes/bloom/BloomPass.h"
#include "passes/contactshadows/ContactShadowsPass.h"
#include "passes/debug/DebugViewPass.h"
#include "passes/display/DisplayEffectsPass.h"
#include "passes/dof/DofPass.h"
#include "passes/exposure/ExposurePass.h"
#include "passes/fxaa/FxaaPass.h"
#include "passes/glare/GlarePass.h"
#include "passes/gtao/GtaoPass.h"
#include "passes/inputs/InputPasses.h"
#include "passes/lensflare/LensFlarePass.h"
#include "passes/metering/MeteringPass.h"
#include "passes/motionblur/MotionBlurPass.h"
#include "passes/outline/OutlinePass.h"
#include "passes/probe/ProbePass.h"
#include "passes/probe/SubjectContextsPass.h"
#include "passes/sanitize/SanitizePass.h"
#include "passes/smaa/SmaaPass.h"
#include "passes/ssr/SsrPass.h"
#include "passes/taa/TaaPass.h"
#include "passes/tonemap/TonemapPass.h"
#include "passes/volumetriclight/VolumetricLightPass.h"

#include <span>
#include <vector>

namespace photopic {

class FrameOrder {
public:
    FrameOrder(const Capabilities& caps, bool keepTelemetryHistory);
    FrameOrder(const FrameOrder&) = delete;
    FrameOrder& operator=(const FrameOrder&) = delete;

    /// Lighting stage: passes whose outputs the host reads while it shades.
    [[nodiscard]] std::span<FramePass* const> lighting() const { return mLighting; }
    /// Post stage: HDR domain, then display domain.
    [[nodiscard]] std::span<FramePass* const> post() const { return mPost; }
    /// Every pass once (configure, resize, history).
    [[nodiscard]] std::span<FramePass* const> all() const { return mAll; }

    // The passes, for the pipeline's API (telemetry, subjects, the scene-referred output, status).
    LinearDepthPass lightingLinearDepth; ///< the lighting stage's own (its linear depth is not kept for post)
    GtaoPass gtao{GtaoPass::Stage::Lighting};
    ContactShadowsPass contactShadows;
    SanitizePass sanitize;
    LinearDepthPass linearDepth;
    GtaoPass gtaoPost{GtaoPass::Stage::Post};
    AoMultiplyPass aoMultiply;
    CameraMotionPass cameraMotion;
    TaaPass taa;
    MeteringPass metering;
    ProbePass probes;
    ExposurePass exposure;
    SubjectContextsPass subjectContexts;
    BloomPass bloom;
    GlarePass glare;
    DebugViewPass debugView;
    TonemapPass tonemap;
    FxaaPass fxaa;
    SmaaPass smaaHdr{SmaaPass::Domain::Hdr};
    SmaaPass smaa{SmaaPass::Domain::Display};
    LensFlarePass lensFlare;
    DisplayEffectsPass displayEffects;
    HistogramOverlayPass histogramOverlay;
    DofPass dof;
    SsrHistoryPass ssrHistory; ///< before ssr, which reads the history it keeps
    DepthPyramidPass ssrPyramid;
    SsrPass ssr{ssrHistory};
    VolumetricLightPass volumetricLight;
    OutlinePass outline;
    MotionBlurPass motionBlur{MotionBlurPlacement::BeforeTaa};
    MotionBlurPass motionBlurLate{MotionBlurPlacement::AfterTaa};

private:
    std::vector<FramePass*> mLighting;
    std::vector<FramePass*> mPost;
    std::vector<FramePass*> mAll;
};

} // namespace photopic
