#pragma once
// Telemetry CSV written as frames finish: each row goes to disk when its frame's record comes back from the
// GPU, so memory stays flat over a run of any length. The file appears, whole, only at commit().

#include "io/ImageIO.h"
#include "pipeline/Pipeline.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace photopic::cli {

/// Columns: frame,time_s, then the scene's own columns (if any), then the exposure columns, whose first four
/// are measured_luma,target_log2,applied_log2,exposure (see telemetryCsv in Commands.h).
class TelemetryCsv {
public:
    /// Frames whose records may be waiting before take() collects them (a bound on what is held).
    static constexpr std::uint64_t kDrainEvery = 64;

    /// Opens the file's temporary at once, so an unwritable path fails (InputError naming it) before any
    /// frame is rendered.
    TelemetryCsv(const std::filesystem::path& path, float dt, std::vector<std::string> sceneColumns);

    /// Frames numbered below `frame` get no row (--preroll's frames, processed only to warm the histories).
    void skipFramesBefore(std::uint64_t frame) { mFirstFrame = frame; }
    /// The scene's values for `frame`, held until that frame's row is written.
    void sceneValues(std::uint64_t frame, std::vector<double> values);
    /// Called with each record and its scene values as its row is written (analysis that needs them).
    using RowObserver = std::function<void(const ExposureTelemetry&, const std::vector<double>&)>;
    /// After frame `frame` was executed: writes the rows that have come back. Every kDrainEvery frames, and
    /// when `last`, it waits for all of them (Pipeline::drainTelemetry), which bounds what is held.
    void take(Pipeline& pipeline, std::uint64_t frame, bool last, const RowObserver& observer = {});
    /// Publishes the file; throws unless exactly `frames` rows were written (a dropped record is an error).
    void commit(std::uint64_t frames, std::uint64_t dropped);
    [[nodiscard]] std::uint64_t rows() const { return mRows; }

private:
    AtomicFileWriter mFile;
    float mDt;
    std::vector<std::string> mSceneColumns;
    std::map<std::uint64_t, std::vector<double>> mPending;
    std::uint64_t mRows = 0;
    std::uint64_t mFirstFrame = 0;
};

} // namespace photopic::cli
