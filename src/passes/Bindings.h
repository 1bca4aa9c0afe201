#pragma once
// Binding indices and GPU struct mirrors shared by C++ and GLSL (STYLE.md: one header for both).
// The same numbers are injected into every shader as #defines (see bindingDefines()).

#include "gl/ShaderLibrary.h"

#include <cstddef>

namespace photopic {

inline constexpr unsigned kBindingExposureState = 0; ///< SSBO: GpuExposureState
inline constexpr unsigned kBindingHistogram = 1;     ///< SSBO: histogram bins
inline constexpr unsigned kBindingMetering = 2;      ///< SSBO: metering scratch

/// std430 mirror of passes/common/exposure.h.glsl.
struct GpuExposureState {
    float appliedLog2 = 0;
    float targetLog2 = 0;
    float meteredLuminance = 0;
    float exposure = 1;
    int adapting = 0;
    int initialized = 0;
    float manualEV = 0;
    float pad0 = 0;
};
static_assert(sizeof(GpuExposureState) == 32);
static_assert(offsetof(GpuExposureState, exposure) == 12);
static_assert(offsetof(GpuExposureState, manualEV) == 24);

/// #defines every shader gets: the binding indices above.
ShaderDefines bindingDefines(ShaderDefines extra = {});

} // namespace photopic
