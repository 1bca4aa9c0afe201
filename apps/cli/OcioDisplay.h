#pragma once
// `photopic image --ocio-display/--ocio-view`: the display image made by an OpenColorIO config's
// display/view transform instead of Photopic's own tone curve and sRGB output. The input is the pipeline's
// exposed scene-referred image (after exposure, bloom and grading, just before the tone curve), taken as the
// config's scene_linear role; the transform runs on the CPU.

#include "core/Image.h"

#include <filesystem>
#include <memory>
#include <string>

namespace photopic::cli {

struct OcioOptions {
    std::filesystem::path config; ///< --ocio-config FILE; empty: $OCIO
    std::string display;          ///< --ocio-display NAME; empty: the config's default display
    std::string view;             ///< --ocio-view NAME; empty: the display's default view

    /// Whether any --ocio-* option was given, which turns the OCIO output on.
    [[nodiscard]] bool requested() const { return !config.empty() || !display.empty() || !view.empty(); }
};

class OcioDisplay {
public:
    /// Loads the config (--ocio-config, else $OCIO) and builds the scene_linear -> display/view processor.
    /// Throws InputError naming the value and listing what exists: no config given, a config that cannot be
    /// read or parsed, one without a scene_linear role, an unknown display or view.
    explicit OcioDisplay(const OcioOptions& options);
    ~OcioDisplay();
    OcioDisplay(OcioDisplay&&) noexcept;
    OcioDisplay& operator=(OcioDisplay&&) noexcept;

    /// "DISPLAY / VIEW from CONFIG", for the log.
    [[nodiscard]] const std::string& description() const;

    /// `sceneReferred` through the display/view transform, each channel rounded to 8 bits after clamping to
    /// [0, 1]; alpha 255. No dither: the config's output is kept as it computes it.
    [[nodiscard]] Image8 apply(const ImageF& sceneReferred) const;
    /// apply() at 16 bits per channel (alpha 65535), for --bit-depth 16.
    [[nodiscard]] Image16 apply16(const ImageF& sceneReferred) const;

private:
    /// The transform's output, display-encoded, before quantisation.
    [[nodiscard]] std::vector<float> transform(const ImageF& sceneReferred) const;

    struct State;
    std::unique_ptr<State> mState;
};

} // namespace photopic::cli
