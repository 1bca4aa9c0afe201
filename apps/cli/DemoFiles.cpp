#include "DemoFiles.h"

#include "Commands.h"
#include "Video.h"

#include <fmt/format.h>

namespace photopic::cli {

namespace fs = std::filesystem;

fs::path demoFramePath(const fs::path& folder, std::size_t index) {
    return folder / fmt::format("frame_{:04d}.png", index);
}

DemoFiles prepareDemoFiles(RunOutputs& outputs, const fs::path& folder, int width, int height, float fps,
                           float seconds) {
    if (width < 16 || height < 16 || fps <= 0.0f || seconds <= 0.0f) {
        throw InputError("demo: --size must be at least 16x16, --fps and --seconds positive");
    }
    outputs.makeFolder(folder);
    DemoFiles files{folder, folder / "exposure_plot.png", folder / "contact_sheet.png", folder / "demo.mp4"};
    for (const fs::path& path : {demoFramePath(folder, 0), files.plot, files.sheet, files.video}) {
        RunOutputs::requireFile(path);
    }
    outputs.sequence([folder](std::size_t i) { return demoFramePath(folder, i); });
    return files;
}

std::string encodeDemoVideo(RunOutputs& outputs, const DemoFiles& files, double fps, bool enabled) {
    if (!enabled) {
        return "demo.mp4 skipped (--no-video)";
    }
    const VideoResult result = encodeFrameSequence(files.folder, fps, files.video);
    if (result.written) {
        outputs.wrote(files.video);
    }
    return result.note;
}

} // namespace photopic::cli
