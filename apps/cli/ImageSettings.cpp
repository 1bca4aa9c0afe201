// The settings of a `photopic image` run (ImageSettings.h).
#include "ImageSettings.h"

#include "PlannedOutputs.h"

#include "core/Log.h"
#include "core/settings/SettingsJson.h"

#include <fmt/format.h>

#include <string>

namespace photopic::cli {

namespace fs = std::filesystem;

std::unique_ptr<Pipeline> makeImagePipeline(const PipelineCreateInfo& createInfo) {
    try {
        return std::make_unique<Pipeline>(createInfo);
    } catch (const IoError& e) { // the metering mask named in the settings
        throw InputError(fmt::format("autoExposure.mask.path: {}", e.what()));
    }
}

Settings imageSettings(const ImageOptions& options) {
    // Photographs get the stills look unless --preset or the settings file names another. An image has no
    // lighting stage to hand ambient occlusion to, so it multiplies the scene colour unless the settings
    // say otherwise: no look sets ssao.apply (Settings::applyLook), so lighting over this base is the user's.
    Settings base = Settings::stills();
    base.gtao.apply = GtaoApply::Multiply;
    Settings settings = resolveSettings(options.settings, base);
    const bool lightingAsked = settings.gtao.apply == GtaoApply::Lighting;
    if (options.bitDepth) {
        settings.output.bitDepth = *options.bitDepth;
    }
    // Said in the CLI's words; the keys are the pipeline's own, so its host-API wording stays unsaid.
    if (settings.gtao.enabled && lightingAsked) {
        warnOnce("ssao.no-lighting",
                 "ssao.apply=lighting: an image has no lighting stage to hand ambient occlusion to, so none "
                 "is applied; ssao.apply=multiply (photopic image's default) multiplies the colour by it");
    }
    if (settings.contactShadows.enabled) {
        warnOnce("contactShadows.no-lighting",
                 "contactShadows.enabled: contact shadows darken a renderer's sun term as it lights the "
                 "scene, and an image's sun is already in its colour, so photopic image cannot apply them");
    }
    return settings;
}

namespace {

/// The setting that turns on the effect a data view shows, for the error of a view that could not be made.
const char* debugViewSwitch(DebugView view) {
    switch (view) {
    case DebugView::Gtao:
        return "ssao.enabled=true";
    case DebugView::Coc:
        return "dof.enabled=true";
    case DebugView::Ssr:
        return "ssr.enabled=true";
    case DebugView::VelocityTiles:
        return "motionBlur.enabled=true";
    case DebugView::VolumetricLight:
        return "volumetricLight.enabled=true";
    case DebugView::TaaHistoryWeight:
    case DebugView::Disocclusion:
        return "aa.mode=taa";
    case DebugView::ContactShadows:
    case DebugView::ContactShadowSteps:
        return "a host's lighting stage (photopic scene; an image has none)";
    default:
        return nullptr;
    }
}

} // namespace

/// A debug view the frame cannot make is an error naming what it lacks, not the plain image the pipeline
/// would show instead.
void requireDebugViewMade(const Pipeline& pipeline, const Settings& settings, const fs::path& input) {
    if (settings.debug.view == DebugView::None)
        return;
    for (const SkippedPass& skipped : pipeline.status().skipped) {
        if (skipped.pass != "debug view")
            continue;
        std::string missing;
        for (const std::string& name : skipped.missing)
            missing += (missing.empty() ? "" : ", ") + name;
        const char* effect = debugViewSwitch(settings.debug.view);
        throw InputError(fmt::format(
            "--debug {}: {} gives the view no {}{}", debugViewNames()[std::size_t(settings.debug.view)],
            input.string(), missing, effect ? fmt::format(" (it shows what {} makes)", effect) : ""));
    }
}

/// The OpenColorIO display/view transform when --ocio-* asks for it, its config and names checked before
/// any output exists. It makes display images, so every output must be one (PNG, TIFF, JPEG).
std::optional<OcioDisplay> ocioDisplayFor(const ImageOptions& options) {
    if (!options.ocio.requested()) {
        return std::nullopt;
    }
    if (lowerExtension(options.output) == ".exr" || options.format == "exr") {
        throw InputError(
            fmt::format("output {}: --ocio-display/--ocio-view make the display image (PNG, TIFF, JPEG); "
                        "an EXR output holds the scene-referred image, which they do not change",
                        options.output.string()));
    }
    OcioDisplay ocio(options.ocio);
    logInfo("display image: {}", ocio.description());
    return ocio;
}

/// The anti-aliasing an image run cannot do, turned off with one warning that says why and what runs
/// instead (SMAA under taa+smaa, else FXAA when its switch is on, else nothing): TAA gathers each pixel over
/// earlier frames, and a single image has none; SSAA renders each frame several times, which only the
/// renderer that made the image could.
void dropUnavailableAa(Settings& settings, std::size_t inputCount) {
    const AntiAliasing asked = settings.antiAliasing();
    std::string why;
    if (asked == AntiAliasing::Ssaa) {
        why = "SSAA renders each frame several times, which only the renderer that made an image can do, so "
              "it is off for images";
    } else if (settings.temporalAntiAliasing() && inputCount == 1) {
        why = "a single image has no earlier frames for TAA to gather, so TAA is off for it";
    } else {
        return;
    }
    settings.aa.mode = asked == AntiAliasing::TaaSmaa ? AntiAliasing::Smaa : AntiAliasing::None;
    settings.taa.enabled = false;
    const AntiAliasing now = settings.antiAliasing();
    logWarning("aa.mode {}: {}; {}", antiAliasingNames()[std::size_t(asked)], why,
               now == AntiAliasing::None
                   ? std::string("no anti-aliasing runs (aa.mode smaa or fxaa anti-alias images)")
                   : fmt::format("{} runs", antiAliasingNames()[std::size_t(now)]));
}

} // namespace photopic::cli
