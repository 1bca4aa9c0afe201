#include "pipeline/FrameOrder.h"

namespace photopic {

FrameOrder::FrameOrder(const Capabilities& caps, bool keepTelemetryHistory)
    : exposure(keepTelemetryHistory)
    , subjectContexts(probes, exposure)
    , tonemap(caps) {
    // A host that keeps every frame's telemetry gets the frame's readings even with auto exposure off.
    metering.setMeterForTelemetry(keepTelemetryHistory);
    // Lighting stage (3D hosts, while they shade): ambient occlusion for indirect light and contact
    // shadows for the sun read depth and normals and write ambientOcclusion / contactShadows. The post stage
    // starts from the host's inputs again (its own linear depth pass runs when a post pass needs it), so the
    // lighting stage has its own linear depth instance.
    mLighting = {
        &lightingLinearDepth, // depth, camera -> linearDepth
        &gtao,                // linearDepth, normals, camera -> ambientOcclusion (ssao.apply = lighting)
        &contactShadows, // linearDepth, camera, sunDirection, normals?, motion?, objectId? -> contactShadows
    };

    // Post stage. Reads -> writes of each pass; the sequencer skips what a frame lacks the inputs for and
    // does not run what nothing reads.
    mPost = {
        // HDR domain: scene-referred, linear.
        &sanitize,        // color -> sceneColor (NaN/Inf/negatives to 0, below the half maximum)
        &linearDepth,     // depth, camera -> linearDepth
        &cameraMotion,    // linearDepth, camera -> motion (only when the host gives none)
        &gtaoPost,        // linearDepth, normals, camera -> ambientOcclusion (ssao.apply = multiply)
        &aoMultiply,      // sceneColor, ambientOcclusion -> sceneColor (ssao.apply = multiply)
        &ssrPyramid,      // linearDepth -> depthPyramid (ssr.enabled)
        &ssr,             // sceneColor, depthPyramid, linearDepth, camera, ... -> sceneColor, reflections
        &volumetricLight, // sceneColor, linearDepth, camera, sunDirection, motion? -> sceneColor
        &outline,         // sceneColor, linearDepth, normals? -> sceneColor (outline.enabled)
        &motionBlur,      // sceneColor, motion, linearDepth -> sceneColor, velocityTiles (before-taa)
        &smaaHdr,         // sceneColor, exposure (last frame's) -> sceneColor (aa.mode taa+smaa)
        &taa,             // sceneColor, motion, exposure (last frame's), linearDepth?, camera? -> sceneColor
        &ssrHistory,      // sceneColor -> (next frame's reflection source; ssr.enabled)
        &motionBlurLate,  // the same as motionBlur, when motionBlur.placement is after-taa
        &metering,        // sceneColor -> histogram, metering, meteringMask
        &probes,          // sceneColor, metering -> metering (subject probes; the subject's reading)
        &exposure,        // histogram, metering -> exposure (adaptation; telemetry readback)
        &subjectContexts, // exposure -> (subject contexts for the host)
        &dof,             // sceneColor, linearDepth, camera -> sceneColor, dofCoc (depth of field)
        &bloom,           // sceneColor, exposure -> bloom (the mip chain; not in glare mode)
        &glare,           // sceneColor, exposure, camera? -> bloom (bloom.mode glare: FFT convolution)
        &debugView,       // scene values or 3D inputs -> debugColor (replaces the image, no tone mapping)
        // Display domain.
        &tonemap,          // sceneColor, exposure, bloom? -> displayColor (composite, grade, curve, sRGB)
        &fxaa,             // displayColor -> displayColor
        &smaa,             // displayColor -> displayColor (edges, weights: pooled)
        &lensFlare,        // sceneColor, exposure -> lensFlare
        &displayEffects,   // displayColor, exposure, lensFlare?, bloom? -> displayColor
        &histogramOverlay, // displayColor, histogram, exposure -> displayColor
    };

    mAll = mLighting;
    mAll.insert(mAll.end(), mPost.begin(), mPost.end());
}

} // namespace photopic
