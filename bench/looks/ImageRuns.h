#pragma once
// Part 2 and 3 of the looks measure: images through the real pipeline (the photopic CLI, stills preset), the
// share of crushed and clipped pixels, contact sheets and crops of light sources.

#include "Variants.h"

#include "core/Image.h"

#include <filesystem>
#include <string>
#include <vector>

namespace looks {

enum class Exposure {
    Fixed, ///< the stills preset's own: auto exposure off, tonemapping.exposure 0 EV
    Auto,  ///< autoExposure.enabled=true (a still's first reading snaps, so one frame is the converged one)
};

struct CliRun {
    std::filesystem::path cli;     ///< the photopic executable
    std::filesystem::path workDir; ///< where the PNGs of each run go (a temporary folder)
};

/// `input` through `photopic image --preset stills` with the variant's curve, bloom on or off; the PNG read
/// back as stored 8-bit sRGB. Throws std::runtime_error naming the input when the CLI fails.
[[nodiscard]] photopic::Image8 renderWithCli(const CliRun& run, const std::filesystem::path& input,
                                             const Variant& variant, Exposure exposure, bool bloom);

struct ClipShare {
    double crushedPercent = 0; ///< pixels whose every channel is below code 10
    double clippedPercent = 0; ///< pixels with any channel above code 250
};
[[nodiscard]] ClipShare clipShare(const photopic::Image8& image);

/// A 480x270 scene made for this measure: a ColorChecker, six saturated lights and exposure ramps of skin,
/// sky and red (ImageRuns.cpp draws it).
[[nodiscard]] photopic::ImageF makeSyntheticScene();
/// The centre of the red light of makeSyntheticScene.
inline constexpr int kSyntheticLightX = 287, kSyntheticLightY = 46;
/// Its crop's centre: 14 px right of the core, so the 28 px crop runs from the core (+9 EV) to 0 EV.
inline constexpr int kSyntheticCropX = kSyntheticLightX + 14;

/// The pixel of the highest Rec.709 luminance (the first one in scan order on a tie).
[[nodiscard]] std::pair<int, int> brightestPixel(const photopic::ImageF& image);

/// `image` box-filtered (in linear light) to `width` pixels wide, aspect kept.
[[nodiscard]] photopic::Image8 shrink(const photopic::Image8& image, int width);
/// The `size` x `size` square around (cx, cy), moved inside the image, enlarged 4x by pixel repetition.
[[nodiscard]] photopic::Image8 crop4x(const photopic::Image8& image, int cx, int cy, int size);
inline constexpr int kTileGutter = 2;
/// Cells of one size in rows of `columns`, kTileGutter px black gutters; unused cells stay black.
[[nodiscard]] photopic::Image8 tile(const std::vector<photopic::Image8>& cells, int columns);

} // namespace looks
