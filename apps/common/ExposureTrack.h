#pragma once
// The files between the three stages of a sequence rendered in chunks (docs/farm.md): a meter file, one row
// per frame, written by `photopic meter` and read by `photopic expose`; and an exposure track, one row per
// frame, written by `photopic expose` and read by `photopic image --exposure-track`. Both are CSV with a
// first line `# photopic ...` that says how the frames were metered, so files metered or planned with other
// settings are refused rather than mixed. Columns are found by their header names.
//
// Meter file:     frame,reading,camera_log2,min_luma,max_luma,histogram_count,histogram_low_log2,
//                 histogram_high_log2,histogram_average_log2[,bin_000,...,bin_255]   (bins: histogram
//                 metering)
// Exposure track: frame,time_s,cut,reading,target_log2,applied_log2,exposure

#include "core/ExposurePlan.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace photopic {

/// A meter file's records with the metering they were made with (meteringDescription()).
struct MeterFile {
    std::string metering;
    std::vector<MeterRecord> records;
};

/// The text of a meter file.
[[nodiscard]] std::string meterCsvHeader(const std::string& metering, bool histogram);
[[nodiscard]] std::string meterCsvRow(const MeterRecord& record, float histogramLowLog2,
                                      float histogramHighLog2, float histogramAverageLog2);

/// Reads a meter file; throws std::invalid_argument naming the file, the line and the column of what is
/// wrong (a missing column, a value that is not a number, a frame given twice).
[[nodiscard]] MeterFile readMeterCsv(const std::filesystem::path& path);

/// Joins meter files into one sequence in frame order: the same frame in two files must carry the same
/// values (chunks metered twice), and every file must have the same metering; throws std::invalid_argument
/// naming the files otherwise.
[[nodiscard]] MeterFile mergeMeterFiles(const std::vector<std::filesystem::path>& paths,
                                        const std::vector<MeterFile>& files);

/// One frame of an exposure track.
struct TrackFrame {
    std::int64_t frame = 0;
    bool cut = false;
    float appliedLog2 = 0.0f; ///< EV, the auto exposure to apply
};

struct ExposureTrack {
    float fps = 0.0f; ///< the frame rate it was planned at
    std::string metering;
    std::vector<TrackFrame> frames; ///< in frame order
    /// The frame's entry, nullptr when the track has none.
    [[nodiscard]] const TrackFrame* find(std::int64_t frame) const;
};

/// The text of an exposure track.
[[nodiscard]] std::string exposureTrackCsv(const std::vector<PlannedExposure>& plan, float fps,
                                           const std::string& metering);
/// Reads an exposure track; throws std::invalid_argument naming the file, line and column.
[[nodiscard]] ExposureTrack readExposureTrack(const std::filesystem::path& path);

} // namespace photopic
