#pragma once
// Every setting of the pipeline, one typed struct per effect, gathered here: an effect's settings header
// sits beside its pass (src/passes/<effect>/<Effect>Settings.h), the rest in core/settings/.
// JSON: {"version": 1, "postEffects": {<key>: {...}}} with the keys below.

#include "core/settings/AntiAliasingSettings.h"
#include "core/settings/AutoExposureSettings.h"
#include "core/settings/ColorGradingSettings.h"
#include "core/settings/DebugSettings.h"
#include "core/settings/ExposureModeSettings.h"
#include "core/settings/OutputSettings.h"
#include "core/settings/QualitySettings.h"
#include "core/settings/SubjectSettings.h"
#include "core/settings/TemporalSettings.h"
#include "core/settings/ToneMappingSettings.h"
#include "passes/bloom/BloomSettings.h"
#include "passes/contactshadows/ContactShadowsSettings.h"
#include "passes/display/DisplaySettings.h"
#include "passes/dof/DofSettings.h"
#include "passes/fxaa/FxaaSettings.h"
#include "passes/gtao/GtaoSettings.h"
#include "passes/lensflare/LensFlareSettings.h"
#include "passes/motionblur/MotionBlurSettings.h"
#include "passes/outline/OutlineSettings.h"
#include "passes/smaa/SmaaSettings.h"
#include "passes/ssr/SsrSettings.h"
#include "passes/taa/TaaSettings.h"
#include "passes/volumetriclight/VolumetricLightSettings.h"

#include <optional>
#include <span>
#include <string_view>

namespace photopic {

/// Names of the presets, in the order `--help` lists them: stills, realtime, neutral.
[[nodiscard]] std::span<const std::string_view> presetNames();

struct Settings {
    ToneMappingSettings tonemapping;
    OutputSettings output;
    AutoExposureSettings autoExposure;
    DebugSettings debug;
    Quality quality = Quality::High;
    BloomSettings bloom;
    ColorGradingSettings colorGrading;
    FxaaSettings fxaa;
    LensFlareSettings lensFlare;
    VignetteSettings vignette;
    GrainSettings grain;
    DazzleSettings dazzle;
    SubjectSettings subjects;
    TemporalSettings temporal;
    AntiAliasingSettings aa;
    TaaSettings taa;
    SmaaSettings smaa;
    GtaoSettings gtao;
    ContactShadowsSettings contactShadows;
    DofSettings dof;
    ExposureModeSettings exposure;
    SsrSettings ssr;
    MotionBlurSettings motionBlur;
    OutlineSettings outline;
    VolumetricLightSettings volumetricLight;

    /// Named looks (`--preset NAME`, a settings file's "preset"). A look is the tone curve (tonemapping.mode
    /// and agxLook), bloom, lens flare, vignette, grain, dazzle and colour grading; the rest (exposure,
    /// metering, anti-aliasing, the 3D effects) belongs to the host or the scene, and applyLook() leaves it as
    /// it was.
    /// stills: photographs (`photopic image`'s default): AgX, a tight bloom of what is far past white only.
    [[nodiscard]] static Settings stills();
    /// realtime: the defaults, the look of games and the built-in scenes: ACES (fitted), a soft glow over the
    /// whole image.
    [[nodiscard]] static Settings realtime();
    /// neutral: no bloom, no display effects, no grading: exposure and the tone curve alone, for measuring.
    [[nodiscard]] static Settings neutral();
    /// The preset called `name`; nullopt when there is none (presetNames() lists them).
    [[nodiscard]] static std::optional<Settings> preset(std::string_view name);
    /// Takes `look`'s look (the fields above) and keeps everything else.
    void applyLook(const Settings& look);

    /// The anti-aliasing the frame uses: aa.mode, or FXAA / TAA when their older switches are on and aa.mode
    /// is none.
    [[nodiscard]] AntiAliasing antiAliasing() const noexcept {
        if (aa.mode != AntiAliasing::None) {
            return aa.mode;
        }
        if (taa.enabled) {
            return AntiAliasing::Taa;
        }
        return fxaa.enabled ? AntiAliasing::Fxaa : AntiAliasing::None;
    }
    /// Whether that anti-aliasing gathers over frames: taa or taa+smaa.
    [[nodiscard]] bool temporalAntiAliasing() const noexcept {
        const AntiAliasing a = antiAliasing();
        return a == AntiAliasing::Taa || a == AntiAliasing::TaaSmaa;
    }

    template <class V>
    void visit(V& v) {
        v.object("tonemapping", tonemapping);
        v.object("output", output);
        v.object("autoExposure", autoExposure);
        v.object("debug", debug);
        v.field("quality", quality, qualityNames(), "tier of every effect's cost; legacy is the LDR path");
        v.object("bloom", bloom);
        v.object("colorGrading", colorGrading);
        v.object("fxaa", fxaa);
        v.object("lensFlare", lensFlare);
        v.object("vignette", vignette);
        v.object("grain", grain);
        v.object("dazzle", dazzle);
        v.object("subjects", subjects);
        v.object("temporal", temporal);
        v.object("aa", aa);
        v.object("taa", taa);
        v.object("smaa", smaa);
        v.object("ssao", gtao); // the JSON key users write
        v.object("contactShadows", contactShadows);
        v.object("dof", dof);
        v.object("exposure", exposure);
        v.object("ssr", ssr);
        v.object("motionBlur", motionBlur);
        v.object("outline", outline);
        v.object("volumetricLight", volumetricLight);
    }
};

} // namespace photopic
