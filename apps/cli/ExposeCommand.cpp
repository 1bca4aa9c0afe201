// `photopic expose` (ExposeCommand.h), and the output file the sequence stages write.
#include "ExposeCommand.h"

#include "CommandOptions.h"
#include "InputSequence.h"
#include "SequenceCommands.h"

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

ExposeCommand::ExposeCommand(CLI::App& parent)
    : Command(parent.add_subcommand("expose",
                                    "plan a sequence's auto exposure from its meter CSVs: the exposure "
                                    "controller over every frame in order, one row per frame, for "
                                    "photopic image --exposure-track")) {
    CLI::App& cmd = app();
    ExposeOptions& o = mOptions;
    cmd.add_option("meter", o.meterFiles, "meter CSVs (photopic meter), in any order")
        ->required()
        ->check(CLI::ExistingFile);
    cmd.add_option("-o,--output", o.output, "the exposure track CSV")->check(kOutputPath)->required();
    cmd.add_option("--fps", o.fps, "frame rate: one frame is 1/fps seconds of adaptation")
        ->check(CLI::Range(0.001f, 10000.0f))
        ->capture_default_str();
    cmd.add_option("--cut", o.cuts,
                   "a frame where exposure snaps to its target (a camera cut; photopic image "
                   "--exposure-track restarts the histories there too); repeatable")
        ->take_all()
        ->allow_extra_args(false);
    cmd.add_flag("--allow-gaps", o.allowGaps,
                 "plan over frames missing from the meter files as photopic image runs over a pattern's "
                 "gaps (one frame time apart); without it a missing frame is an error");
    addSettingsOptions(&cmd, o.settings, "stills (as photopic image)");
    cmd.footer("Examples:\n"
               "  photopic expose meter-*.csv --fps 24 --settings look.json -o exposure.csv\n"
               "  photopic expose meter.csv --fps 24 --cut 1040 --set autoExposure.enabled=true -o e.csv");
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
    const MeterFile merged = mergedMeterFiles(settings);
    const std::vector<MeterRecord>& records = merged.records;
    checkFrames(records);
    const auto start = std::chrono::steady_clock::now();
    const std::vector<PlannedExposure> plan = planExposure(
        settings.autoExposure, records, 1.0f / mOptions.fps, settings.tonemapping.exposure, mOptions.cuts);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    AtomicFileWriter file = openCommandOutput("expose", mOptions.output);
    file.write(exposureTrackCsv(plan, mOptions.fps, merged.metering));
    file.commit();
    if (statusLines())
        std::printf("expose -> %s (%zu frames, %lld to %lld, planned in %.3f ms)\n",
                    mOptions.output.string().c_str(), plan.size(),
                    static_cast<long long>(records.front().frame),
                    static_cast<long long>(records.back().frame), ms);
    return kOk;
}

MeterFile ExposeCommand::mergedMeterFiles(const Settings& settings) const {
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
    return merged;
}

void ExposeCommand::checkFrames(const std::vector<MeterRecord>& records) const {
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
}

} // namespace photopic::cli
