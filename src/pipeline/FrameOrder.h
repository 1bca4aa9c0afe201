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

    // The passes whose state the pipeline's API reads (telemetry, subjects, the scene-referred output, the
    // status). The frame itself reaches them only through the resources and the context.
    [[nodiscard]] ExposurePass& exposure() noexcept { return mExposure; }
    [[nodiscard]] ProbePass& probes() noexcept { return mProbes; }
    [[nodiscard]] TonemapPass& tonemap() noexcept { return mTonemap; }
    [[nodiscard]] const DebugViewPass& debugView() const noexcept { return mDebugView; }
    [[nodiscard]] const BloomPass& bloom() const noexcept { return mBloom; }
    [[nodiscard]] const SanitizePass& sanitize() const noexcept { return mSanitize; }

private:
    LinearDepthPass
        mLightingLinearDepth; ///< the lighting stage's own (its linear depth is not kept for post)
    GtaoPass mGtao{GtaoPass::Stage::Lighting};
    ContactShadowsPass mContactShadows;
    SanitizePass mSanitize;
    LinearDepthPass mLinearDepth;
    GtaoPass mGtaoPost{GtaoPass::Stage::Post};
    AoMultiplyPass mAoMultiply;
    CameraMotionPass mCameraMotion;
    TaaPass mTaa;
    MeteringPass mMetering;
    ProbePass mProbes;
    ExposurePass mExposure;
    SubjectContextsPass mSubjectContexts;
    BloomPass mBloom;
    GlarePass mGlare;
    DebugViewPass mDebugView;
    TonemapPass mTonemap;
    FxaaPass mFxaa;
    SmaaPass mSmaaHdr{SmaaPass::Domain::Hdr};
    SmaaPass mSmaa{SmaaPass::Domain::Display};
    LensFlarePass mLensFlare;
    DisplayEffectsPass mDisplayEffects;
    HistogramOverlayPass mHistogramOverlay;
    DofPass mDof;
    SsrHistoryPass mSsrHistory; ///< publishes ssrHistory, last frame's image, which ssr reads
    DepthPyramidPass mSsrPyramid;
    SsrPass mSsr;
    VolumetricLightPass mVolumetricLight;
    OutlinePass mOutline;
    MotionBlurPass mMotionBlur{MotionBlurPlacement::BeforeTaa};
    MotionBlurPass mMotionBlurLate{MotionBlurPlacement::AfterTaa};

    std::vector<FramePass*> mLighting;
    std::vector<FramePass*> mPost;
    std::vector<FramePass*> mAll;
};

} // namespace photopic
