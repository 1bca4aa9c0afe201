#include "pipeline/FrameOrder.h"

namespace photopic {

FrameOrder::FrameOrder(const Capabilities& caps, bool keepTelemetryHistory)
    : mExposure(keepTelemetryHistory)
    , mTonemap(caps) {
    // A host that keeps every frame's telemetry gets the frame's readings even with auto exposure off.
    mMetering.setMeterForTelemetry(keepTelemetryHistory);
    // Lighting stage (3D hosts, while they shade): ambient occlusion for indirect light and contact
    // shadows for the sun read depth and normals and write ambientOcclusion / contactShadows. The post stage
    // starts from the host's inputs again (its own linear depth pass runs when a post pass needs it), so the
    // lighting stage has its own linear depth instance.
    mLighting = {
        &mLightingLinearDepth, // depth, camera -> linearDepth
        &mGtao,                // linearDepth, normals, camera -> ambientOcclusion (ssao.apply = lighting)
        &mContactShadows, // linearDepth, camera, sunDirection, normals?, motion?, objectId? -> contactShadows
    };

    // Post stage. Reads -> writes of each pass; the sequencer skips what a frame lacks the inputs for and
    // does not run what nothing reads.
    mPost = {
        // HDR domain: scene-referred, linear.
        &mSanitize,        // color -> sceneColor (NaN/Inf/negatives to 0, below the half maximum)
        &mLinearDepth,     // depth, camera -> linearDepth
        &mCameraMotion,    // linearDepth, camera -> motion (only when the host gives none)
        &mGtaoPost,        // linearDepth, normals, camera -> ambientOcclusion (ssao.apply = multiply)
        &mAoMultiply,      // sceneColor, ambientOcclusion -> sceneColor (ssao.apply = multiply)
        &mSsrPyramid,      // linearDepth -> depthPyramid (mSsr.enabled)
        &mSsr,             // sceneColor, depthPyramid, linearDepth, camera, ... -> sceneColor, reflections
        &mVolumetricLight, // sceneColor, linearDepth, camera, sunDirection, motion? -> sceneColor
        &mOutline,         // sceneColor, linearDepth, normals? -> sceneColor (mOutline.enabled)
        &mMotionBlur,      // sceneColor, motion, linearDepth -> sceneColor, velocityTiles (before-taa)
        &mSmaaHdr,         // sceneColor, exposure (last frame's) -> sceneColor (aa.mode taa+smaa)
        &mTaa,             // sceneColor, motion, exposure (last frame's), linearDepth?, camera? -> sceneColor
        &mSsrHistory,      // sceneColor -> (next frame's reflection source; mSsr.enabled)
        &mMotionBlurLate,  // the same as motionBlur, when mMotionBlur.placement is after-taa
        &mMetering,        // sceneColor -> histogram, metering, meteringMask
        &mProbes,          // sceneColor, metering -> metering (subject probes; the subject's reading)
        &mExposure,        // histogram, metering -> exposure (adaptation; telemetry readback)
        &mSubjectContexts, // exposure -> (subject contexts for the host)
        &mDof,             // sceneColor, linearDepth, camera -> sceneColor, dofCoc (depth of field)
        &mBloom,           // sceneColor, exposure -> bloom (the mip chain; not in glare mode)
        &mGlare,           // sceneColor, exposure, camera? -> bloom (mBloom.mode glare: FFT convolution)
        &mDebugView,       // scene values or 3D inputs -> debugColor (replaces the image, no tone mapping)
        // Display domain.
        &mTonemap,          // sceneColor, exposure, bloom? -> displayColor (composite, grade, curve, sRGB)
        &mFxaa,             // displayColor -> displayColor
        &mSmaa,             // displayColor -> displayColor (edges, weights: pooled)
        &mLensFlare,        // sceneColor, exposure -> lensFlare
        &mDisplayEffects,   // displayColor, exposure, lensFlare?, bloom? -> displayColor
        &mHistogramOverlay, // displayColor, histogram, exposure -> displayColor
    };

    mAll = mLighting;
    mAll.insert(mAll.end(), mPost.begin(), mPost.end());
}

} // namespace photopic
