// Entry points for the GL-free core's parsers: settings JSON, --set overrides, motion CSV.

#include "FuzzTargets.h"

#include "core/Motion.h"
#include "core/settings/SettingsJson.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

namespace photopic::fuzz {

namespace {

std::string_view text(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

[[noreturn]] void broken(const char* what) {
    std::fprintf(stderr, "fuzz target: promise broken: %s\n", what);
    std::abort();
}

bool finite(const Attitude& a) {
    return std::isfinite(a.pitch) && std::isfinite(a.roll) && std::isfinite(a.yaw);
}

} // namespace

void settingsJson(const std::uint8_t* data, std::size_t size) {
    Settings settings;
    if (!readSettingsJson(text(data, size), settings).empty()) {
        return;
    }
    // Accepted settings must survive save then load unchanged (the loader's own promise).
    const std::string saved = settingsToJson(settings);
    Settings reloaded;
    if (!readSettingsJson(saved, reloaded).empty() || settingsToJson(reloaded) != saved) {
        broken("accepted settings do not round-trip");
    }
}

void settingsOverride(const std::uint8_t* data, std::size_t size) {
    Settings settings;
    std::string_view rest = text(data, size);
    while (!rest.empty()) {
        const std::size_t newline = rest.find('\n');
        try {
            applySettingsOverride(settings, rest.substr(0, newline));
        } catch (const SettingsError& e) {
            (void)e.what();
        }
        rest = newline == std::string_view::npos ? std::string_view{} : rest.substr(newline + 1);
    }
    (void)settingsToJson(settings);
}

void motionCsv(const std::uint8_t* data, std::size_t size) {
    MotionTrack track;
    try {
        track = parseMotionCsv(text(data, size), "fuzz.csv");
    } catch (const MotionError&) {
        return;
    }
    const auto& samples = track.samples();
    constexpr double kInf = std::numeric_limits<double>::infinity();
    for (double t : {std::numeric_limits<double>::quiet_NaN(), -kInf, kInf, 0.0}) {
        if (!finite(track.at(t))) {
            broken("MotionTrack::at gave a non-finite attitude at a special time");
        }
    }
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const double t = samples[i].time;
        const double next = i + 1 < samples.size() ? samples[i + 1].time : t;
        for (double probe : {t, std::nextafter(t, kInf), 0.5 * t + 0.5 * next}) {
            if (!finite(track.at(probe))) {
                broken("MotionTrack::at gave a non-finite attitude between samples");
            }
        }
    }
}

} // namespace photopic::fuzz
