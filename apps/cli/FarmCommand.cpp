// `photopic farm` (FarmCommand.h): the job set of a sequence's meter, expose and render stages.
#include "FarmCommand.h"

#include "CommandOptions.h"

#include "InputSequence.h"
#include "Video.h"

#include "common/SequencePattern.h"
#include "core/settings/SettingsJson.h"
#include "io/ImageIO.h"

#include <fmt/format.h>

#include <cstdio>

namespace photopic::cli {

namespace fs = std::filesystem;

namespace {

/// One word of a POSIX shell command line, quoted so the shell takes it as it is.
std::string shellWord(const std::string& word) {
    if (!word.empty() &&
        word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                               "_-+=.,/:@%") == std::string::npos) {
        return word;
    }
    std::string quoted = "'";
    for (const char c : word) {
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return quoted + "'";
}

std::string shellLine(const std::vector<std::string>& words) {
    std::string line;
    for (const std::string& w : words) {
        if (!line.empty()) {
            line += ' ';
        }
        line += shellWord(w);
    }
    return line;
}

/// The program the jobs run: --photopic, else this executable's own path (the nodes must see it there).
std::string photopicCommand(const FarmOptions& options) {
    if (!options.photopic.empty()) {
        return options.photopic;
    }
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    return ec ? std::string("photopic") : self.string();
}

void writeFile(const fs::path& path, const std::string& text, bool executable) {
    try {
        AtomicFileWriter file(path);
        file.write(text);
        file.commit();
    } catch (const IoError& e) {
        throw InputError(fmt::format("farm: {}", e.what()));
    }
    if (executable) {
        fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                        fs::perm_options::add);
    }
}

/// The sequence's frames: --frames, else every frame of the pattern that exists (which must be gapless:
/// a chunk is a range, and each of its frames must exist).
FrameRange sequenceRange(const FarmOptions& options) {
    ImageOptions probe;
    probe.inputs = {options.input};
    probe.frames = options.frames;
    const std::vector<InputFile> files = expandInputs(probe);
    if (!parseFramePattern(options.input.filename().string()) || files.empty() || !files.front().frame) {
        throw InputError(fmt::format("farm: {} is not a frame-numbered pattern (f%04d.exr, f.####.exr)",
                                     options.input.string()));
    }
    const FrameRange range{*files.front().frame, *files.back().frame};
    if (std::int64_t(files.size()) != range.last - range.first + 1) {
        throw InputError(
            fmt::format("farm: {} has frames missing between {} and {}: chunks are frame ranges, "
                        "so give --frames A-B over frames that all exist",
                        options.input.string(), range.first, range.last));
    }
    return range;
}

/// The part of each array task's script that turns its index into its frame range.
std::string chunkRange(const FrameRange& range, int chunk) {
    return fmt::format("first=$(( {} + SLURM_ARRAY_TASK_ID * {} ))\n"
                       "last=$(( first + {} ))\n"
                       "if [ \"$last\" -gt {} ]; then last={}; fi\n",
                       range.first, chunk, chunk - 1, range.last, range.last);
}

std::string jobScript(const std::string& name, const fs::path& logs, const std::vector<std::string>& sbatch,
                      std::optional<int> arrayTasks, const std::string& body) {
    std::string text = fmt::format("#!/bin/bash\n#SBATCH --job-name=photopic-{}\n", name);
    if (arrayTasks) {
        text += fmt::format("#SBATCH --array=0-{}\n#SBATCH --output={}\n", *arrayTasks - 1,
                            (logs / (name + "-%a.log")).string());
    } else {
        text += fmt::format("#SBATCH --output={}\n", (logs / (name + ".log")).string());
    }
    for (const std::string& o : sbatch) {
        text += "#SBATCH " + o + "\n";
    }
    return text + "set -euo pipefail\n" + body;
}

/// What every job script is written from: the resolved command lines' common parts and the folders.
struct JobSet {
    fs::path dir;
    fs::path logs;
    FrameRange range;
    int chunks = 0;
    int preroll = 0;
    std::string exe;
    std::string input;
    std::string settingsFile;
    std::string fps;
};

JobSet prepareJobSet(const FarmOptions& o) {
    if (o.chunk < 1) {
        throw InputError(fmt::format("farm: --chunk {} must be at least 1", o.chunk));
    }
    if (o.output.empty() || !parseFramePattern(o.output.filename().string())) {
        throw InputError(
            "farm: -o must be a frame-numbered output pattern (out/f%04d.png): each chunk writes "
            "its own frames");
    }
    JobSet set;
    set.range = sequenceRange(o);
    const std::int64_t frames = set.range.last - set.range.first + 1;
    set.chunks = int((frames + o.chunk - 1) / o.chunk);
    set.preroll = o.preroll >= 0 ? o.preroll : kDefaultFarmPreroll;
    // The settings are resolved once (the stills look, the file, the flags) and every stage reads the same
    // file, so the meter, the plan and the renders cannot disagree.
    const Settings settings = resolveSettings(o.settings, Settings::stills());
    if (!settings.autoExposure.enabled) {
        throw InputError(
            "farm: autoExposure.enabled is false in these settings: a sequence without auto "
            "exposure needs no plan; render its chunks with photopic image --frames A-B --preroll N");
    }
    set.dir = fs::absolute(o.jobDir);
    set.logs = set.dir / "logs";
    std::error_code ec;
    fs::create_directories(set.logs, ec);
    fs::create_directories(set.dir / "meter", ec);
    if (ec) {
        throw InputError(fmt::format("farm: cannot make {}: {}", set.dir.string(), ec.message()));
    }
    set.exe = photopicCommand(o);
    set.input = fs::absolute(o.input).string();
    set.settingsFile = (set.dir / "settings.json").string();
    set.fps = fmt::format("{:.9g}", o.fps);
    writeFile(set.settingsFile, settingsToJson(settings), false);
    return set;
}

/// meter.sbatch, expose.sbatch and render.sbatch.
void writeStageScripts(const FarmOptions& o, const JobSet& set) {
    const std::string meter =
        chunkRange(set.range, o.chunk) +
        shellLine({set.exe, "meter", set.input, "--settings", set.settingsFile, "--fps", set.fps, "-q"}) +
        " --frames \"$first-$last\" -o " + shellWord((set.dir / "meter").string()) +
        "/chunk-\"$SLURM_ARRAY_TASK_ID\".csv\n";
    std::vector<std::string> expose = {set.exe,
                                       "expose",
                                       "--settings",
                                       set.settingsFile,
                                       "--fps",
                                       set.fps,
                                       "-q",
                                       "-o",
                                       (set.dir / "exposure.csv").string()};
    for (const std::int64_t cut : o.cuts) {
        expose.insert(expose.end(), {"--cut", std::to_string(cut)});
    }
    std::vector<std::string> render = {set.exe,
                                       "image",
                                       set.input,
                                       "--settings",
                                       set.settingsFile,
                                       "--fps",
                                       set.fps,
                                       "--preroll",
                                       std::to_string(set.preroll),
                                       "--exposure-track",
                                       (set.dir / "exposure.csv").string(),
                                       "-o",
                                       fs::absolute(o.output).string(),
                                       "-q"};
    render.insert(render.end(), o.imageOptions.begin(), o.imageOptions.end());

    writeFile(set.dir / "meter.sbatch", jobScript("meter", set.logs, o.sbatchOptions, set.chunks, meter),
              true);
    writeFile(set.dir / "expose.sbatch",
              jobScript("expose", set.logs, o.sbatchOptions, std::nullopt,
                        shellLine(expose) + " " + shellWord((set.dir / "meter").string()) + "/chunk-*.csv\n"),
              true);
    writeFile(set.dir / "render.sbatch",
              jobScript("render", set.logs, o.sbatchOptions, set.chunks,
                        chunkRange(set.range, o.chunk) + shellLine(render) + " --frames \"$first-$last\"\n"),
              true);
}

/// submit.sh (the three stages chained through Slurm) and local.sh (the same scripts without a scheduler).
void writeRunners(const JobSet& set) {
    const std::string submit =
        "#!/bin/bash\n"
        "# The three stages as Slurm jobs: the meter array, then (afterok) the plan, then (afterok) the "
        "render\n"
        "# array. Prints the three job ids.\n"
        "set -euo pipefail\n"
        "cd \"$(dirname \"$0\")\"\n"
        "meter=$(sbatch --parsable meter.sbatch)\n"
        "expose=$(sbatch --parsable --dependency=afterok:\"${meter%%;*}\" expose.sbatch)\n"
        "render=$(sbatch --parsable --dependency=afterok:\"${expose%%;*}\" render.sbatch)\n"
        "echo \"${meter%%;*} ${expose%%;*} ${render%%;*}\"\n";
    writeFile(set.dir / "submit.sh", submit, true);
    // Without a scheduler: the same job scripts run one chunk at a time (SLURM_ARRAY_TASK_ID set by hand).
    const std::string local =
        fmt::format("#!/bin/bash\n"
                    "# The three stages without a scheduler, chunk after chunk on this machine.\n"
                    "set -euo pipefail\n"
                    "cd \"$(dirname \"$0\")\"\n"
                    "for i in $(seq 0 {0}); do SLURM_ARRAY_TASK_ID=$i bash meter.sbatch; done\n"
                    "bash expose.sbatch\n"
                    "for i in $(seq 0 {0}); do SLURM_ARRAY_TASK_ID=$i bash render.sbatch; done\n",
                    set.chunks - 1);
    writeFile(set.dir / "local.sh", local, true);
}

} // namespace

FarmCommand::FarmCommand(CLI::App& parent)
    : Command(parent.add_subcommand("farm",
                                    "write a sequence's meter, expose and render stages as a Slurm job set "
                                    "(job arrays with afterok dependencies), and submit it with --submit")) {
    CLI::App* cmd = &app();
    FarmOptions& o = mOptions;
    cmd->add_option("input", o.input, "the sequence: a frame-numbered pattern (shot/f%04d.exr)")->required();
    cmd->add_option("-o,--output", o.output, "the output pattern (out/f%04d.png)")
        ->check(kOutputPath)
        ->required();
    cmd->add_option("--jobs", o.jobDir, "folder for the job scripts, settings, meter files and logs")
        ->check(kOutputPath)
        ->required();
    cmd->add_option("--frames", o.frames, "frames A-B (default: every frame of the pattern)");
    cmd->add_option("--chunk", o.chunk, "frames per meter and render job")
        ->check(CLI::Range(1, 1000000))
        ->capture_default_str();
    cmd->add_option("--preroll", o.preroll,
                    "frames each render job processes before its chunk (default " +
                        std::to_string(kDefaultFarmPreroll) + ")")
        ->check(CLI::Range(0, 1000));
    cmd->add_option("--fps", o.fps, "frame rate")->check(CLI::Range(0.001f, 10000.0f))->capture_default_str();
    cmd->add_option("--cut", o.cuts,
                    "a camera cut: exposure snaps and the histories (TAA, SSR, motion blur) restart there, "
                    "and no preroll reaches back past it; repeatable")
        ->take_all()
        ->allow_extra_args(false);
    cmd->add_option("--photopic", o.photopic,
                    "the photopic command the jobs run (default: this program's path, which the nodes must "
                    "see)");
    cmd->add_option("--sbatch-option", o.sbatchOptions,
                    "an #SBATCH line for every job, e.g. --sbatch-option=--partition=render; repeatable")
        ->take_all()
        ->allow_extra_args(false);
    cmd->add_option("--image-option", o.imageOptions,
                    "an option for each render's photopic image, e.g. --image-option=--bit-depth "
                    "--image-option=16; repeatable")
        ->take_all()
        ->allow_extra_args(false);
    cmd->add_flag("--submit", o.submit, "submit the job set with sbatch now (else print the commands)");
    addSettingsOptions(cmd, o.settings, "stills (as photopic image)");
    cmd->footer(
        "Examples:\n"
        "  photopic farm shot/f%04d.exr -o out/f%04d.png --jobs farm/ --chunk 100 --fps 24 "
        "--settings look.json --submit\n"
        "  photopic farm shot/f%04d.exr -o out/f%04d.png --jobs farm/ --sbatch-option=--partition=gpu");
}

int FarmCommand::run() {
    const FarmOptions& o = mOptions;
    const JobSet set = prepareJobSet(o);
    writeStageScripts(o, set);
    writeRunners(set);
    if (statusLines())
        std::printf("farm: frames %lld to %lld in %d chunk(s) of %d, preroll %d, job set in %s\n",
                    static_cast<long long>(set.range.first), static_cast<long long>(set.range.last),
                    set.chunks, o.chunk, set.preroll, set.dir.string().c_str());
    if (!o.submit) {
        std::printf("submit with:\n  %s\nor by hand:\n  sbatch --parsable %s\n  sbatch --parsable "
                    "--dependency=afterok:METER_ID %s\n  sbatch --dependency=afterok:EXPOSE_ID %s\n",
                    shellWord((set.dir / "submit.sh").string()).c_str(),
                    shellWord((set.dir / "meter.sbatch").string()).c_str(),
                    shellWord((set.dir / "expose.sbatch").string()).c_str(),
                    shellWord((set.dir / "render.sbatch").string()).c_str());
        return kOk;
    }
    std::fflush(stdout);
    const int status = runProgram({"bash", (set.dir / "submit.sh").string()});
    if (status != 0) {
        throw std::runtime_error(fmt::format("farm: {} failed (status {}); its sbatch error is above",
                                             (set.dir / "submit.sh").string(), status));
    }
    return kOk;
}

} // namespace photopic::cli
