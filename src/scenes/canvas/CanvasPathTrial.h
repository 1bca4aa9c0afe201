#pragma once
// The canvas's `auto` shading: which of the two paths (tiled, full screen) to run, chosen by timing both on
// the device at hand. Both write the same bits, so the choice changes only the cost. The tiled path can lose:
// the full-screen shader already skips the specular and sparkle work where a pixel has no material (a branch
// that whole SIMD groups take together, the material being painted in regions), so tiling saves little more
// than that branch and pays for a tile list and two indirect dispatches (figures in docs/performance.md).

#include <array>
#include <optional>
#include <vector>

namespace photopic {

enum class CanvasShading;

/// The trial, free of GL (the renderer feeds it GPU times): the first frames alternate the paths; once each
/// has kSamples times, the one with the lower median is kept until restart().
class CanvasPathTrial {
public:
    static constexpr int kSamples = 3;

    /// The path to run this frame: the kept one, or during the trial the paths in turn.
    [[nodiscard]] CanvasShading take();
    /// A GPU time of one frame of `path` (tiled or full screen), in ms; results may arrive frames late.
    void record(CanvasShading path, double ms);
    /// Forgets every time (a new canvas: the costs change).
    void restart();
    /// The kept path, once the trial is over.
    [[nodiscard]] std::optional<CanvasShading> chosen() const { return mChosen; }
    /// Median ms of each path's times (tiled, full screen); 0 without times.
    [[nodiscard]] std::array<double, 2> medians() const;

private:
    std::array<std::vector<double>, 2> mTimes;
    std::optional<CanvasShading> mChosen;
    int mTaken = 0; ///< frames handed out during the trial
};

} // namespace photopic
