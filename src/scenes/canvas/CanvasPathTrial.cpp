#include "scenes/canvas/CanvasPathTrial.h"

#include "scenes/canvas/CanvasRenderer.h"

#include <algorithm>

namespace photopic {

namespace {

std::size_t slot(CanvasShading path) {
    return path == CanvasShading::Tiled ? 0 : 1;
}

double median(std::vector<double> v) {
    if (v.empty()) {
        return 0.0;
    }
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
}

} // namespace

CanvasShading CanvasPathTrial::take() {
    if (mChosen) {
        return *mChosen;
    }
    // A path with all its times waits for the other (whose results may still be in flight).
    const bool tiledDone = int(mTimes[0].size()) >= kSamples;
    const bool fullDone = int(mTimes[1].size()) >= kSamples;
    const int turn = mTaken++;
    if (tiledDone != fullDone) {
        return tiledDone ? CanvasShading::Fullscreen : CanvasShading::Tiled;
    }
    return turn % 2 == 0 ? CanvasShading::Tiled : CanvasShading::Fullscreen;
}

void CanvasPathTrial::record(CanvasShading path, double ms) {
    if (mChosen || path == CanvasShading::Auto) {
        return;
    }
    std::vector<double>& times = mTimes[slot(path)];
    if (int(times.size()) < kSamples) {
        times.push_back(ms);
    }
    if (int(mTimes[0].size()) >= kSamples && int(mTimes[1].size()) >= kSamples) {
        const std::array<double, 2> m = medians();
        mChosen = m[0] < m[1] ? CanvasShading::Tiled : CanvasShading::Fullscreen;
    }
}

void CanvasPathTrial::restart() {
    mTimes = {};
    mChosen.reset();
    mTaken = 0;
}

std::array<double, 2> CanvasPathTrial::medians() const {
    return {median(mTimes[0]), median(mTimes[1])};
}

} // namespace photopic
