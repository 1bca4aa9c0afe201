#include "common/ExposureTrack.h"

#include "core/Csv.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string_view>

namespace photopic {

namespace {

constexpr std::string_view kMeterMagic = "# photopic meter 1";
constexpr std::string_view kTrackMagic = "# photopic exposure track 1";
constexpr const char* kMeterColumns = "frame,reading,camera_log2,min_luma,max_luma,histogram_count,"
                                      "histogram_low_log2,histogram_high_log2,histogram_average_log2";

/// A CSV file of this project's: the `# photopic ...` line, the header, the rows; errors say file:line.
class CsvReader {
public:
    CsvReader(const std::filesystem::path& path, std::string_view magic)
        : mPath(path) {
        std::ifstream in(path, std::ios::binary);
        if (!in) {
            throw std::invalid_argument(fmt::format("{}: cannot be read", path.string()));
        }
        std::string line;
        while (std::getline(in, line)) {
            if (!line.empty() && line.back() == '\r') {
                line.pop_back();
            }
            mLines.push_back(std::move(line));
        }
        if (mLines.empty() || !mLines[0].starts_with(magic)) {
            throw std::invalid_argument(
                fmt::format("{}: not a file of this kind: its first line should start with \"{}\"",
                            path.string(), magic));
        }
        // "# photopic meter 1; metering: histogram ...; fps: 24"
        std::string_view rest = std::string_view(mLines[0]).substr(magic.size());
        while (!rest.empty()) {
            const std::size_t semi = rest.find("; ");
            std::string_view item = rest.substr(0, semi);
            rest = semi == std::string_view::npos ? std::string_view() : rest.substr(semi + 2);
            if (item.starts_with("; ")) {
                item.remove_prefix(2);
            }
            const std::size_t colon = item.find(": ");
            if (colon != std::string_view::npos) {
                mAttributes[std::string(item.substr(0, colon))] = std::string(item.substr(colon + 2));
            }
        }
        if (mLines.size() < 2) {
            throw std::invalid_argument(fmt::format("{}: no header line", path.string()));
        }
        const auto names = splitCsvLine(mLines[1]);
        for (std::size_t i = 0; i < names.size(); ++i) {
            mColumns[std::string(names[i])] = i;
        }
    }

    [[nodiscard]] std::string attribute(const std::string& key) const {
        const auto it = mAttributes.find(key);
        if (it == mAttributes.end()) {
            throw std::invalid_argument(
                fmt::format("{}: line 1 names no \"{}\": the file was not written by this version",
                            mPath.string(), key));
        }
        return it->second;
    }
    [[nodiscard]] bool hasColumn(const std::string& name) const { return mColumns.contains(name); }
    [[nodiscard]] std::size_t column(const std::string& name) const {
        const auto it = mColumns.find(name);
        if (it == mColumns.end()) {
            throw std::invalid_argument(
                fmt::format("{}: the header has no column \"{}\"", mPath.string(), name));
        }
        return it->second;
    }
    /// Calls `row(fields, lineNumber)` for each data line (blank lines skipped).
    template <class F>
    void rows(F&& row) const {
        for (std::size_t i = 2; i < mLines.size(); ++i) {
            if (mLines[i].empty()) {
                continue;
            }
            const auto fields = splitCsvLine(mLines[i]);
            if (fields.size() != mColumns.size()) {
                throw std::invalid_argument(fmt::format("{}:{}: {} fields where the header has {}",
                                                        mPath.string(), i + 1, fields.size(),
                                                        mColumns.size()));
            }
            row(fields, i + 1);
        }
    }
    template <class T>
    [[nodiscard]] T number(const std::vector<std::string_view>& fields, const std::string& name,
                           std::size_t line) const {
        const std::string_view text = fields[column(name)];
        T value{};
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec != std::errc() || end != text.data() + text.size() || text.empty()) {
            throw std::invalid_argument(fmt::format("{}:{}: column {}: \"{}\" is not a number", mPath.string(),
                                                    line, name, text.substr(0, 40)));
        }
        if constexpr (std::is_floating_point_v<T>) {
            if (!std::isfinite(value)) {
                throw std::invalid_argument(fmt::format("{}:{}: column {}: {} is not finite", mPath.string(),
                                                        line, name, text.substr(0, 40)));
            }
        }
        return value;
    }
    [[nodiscard]] const std::filesystem::path& path() const { return mPath; }

private:
    std::filesystem::path mPath;
    std::vector<std::string> mLines;
    std::map<std::string, std::string> mAttributes;
    std::map<std::string, std::size_t> mColumns;
};

std::string binName(int bin) {
    return fmt::format("bin_{:03d}", bin);
}

bool sameRecord(const MeterRecord& a, const MeterRecord& b) {
    return a.reading == b.reading && a.cameraLog2 == b.cameraLog2 && a.minLuminance == b.minLuminance &&
           a.maxLuminance == b.maxLuminance && a.histogram.has_value() == b.histogram.has_value() &&
           (!a.histogram || a.histogram->bins == b.histogram->bins);
}

} // namespace

std::string meterCsvHeader(const std::string& metering, bool histogram) {
    std::string text = fmt::format("{}; metering: {}\n{}", kMeterMagic, metering, kMeterColumns);
    for (int b = 0; histogram && b < kHistogramBins; ++b) {
        text += ',';
        text += binName(b);
    }
    return text + "\n";
}

std::string meterCsvRow(const MeterRecord& r, float histogramLowLog2, float histogramHighLog2,
                        float histogramAverageLog2) {
    std::uint64_t count = 0;
    if (r.histogram) {
        for (const std::uint32_t n : r.histogram->bins) {
            count += n;
        }
    }
    std::string row = fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{},{:.9g},{:.9g},{:.9g}", r.frame, r.reading,
                                  r.cameraLog2, r.minLuminance, r.maxLuminance, count, histogramLowLog2,
                                  histogramHighLog2, histogramAverageLog2);
    if (r.histogram) {
        for (const std::uint32_t n : r.histogram->bins) {
            row += fmt::format(",{}", n);
        }
    }
    return row + "\n";
}

MeterFile readMeterCsv(const std::filesystem::path& path) {
    const CsvReader csv(path, kMeterMagic);
    MeterFile file{.metering = csv.attribute("metering"), .records = {}};
    const bool histogram = csv.hasColumn(binName(0));
    csv.rows([&](const std::vector<std::string_view>& fields, std::size_t line) {
        MeterRecord r;
        r.frame = csv.number<std::int64_t>(fields, "frame", line);
        r.reading = csv.number<float>(fields, "reading", line);
        r.cameraLog2 = csv.number<float>(fields, "camera_log2", line);
        r.minLuminance = csv.number<float>(fields, "min_luma", line);
        r.maxLuminance = csv.number<float>(fields, "max_luma", line);
        if (histogram) {
            Histogram h;
            for (int b = 0; b < kHistogramBins; ++b) {
                h.bins[std::size_t(b)] = csv.number<std::uint32_t>(fields, binName(b), line);
            }
            r.histogram = h;
        }
        if (!file.records.empty() && r.frame <= file.records.back().frame) {
            throw std::invalid_argument(fmt::format("{}:{}: frame {} after frame {}: frames must increase",
                                                    path.string(), line, r.frame, file.records.back().frame));
        }
        file.records.push_back(r);
    });
    return file;
}

MeterFile mergeMeterFiles(const std::vector<std::filesystem::path>& paths, const std::vector<MeterFile>& files) {
    MeterFile merged;
    std::map<std::int64_t, std::pair<MeterRecord, std::size_t>> byFrame;
    for (std::size_t f = 0; f < files.size(); ++f) {
        if (f == 0) {
            merged.metering = files[f].metering;
        } else if (files[f].metering != merged.metering) {
            throw std::invalid_argument(fmt::format(
                "{} was metered with \"{}\" and {} with \"{}\": meter every chunk with the same settings",
                paths[0].string(), merged.metering, paths[f].string(), files[f].metering));
        }
        for (const MeterRecord& r : files[f].records) {
            const auto [it, added] = byFrame.try_emplace(r.frame, r, f);
            if (!added && !sameRecord(it->second.first, r)) {
                throw std::invalid_argument(
                    fmt::format("frame {} is in {} and in {} with different readings: they were not metered "
                                "from the same frame with the same settings",
                                r.frame, paths[it->second.second].string(), paths[f].string()));
            }
        }
    }
    for (auto& [frame, entry] : byFrame) {
        merged.records.push_back(entry.first);
    }
    return merged;
}

const TrackFrame* ExposureTrack::find(std::int64_t frame) const {
    const auto it = std::lower_bound(frames.begin(), frames.end(), frame,
                                     [](const TrackFrame& f, std::int64_t n) { return f.frame < n; });
    return it != frames.end() && it->frame == frame ? &*it : nullptr;
}

std::string exposureTrackCsv(const std::vector<PlannedExposure>& plan, float fps, const std::string& metering) {
    std::string text = fmt::format("{}; fps: {:.9g}; metering: {}\n"
                                   "frame,time_s,cut,reading,target_log2,applied_log2,exposure\n",
                                   kTrackMagic, fps, metering);
    for (const PlannedExposure& p : plan) {
        text += fmt::format("{},{:.6f},{},{:.9g},{:.9g},{:.9g},{:.9g}\n", p.frame, double(p.frame) / double(fps),
                            p.cut ? 1 : 0, p.reading, p.state.targetLog2, p.state.appliedLog2,
                            p.state.exposure);
    }
    return text;
}

ExposureTrack readExposureTrack(const std::filesystem::path& path) {
    const CsvReader csv(path, kTrackMagic);
    ExposureTrack track;
    track.metering = csv.attribute("metering");
    const std::string fps = csv.attribute("fps");
    const auto [end, ec] = std::from_chars(fps.data(), fps.data() + fps.size(), track.fps);
    if (ec != std::errc() || !(track.fps > 0.0f)) {
        throw std::invalid_argument(fmt::format("{}: line 1: fps \"{}\" is not a frame rate", path.string(), fps));
    }
    csv.rows([&](const std::vector<std::string_view>& fields, std::size_t line) {
        TrackFrame f;
        f.frame = csv.number<std::int64_t>(fields, "frame", line);
        f.cut = csv.number<int>(fields, "cut", line) != 0;
        f.appliedLog2 = csv.number<float>(fields, "applied_log2", line);
        if (!track.frames.empty() && f.frame <= track.frames.back().frame) {
            throw std::invalid_argument(fmt::format("{}:{}: frame {} after frame {}: frames must increase",
                                                    path.string(), line, f.frame, track.frames.back().frame));
        }
        track.frames.push_back(f);
    });
    if (track.frames.empty()) {
        throw std::invalid_argument(fmt::format("{}: the track holds no frame", path.string()));
    }
    return track;
}

} // namespace photopic
