#include "TelemetryCsv.h"

#include "Commands.h"

#include <fmt/format.h>

namespace photopic::cli {

namespace {

AtomicFileWriter openOutput(const std::filesystem::path& path) {
    try {
        return AtomicFileWriter(path);
    } catch (const IoError& e) {
        throw InputError(fmt::format("telemetry {}", e.what()));
    }
}

} // namespace

TelemetryCsv::TelemetryCsv(const std::filesystem::path& path, float dt, std::vector<std::string> sceneColumns)
    : mFile(openOutput(path))
    , mDt(dt)
    , mSceneColumns(std::move(sceneColumns)) {
    mFile.write(telemetryCsv({}, mDt, mSceneColumns, {}));
}

void TelemetryCsv::sceneValues(std::uint64_t frame, std::vector<double> values) {
    if (!mSceneColumns.empty()) {
        mPending[frame] = std::move(values);
    }
}

void TelemetryCsv::take(Pipeline& pipeline, std::uint64_t frame, bool last, const RowObserver& observer) {
    if (!last && (frame + 1) % kDrainEvery != 0) {
        return;
    }
    static const std::vector<double> kNone;
    std::string text;
    for (const ExposureTelemetry& t : pipeline.drainTelemetry()) {
        if (t.frame < mFirstFrame) {
            continue;
        }
        const auto values = mPending.find(t.frame);
        const std::vector<double>& row = values == mPending.end() ? kNone : values->second;
        text += telemetryCsvRow(t, mDt, mSceneColumns.size(), row);
        if (observer) {
            observer(t, row);
        }
        if (values != mPending.end()) {
            mPending.erase(values);
        }
        ++mRows;
    }
    // A record that never came back leaves its values behind: drop everything up to this frame.
    mPending.erase(mPending.begin(), mPending.upper_bound(frame));
    mFile.write(text);
}

void TelemetryCsv::commit(std::uint64_t frames, std::uint64_t dropped) {
    if (mRows != frames) {
        throw std::runtime_error(
            fmt::format("telemetry: {} of {} frames came back ({} dropped)", mRows, frames, dropped));
    }
    mFile.commit();
}

} // namespace photopic::cli
