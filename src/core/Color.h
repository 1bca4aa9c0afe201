#pragma once
// Colour math shared by the CPU reference and (mirrored in src/passes/common/color.h.glsl) the shaders.
//
// References:
//  - IEC 61966-2-1:1999 (sRGB): piecewise transfer function, break points 0.0031308 / 0.04045.
//  - ITU-R BT.709-6: luma weights 0.2126, 0.7152, 0.0722.
//  - S. Lagarde, C. de Rousiers, "Moving Frostbite to Physically Based Rendering 3.0", SIGGRAPH 2014
//    course notes, section 5.1 (EV100, saturation-based exposure; K = 12.5, q = 0.65 -> the 1.2 factor).

#include <glm/vec3.hpp>

namespace photopic {

/// Rec.709 relative luminance of linear Rec.709 RGB.
[[nodiscard]] float luma709(glm::vec3 linearRgb) noexcept;

/// sRGB OETF (linear -> encoded). Input is clamped to [0, 1] first.
[[nodiscard]] float srgbEncode(float linear) noexcept;
/// sRGB EOTF (encoded -> linear), the exact inverse of srgbEncode on [0, 1]. No clamp: values below the break
/// point follow the linear segment, so negative inputs map to negative outputs.
[[nodiscard]] float srgbDecode(float encoded) noexcept;
[[nodiscard]] glm::vec3 srgbEncode(glm::vec3 linear) noexcept;
[[nodiscard]] glm::vec3 srgbDecode(glm::vec3 encoded) noexcept;

/// EV100 of a camera setting: log2(N^2 / t * 100 / S). aperture is the f-number N, shutter time t in seconds,
/// sensitivity S in ISO. All three must be positive.
[[nodiscard]] float ev100FromCamera(float aperture, float shutterSeconds, float iso) noexcept;
/// EV100 that exposes an average scene luminance (cd/m^2) as a reflected-light meter does: log2(L * S / K).
/// Luminance is clamped to the smallest normal float so a black frame gives a finite (very low) EV.
[[nodiscard]] float ev100FromLuminance(float avgLuminance, float iso = 100.0f, float K = 12.5f) noexcept;
/// Saturation-based exposure scale for an EV100: 1 / (1.2 * 2^EV100), i.e. the luminance that saturates the
/// sensor (1.2 * 2^EV100) maps to 1.
[[nodiscard]] float exposureFromEv100(float ev100) noexcept;

} // namespace photopic
