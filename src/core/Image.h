#pragma once
// CPU images: the currency between io, the CLI, scenes and tests. No GL here.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace photopic {

/// Linear RGBA float image, rows top to bottom, 4 floats per pixel (scene-referred unless stated).
struct ImageF {
    int width = 0;
    int height = 0;
    std::vector<float> rgba; ///< width * height * 4 floats

    ImageF() = default;
    ImageF(int w, int h, float fill = 0.0f)
        : width(w)
        , height(h)
        , rgba(std::size_t(w) * std::size_t(h) * 4, fill) {}

    [[nodiscard]] bool empty() const { return width <= 0 || height <= 0; }
    [[nodiscard]] std::size_t pixelCount() const { return std::size_t(width) * std::size_t(height); }
    float* at(int x, int y) {
        return rgba.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
    }
    [[nodiscard]] const float* at(int x, int y) const {
        return rgba.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
    }
};

/// Linear RGBA image of half floats (IEEE binary16 bits, core/HalfFloat.h), rows top to bottom: a colour
/// whose every value is a half exactly (an OpenEXR file's half channels as stored), in half an ImageF's
/// memory.
struct ImageH {
    int width = 0;
    int height = 0;
    std::vector<std::uint16_t> rgba; ///< width * height * 4 halves

    [[nodiscard]] bool empty() const { return width <= 0 || height <= 0; }
    [[nodiscard]] std::size_t pixelCount() const { return std::size_t(width) * std::size_t(height); }
};

/// 8-bit RGBA image (display-referred, sRGB-encoded), rows top to bottom.
struct Image8 {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba; ///< width * height * 4 bytes

    Image8() = default;
    Image8(int w, int h, std::uint8_t fill = 0)
        : width(w)
        , height(h)
        , rgba(std::size_t(w) * std::size_t(h) * 4, fill) {}

    [[nodiscard]] bool empty() const { return width <= 0 || height <= 0; }
    std::uint8_t* at(int x, int y) {
        return rgba.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
    }
    [[nodiscard]] const std::uint8_t* at(int x, int y) const {
        return rgba.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
    }
};

/// 16-bit RGBA image (display-referred, sRGB-encoded, 0..65535), rows top to bottom: the display image at
/// output.bitDepth 16.
struct Image16 {
    int width = 0;
    int height = 0;
    std::vector<std::uint16_t> rgba; ///< width * height * 4 samples

    Image16() = default;
    Image16(int w, int h, std::uint16_t fill = 0)
        : width(w)
        , height(h)
        , rgba(std::size_t(w) * std::size_t(h) * 4, fill) {}

    [[nodiscard]] bool empty() const { return width <= 0 || height <= 0; }
    std::uint16_t* at(int x, int y) {
        return rgba.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
    }
    [[nodiscard]] const std::uint16_t* at(int x, int y) const {
        return rgba.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
    }
};

} // namespace photopic
