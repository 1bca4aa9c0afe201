// `photopic bench`: renders a frame N times after a warm-up and prints, for every pass, the median GPU time
// (timer queries, harvested after each frame so none is dropped), the estimated bytes it moves and the
// bandwidth that implies: a pass far below the device's bandwidth is bound by something else.

#include "Bench.h"

#include "core/Log.h"
#include "gl/Context.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "pipeline/Pipeline.h"
#include "scenes/SyntheticHdr.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>

namespace photopic::cli {

namespace fs = std::filesystem;

namespace {

double median(std::vector<double> v) {
    if (v.empty()) {
        return 0;
    }
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct PassRow {
    std::string name;
    double ms = 0;
    double bytes = 0;
};

void writeJsonAtomically(const fs::path& path, const nlohmann::json& doc) {
    const fs::path tmp = path.string() + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) {
            throw std::runtime_error(fmt::format("cannot write {}", path.string()));
        }
        out << doc.dump(2) << "\n";
        if (!out.flush()) {
            std::error_code ec;
            fs::remove(tmp, ec);
            throw std::runtime_error(fmt::format("cannot write {}", path.string()));
        }
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw std::runtime_error(fmt::format("cannot write {}: {}", path.string(), ec.message()));
    }
}

} // namespace

int runBench(const BenchOptions& options) {
    const Settings settings = resolveSettings(options.settings);
    if (options.frames < 1) {
        throw InputError("--frames must be at least 1");
    }
    ImageF image;
    if (!options.input.empty()) {
        try {
            image = readImage(options.input);
        } catch (const IoError& e) {
            throw InputError(e.what());
        }
    } else {
        std::smatch m;
        static const std::regex kSize(R"((\d{1,5})x(\d{1,5}))");
        if (!std::regex_match(options.size, m, kSize) || std::stoi(m[1]) < 8 || std::stoi(m[2]) < 8 ||
            std::stoi(m[1]) > 16384 || std::stoi(m[2]) > 16384) {
            throw InputError(fmt::format(
                "--size {}: expected WxH with each side in [8, 16384], e.g. 1920x1080", options.size));
        }
        image = makeSyntheticHdr(std::stoi(m[1]), std::stoi(m[2]));
    }

    HeadlessContext context;
    Pipeline pipeline({.settings = settings, .forceLdr = options.forceLdr});
    if (!pipeline.capabilities().timerQueries) {
        throw std::runtime_error("this GL implementation has no timer queries; nothing to measure");
    }
    const Texture input = makeTexture(image, "bench input");
    std::uint64_t frame = 0;
    for (int i = 0; i < options.warmup; ++i) {
        pipeline.execute({.color = &input}, {.frameIndex = frame++});
        pipeline.timers().drain();
    }
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> times;
    std::map<std::string, double> bytes;
    std::vector<double> totals;
    for (int i = 0; i < options.frames; ++i) {
        pipeline.execute({.color = &input}, {.frameIndex = frame++});
        for (const auto& passes : pipeline.timers().drain()) {
            double total = 0;
            for (const PassTiming& p : passes) {
                if (!times.contains(p.name)) {
                    order.push_back(p.name);
                }
                times[p.name].push_back(p.gpuMs);
                bytes[p.name] = p.bytesMoved;
                total += p.gpuMs;
            }
            totals.push_back(total);
        }
    }

    const PipelineStatus t = pipeline.status();
    const ContextInfo& info = context.info();
    std::printf("photopic bench: %dx%d, %d frames after %d warm-up, %s\n", image.width, image.height,
                options.frames, options.warmup, info.renderer.c_str());
    std::printf("colour path: %s (%s), quality %s, bloom levels %d\n",
                t.path == ColorPath::Hdr ? "HDR" : "LDR", t.pathReason.c_str(),
                std::string(qualityNames()[std::size_t(t.quality)]).c_str(), t.bloomLevels);
    std::printf("%-36s %12s %12s %10s\n", "pass", "median ms", "MB moved", "GB/s");
    nlohmann::json passesJson = nlohmann::json::array();
    double totalBytes = 0;
    for (const auto& name : order) {
        const double ms = median(times[name]);
        const double b = bytes[name];
        const double gbps = ms > 0 ? b / (ms * 1e6) : 0.0;
        totalBytes += b;
        std::printf("%-36s %12.3f %12.2f %10.2f\n", name.c_str(), ms, b / 1e6, gbps);
        passesJson.push_back({{"name", name},
                              {"medianGpuMs", ms},
                              {"bytesMoved", b},
                              {"gbPerSecond", gbps},
                              {"samples", times[name].size()}});
    }
    const double totalMs = median(totals);
    std::printf("%-36s %12.3f %12.2f %10.2f\n", "total (median of frame sums)", totalMs, totalBytes / 1e6,
                totalMs > 0 ? totalBytes / (totalMs * 1e6) : 0.0);

    if (!options.json.empty()) {
        const nlohmann::json doc = {
            {"width", image.width},
            {"height", image.height},
            {"frames", options.frames},
            {"warmup", options.warmup},
            {"renderer", info.renderer},
            {"colourPath", t.path == ColorPath::Hdr ? "hdr" : "ldr"},
            {"colourPathReason", t.pathReason},
            {"quality", std::string(qualityNames()[std::size_t(t.quality)])},
            {"passes", passesJson},
            {"totalMedianGpuMs", totalMs},
            {"totalBytesMoved", totalBytes},
        };
        writeJsonAtomically(options.json, doc);
        std::printf("wrote %s\n", options.json.string().c_str());
    }
    return kOk;
}

} // namespace photopic::cli
