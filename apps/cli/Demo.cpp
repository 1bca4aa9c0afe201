// `photopic demo`: every image in the data folder through three tone curves, as a labelled contact sheet.
// `photopic demo --images`, the demo before the tabletop walk became the main one (TabletopDemo.cpp).

#include "Commands.h"
#include "Outputs.h"
#include "Progress.h"

#include "common/Raster.h"
#include "core/Metering.h"
#include "core/ToneCurves.h"
#include "gl/Context.h"
#include "io/ImageIO.h"
#include "pipeline/Pipeline.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace photopic::cli {

namespace fs = std::filesystem;

int runDemo(const fs::path& dataDir, const fs::path& outDir, std::int64_t maxPixels, const Settings& look) {
    if (!fs::is_directory(dataDir)) {
        throw InputError(fmt::format("data folder {} does not exist (pass --data DIR)", dataDir.string()));
    }
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dataDir)) {
        const auto ext = entry.path().extension().string();
        if (ext == ".exr" || ext == ".hdr") {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    if (files.empty()) {
        throw InputError(fmt::format("no .exr or .hdr images in {}", dataDir.string()));
    }
    // The output is checked before any work; a run that fails takes back what it wrote.
    RunOutputs outputs;
    outputs.makeFolder(outDir);
    const fs::path out = outDir / "contact_sheet.png";
    RunOutputs::requireFile(out);
    std::printf("reading %zu images from %s\n", files.size(), dataDir.string().c_str());

    HeadlessContext context(commandContext());
    Pipeline pipeline;
    const ToneMapper curves[] = {ToneMapper::Aces, ToneMapper::Agx, ToneMapper::Neutral};
    std::vector<std::pair<std::string, Image8>> tiles;
    Progress progress("demo --images", files.size(), "images");
    for (const auto& file : files) {
        const ImageF image = readInput(file, maxPixels);
        requireTextureFits(file, image.width, image.height);
        // Expose each image so its geometric-mean luminance lands on middle grey (key 0.18).
        const float mean = meterAverage(image);
        const float ev = mean > 0 ? std::log2(0.18f / mean) : 0.0f;
        for (ToneMapper curve : curves) {
            Settings settings = look;
            settings.tonemapping.mode = curve;
            settings.tonemapping.exposure = std::clamp(ev, -20.0f, 20.0f);
            pipeline.setSettings(settings);
            tiles.emplace_back(fmt::format("{}  {}  {:+.1f} EV", file.filename().string(),
                                           toneMapperName(curve), settings.tonemapping.exposure),
                               processImage(pipeline, image));
        }
        progress.clear();
        std::printf("%s: %dx%d, geometric mean luminance %.4f -> exposure %+.2f EV\n",
                    file.filename().string().c_str(), image.width, image.height, double(mean), double(ev));
        std::fflush(stdout);
        progress.advance();
    }
    const Image8 sheet = makeContactSheet(tiles, 3, 420);
    writePng(out, sheet);
    outputs.commit();
    std::printf("wrote %s (%dx%d): %zu images x 3 tone curves\n", out.string().c_str(), sheet.width,
                sheet.height, files.size());
    return kOk;
}

} // namespace photopic::cli
