#include "SequenceCommands.h"

#include "InputSequence.h"

#include "common/ExposureTrack.h"
#include "core/ExposurePlan.h"
#include "io/ImageIO.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace photopic::cli {

namespace fs = std::filesystem;

AtomicFileWriter openCommandOutput(std::string_view command, const fs::path& path) {
    try {
        return AtomicFileWriter(path);
    } catch (const IoError& e) {
        throw InputError(fmt::format("{} {}", command, e.what()));
    }
}

int ExposeCommand::run() {
    if (mOptions.output.empty()) {
        throw InputError("expose: an output is required (-o exposure.csv)");
    }
    const Settings settings = resolveSettings(mOptions.settings, Settings::stills());
    if (!settings.autoExposure.enabled) {
        throw InputError(
            "expose: autoExposure.enabled is false in these settings, so there is nothing to plan: "
            "--set autoExposure.enabled=true (and the same settings for every stage)");
    }
    std::vector<MeterFile> files;
    for (const fs::path& path : mOptions.meterFiles) {
        try {
            files.push_back(readMeterCsv(path));
        } catch (const std::invalid_argument& e) {
            throw InputError(e.what());
        }
    }
    MeterFile merged;
    try {
        merged = mergeMeterFiles(mOptions.meterFiles, files);
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    }
    const std::string metering = meteringDescription(settings.autoExposure);
    if (merged.metering != metering) {
        throw InputError(
            fmt::format("expose: {} was metered with \"{}\", and these settings meter with \"{}\": "
                        "meter again with the same autoExposure settings",
                        mOptions.meterFiles.front().string(), merged.metering, metering));
    }
    if (merged.records.empty()) {
        throw InputError("expose: the meter files hold no frame");
    }
    const std::vector<MeterRecord>& records = merged.records;
    const FrameGaps gaps = frameGaps(records, [](const MeterRecord& r) { return r.frame; });
    if (gaps.firstMissing && !mOptions.allowGaps) {
        throw InputError(
            fmt::format("expose: {} frame(s) between {} and {} are in no meter file, the first {}: "
                        "meter them (a chunk's file missing?), or --allow-gaps to plan without "
                        "them",
                        gaps.missing, records.front().frame, records.back().frame, *gaps.firstMissing));
    }
    for (const std::int64_t cut : mOptions.cuts) {
        if (std::none_of(records.begin(), records.end(),
                         [cut](const MeterRecord& r) { return r.frame == cut; })) {
            throw InputError(fmt::format("expose: --cut {} is not a metered frame ({} to {})", cut,
                                         records.front().frame, records.back().frame));
        }
    }
    const auto start = std::chrono::steady_clock::now();
    const std::vector<PlannedExposure> plan = planExposure(
        settings.autoExposure, records, 1.0f / mOptions.fps, settings.tonemapping.exposure, mOptions.cuts);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    AtomicFileWriter file = openCommandOutput("expose", mOptions.output);
    file.write(exposureTrackCsv(plan, mOptions.fps, metering));
    file.commit();
    if (statusLines())
        std::printf("expose -> %s (%zu frames, %lld to %lld, planned in %.3f ms)\n",
                    mOptions.output.string().c_str(), plan.size(),
                    static_cast<long long>(records.front().frame),
                    static_cast<long long>(records.back().frame), ms);
    return kOk;
}

} // namespace photopic::cli
