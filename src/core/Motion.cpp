#include "core/Motion.h"

#include "core/Csv.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace photopic {

namespace {

std::string describe(std::string_view file, int line, std::string_view problem) {
    return line > 0 ? fmt::format("{}:{}: {}", file, line, problem) : fmt::format("{}: {}", file, problem);
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) {
        s.remove_prefix(1);
    }
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) {
        s.remove_suffix(1);
    }
    return s;
}

std::vector<std::string_view> splitCells(std::string_view line) {
    std::vector<std::string_view> cells = splitCsvLine(line);
    for (std::string_view& cell : cells) {
        cell = trim(cell);
    }
    return cells;
}

bool parseNumber(std::string_view cell, double& value) {
    if (!cell.empty() && cell.front() == '+') {
        cell.remove_prefix(1);
    }
    const char* end = cell.data() + cell.size();
    const auto result = std::from_chars(cell.data(), end, value);
    return !cell.empty() && result.ec == std::errc() && result.ptr == end && std::isfinite(value);
}

} // namespace

MotionError::MotionError(std::string_view file, int line, std::string_view problem)
    : std::runtime_error(describe(file, line, problem))
    , mLine(line) {}

MotionTrack::MotionTrack(std::vector<MotionSample> samples)
    : mSamples(std::move(samples)) {
    for (std::size_t i = 0; i < mSamples.size(); ++i) {
        const MotionSample& s = mSamples[i];
        if (!std::isfinite(s.time) || !std::isfinite(s.attitude.pitch) || !std::isfinite(s.attitude.roll) ||
            !std::isfinite(s.attitude.yaw)) {
            throw std::invalid_argument(fmt::format("motion sample {} is not finite", i));
        }
        if (i > 0 && !(s.time > mSamples[i - 1].time)) {
            throw std::invalid_argument(fmt::format("motion sample {}: time does not increase", i));
        }
    }
}

Attitude MotionTrack::at(double time) const {
    if (mSamples.empty()) {
        return {};
    }
    // NaN compares false with everything, so it must be caught here or the search below runs off the end.
    if (std::isnan(time) || time <= mSamples.front().time) {
        return mSamples.front().attitude;
    }
    if (time >= mSamples.back().time) {
        return mSamples.back().attitude;
    }
    const auto next = std::upper_bound(mSamples.begin(), mSamples.end(), time,
                                       [](double t, const MotionSample& s) { return t < s.time; });
    const MotionSample& b = *next;
    const MotionSample& a = *(next - 1);
    // The span of two finite times can overflow (1e308 - -1e308); halved, it cannot. Not halved always:
    // halving subnormal times can make two distinct ones equal.
    const double span = b.time - a.time;
    const double f =
        std::clamp(std::isfinite(span) ? (time - a.time) / span
                                       : (0.5 * time - 0.5 * a.time) / (0.5 * b.time - 0.5 * a.time),
                   0.0, 1.0);
    // std::lerp stays finite for finite ends and f in [0, 1]; x + (y - x) * f overflows to inf * 0 = NaN.
    return {.pitch = std::lerp(a.attitude.pitch, b.attitude.pitch, f),
            .roll = std::lerp(a.attitude.roll, b.attitude.roll, f),
            .yaw = std::lerp(a.attitude.yaw, b.attitude.yaw, f)};
}

MotionTrack parseMotionCsv(std::string_view text, std::string_view fileName) {
    static constexpr std::array<std::string_view, 4> kColumns{"time_s", "pitch", "roll", "yaw"};
    std::vector<MotionSample> samples;
    bool sawHeader = false;
    int lineNumber = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t newline = text.find('\n', start);
        const std::string_view raw =
            text.substr(start, newline == std::string_view::npos ? std::string_view::npos : newline - start);
        start = newline == std::string_view::npos ? text.size() + 1 : newline + 1;
        ++lineNumber;
        const std::string_view line = trim(raw);
        if (line.empty()) {
            continue;
        }
        if (!sawHeader) {
            if (line != kMotionCsvHeader) {
                throw MotionError(
                    fileName, lineNumber,
                    fmt::format("header is \"{}\", expected exactly \"{}\"", line, kMotionCsvHeader));
            }
            sawHeader = true;
            continue;
        }
        const auto cells = splitCells(line);
        if (cells.size() != kColumns.size()) {
            throw MotionError(fileName, lineNumber,
                              fmt::format("{} columns, expected 4 ({})", cells.size(), kMotionCsvHeader));
        }
        double values[4] = {};
        for (std::size_t c = 0; c < cells.size(); ++c) {
            if (!parseNumber(cells[c], values[c])) {
                throw MotionError(fileName, lineNumber,
                                  fmt::format("{} \"{}\" is not a finite number", kColumns[c], cells[c]));
            }
        }
        if (!samples.empty() && values[0] <= samples.back().time) {
            throw MotionError(fileName, lineNumber,
                              fmt::format("time_s {} does not increase (previous row: {})", values[0],
                                          samples.back().time));
        }
        samples.push_back(
            {.time = values[0], .attitude = {.pitch = values[1], .roll = values[2], .yaw = values[3]}});
    }
    if (!sawHeader) {
        throw MotionError(fileName, 0,
                          fmt::format("empty file, expected the header \"{}\"", kMotionCsvHeader));
    }
    if (samples.empty()) {
        throw MotionError(fileName, 0, "no samples after the header");
    }
    return MotionTrack(std::move(samples));
}

MotionTrack loadMotionCsv(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw MotionError(path.string(), 0, "cannot open the motion file");
    }
    std::stringstream text;
    text << in.rdbuf();
    if (in.bad()) {
        throw MotionError(path.string(), 0, "cannot read the motion file");
    }
    return parseMotionCsv(text.str(), path.string());
}

Attitude ScriptedTilt::at(double time) const {
    const double w = 2.0 * std::numbers::pi * time / period;
    return {.pitch = pitchAmplitude * std::sin(w / 1.5), .roll = rollAmplitude * std::sin(w), .yaw = 0.0};
}

glm::vec3 seedLightVector(double pitch, double roll) {
    return glm::normalize(
        glm::vec3(float(std::sin(roll)), float(std::sin(pitch)), -float(std::cos(pitch) * std::cos(roll))));
}

glm::vec3 canvasLightDirection(double pitch, double roll) {
    const glm::vec3 l = seedLightVector(pitch, roll);
    return {l.x, l.y, -l.z};
}

} // namespace photopic
