#pragma once
// Where the frame's exposure comes from: the manual EV (tonemapping.exposure) and auto exposure alone, or a
// physical camera's aperture, shutter time and ISO (Lagarde & de Rousiers 2014, "Moving Frostbite to PBR",
// section 5.1: EV100 = log2(N^2 / t * 100 / S), exposure = 1 / (1.2 * 2^EV100)), with auto exposure then
// acting as a compensation within its [minEV, maxEV] around the camera's exposure.

#include "core/settings/Reflect.h"

#include <array>
#include <span>
#include <string_view>

namespace photopic {

enum class ExposureMode {
    Manual,   ///< 2^(tonemapping.exposure) times auto exposure (when enabled): scene values as they are
    Physical, ///< the camera's EV100 (its lens: fNumber, exposure time or shutter angle, iso) sets exposure
};

inline std::span<const std::string_view> exposureModeNames() {
    static constexpr std::array<std::string_view, 2> kNames{"manual", "physical"};
    return kNames;
}

struct ExposureModeSettings {
    ExposureMode mode = ExposureMode::Manual;

    template <class V>
    void visit(V& v) {
        v.field(
            "mode", mode, exposureModeNames(),
            "manual or physical. Physical needs a camera (a frame without one falls back to manual, logged "
            "once): scene values are absolute luminance (cd/m^2); auto exposure, when enabled, meters the "
            "camera-exposed image and adds its correction clamped to [autoExposure.minEV, maxEV]");
    }
};

} // namespace photopic
