#include "OcioDisplay.h"

#include "Commands.h"

#include "core/ShownText.h"

#include <OpenColorIO/OpenColorIO.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace photopic::cli {

namespace OCIO = OCIO_NAMESPACE;
namespace fs = std::filesystem;

struct OcioDisplay::State {
    OCIO::ConstCPUProcessorRcPtr processor;
    std::string description;
};

namespace {

std::string joinQuoted(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names) {
        out += (out.empty() ? "'" : ", '") + n + "'";
    }
    return out.empty() ? "none" : out;
}

/// --ocio-config, else $OCIO.
fs::path configPath(const OcioOptions& options) {
    if (!options.config.empty()) {
        return options.config;
    }
    const char* env = std::getenv("OCIO");
    if (env == nullptr || *env == '\0') {
        throw InputError(
            "--ocio-display/--ocio-view need an OpenColorIO config: give --ocio-config FILE or set "
            "the OCIO environment variable");
    }
    return env;
}

OCIO::ConstConfigRcPtr loadConfig(const OcioOptions& options, const fs::path& path) {
    const std::string source = options.config.empty() ? "$OCIO" : "--ocio-config";
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        throw InputError(
            fmt::format("{}: OpenColorIO config {} does not exist or is not a file", source, path.string()));
    }
    try {
        OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromFile(path.c_str());
        config->validate();
        return config;
    } catch (const OCIO::Exception& e) {
        throw InputError(
            fmt::format("{}: OpenColorIO config {} cannot be used: {}", source, path.string(), e.what()));
    }
}

std::string pickDisplay(const OCIO::Config& config, const OcioOptions& options, const fs::path& path) {
    std::vector<std::string> displays;
    for (int i = 0; i < config.getNumDisplays(); ++i) {
        displays.emplace_back(config.getDisplay(i));
    }
    if (options.display.empty()) {
        return config.getDefaultDisplay();
    }
    if (std::find(displays.begin(), displays.end(), options.display) == displays.end()) {
        throw InputError(fmt::format("--ocio-display: config {} has no display '{}' (displays: {})",
                                     path.string(), shownText(options.display), joinQuoted(displays)));
    }
    return options.display;
}

std::string pickView(const OCIO::Config& config, const std::string& display, const OcioOptions& options,
                     const fs::path& path) {
    std::vector<std::string> views;
    for (int i = 0; i < config.getNumViews(display.c_str()); ++i) {
        views.emplace_back(config.getView(display.c_str(), i));
    }
    if (options.view.empty()) {
        return config.getDefaultView(display.c_str());
    }
    if (std::find(views.begin(), views.end(), options.view) == views.end()) {
        throw InputError(fmt::format("--ocio-view: display '{}' of config {} has no view '{}' (views: {})",
                                     shownText(display), path.string(), shownText(options.view),
                                     joinQuoted(views)));
    }
    return options.view;
}

} // namespace

OcioDisplay::OcioDisplay(const OcioOptions& options)
    : mState(std::make_unique<State>()) {
    const fs::path path = configPath(options);
    const OCIO::ConstConfigRcPtr config = loadConfig(options, path);
    if (!config->hasRole(OCIO::ROLE_SCENE_LINEAR)) {
        std::vector<std::string> roles;
        for (int i = 0; i < config->getNumRoles(); ++i) {
            roles.emplace_back(config->getRoleName(i));
        }
        throw InputError(
            fmt::format("OpenColorIO config {} has no 'scene_linear' role, which names the colour "
                        "space Photopic's scene-referred image is in (roles: {})",
                        path.string(), joinQuoted(roles)));
    }
    const std::string display = pickDisplay(*config, options, path);
    const std::string view = pickView(*config, display, options, path);
    try {
        OCIO::DisplayViewTransformRcPtr transform = OCIO::DisplayViewTransform::Create();
        transform->setSrc(OCIO::ROLE_SCENE_LINEAR);
        transform->setDisplay(display.c_str());
        transform->setView(view.c_str());
        mState->processor = config->getProcessor(transform)->getDefaultCPUProcessor();
    } catch (const OCIO::Exception& e) {
        throw InputError(fmt::format("OpenColorIO config {}: display '{}', view '{}' cannot be built: {}",
                                     path.string(), display, view, e.what()));
    }
    mState->description =
        fmt::format("OpenColorIO display '{}', view '{}' ({})", display, view, path.string());
}

OcioDisplay::~OcioDisplay() = default;
OcioDisplay::OcioDisplay(OcioDisplay&&) noexcept = default;
OcioDisplay& OcioDisplay::operator=(OcioDisplay&&) noexcept = default;

const std::string& OcioDisplay::description() const {
    return mState->description;
}

std::vector<float> OcioDisplay::transform(const ImageF& sceneReferred) const {
    std::vector<float> pixels = sceneReferred.rgba;
    OCIO::PackedImageDesc desc(pixels.data(), sceneReferred.width, sceneReferred.height, 4);
    mState->processor->apply(desc);
    return pixels;
}

namespace {

/// `pixels` (RGBA, display-encoded) quantised to `Sample`'s full range; alpha opaque.
template <class Image, class Sample>
Image quantise(const std::vector<float>& pixels, int width, int height, float maxValue) {
    Image out(width, height);
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        const float v = (i % 4 == 3) ? 1.0f : pixels[i];
        // NaN fails both comparisons of clamp's bounds here and becomes 0, not undefined behaviour.
        const float c = v > 0.0f ? std::min(v, 1.0f) : 0.0f;
        out.rgba[i] = static_cast<Sample>(std::lround(c * maxValue));
    }
    return out;
}

} // namespace

Image8 OcioDisplay::apply(const ImageF& sceneReferred) const {
    return quantise<Image8, std::uint8_t>(transform(sceneReferred), sceneReferred.width, sceneReferred.height,
                                          255.0f);
}

Image16 OcioDisplay::apply16(const ImageF& sceneReferred) const {
    return quantise<Image16, std::uint16_t>(transform(sceneReferred), sceneReferred.width,
                                            sceneReferred.height, 65535.0f);
}

} // namespace photopic::cli
