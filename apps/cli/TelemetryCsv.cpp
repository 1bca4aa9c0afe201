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

std::string exposureTelemetryHeader() {
    return "measured_luma,target_log2,applied_log2,exposure,manual_ev,metered_luma,min_luma,max_luma,"
           "histogram_count,histogram_low_log2,histogram_high_log2,histogram_average_log2";
}

std::string exposureTelemetryRow(const ExposureTelemetry& t) {
    return fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{},{:.9g},{:.9g},{:.9g}",
                       t.frameLuminance, t.targetLog2, t.appliedLog2, t.exposure, t.manualEV,
                       t.meteredLuminance, t.minLuminance, t.maxLuminance, t.histogramCount,
                       t.histogramLowLog2, t.histogramHighLog2, t.histogramAverageLog2);
}

std::string telemetryCsvRow(const ExposureTelemetry& t, float dt, std::size_t sceneColumns,
                            const std::vector<double>& sceneValues) {
    std::string row = fmt::format("{},{:.6f}", t.frame, double(t.frame) * double(dt));
    for (std::size_t c = 0; c < sceneColumns; ++c) {
        row += fmt::format(",{:.9g}", c < sceneValues.size() ? sceneValues[c] : 0.0);
    }
    return row + "," + exposureTelemetryRow(t) + "\n";
}

std::string telemetryCsv(const std::vector<ExposureTelemetry>& rows, float dt,
                         const std::vector<std::string>& sceneColumns,
                         const std::vector<std::vector<double>>& sceneValues) {
    std::string csv = "frame,time_s";
    for (const auto& c : sceneColumns) {
        csv += "," + c;
    }
    csv += "," + exposureTelemetryHeader() + "\n";
    static const std::vector<double> kNone;
    for (const ExposureTelemetry& t : rows) {
        csv += telemetryCsvRow(t, dt, sceneColumns.size(),
                               t.frame < sceneValues.size() ? sceneValues[t.frame] : kNone);
    }
    return csv;
}

} // namespace photopic::cli
