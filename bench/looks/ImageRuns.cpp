#include "ImageRuns.h"

#include "core/Color.h"
#include "io/ImageIO.h"

#include <glm/vec3.hpp>

#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

extern char** environ;

namespace looks {

using photopic::Image8;
using photopic::ImageF;

namespace {

/// Runs argv[0] with these arguments, no shell (paths are passed as they are), and waits for it.
int runProgram(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const std::string& a : args) {
        argv.push_back(const_cast<char*>(a.c_str()));
    }
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) {
        return -1;
    }
    int status = 0;
    if (waitpid(pid, &status, 0) != pid) {
        return -1;
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string outputName(const std::filesystem::path& input, const Variant& variant, Exposure exposure,
                       bool bloom) {
    std::string name = input.filename().string() + "." + variant.label;
    name += exposure == Exposure::Auto ? ".auto" : ".fixed";
    name += bloom ? ".bloom.png" : ".png";
    return name;
}

} // namespace

Image8 renderWithCli(const CliRun& run, const std::filesystem::path& input, const Variant& variant,
                     Exposure exposure, bool bloom) {
    const std::filesystem::path output = run.workDir / outputName(input, variant, exposure, bloom);
    std::vector<std::string> args = {run.cli.string(),
                                     "-q",
                                     "image",
                                     input.string(),
                                     "-o",
                                     output.string(),
                                     "--preset",
                                     "stills",
                                     "--set",
                                     "tonemapping.mode=" + variant.modeName,
                                     "--set",
                                     "tonemapping.agxLook=" + variant.lookName};
    if (!bloom) {
        args.insert(args.end(), {"--set", "bloom.enabled=false"});
    }
    if (exposure == Exposure::Auto) {
        args.insert(args.end(), {"--set", "autoExposure.enabled=true"});
    }
    const int rc = runProgram(args);
    if (rc != 0) {
        throw std::runtime_error(input.string() + ": " + run.cli.string() + " image (" + variant.label +
                                 ") failed with exit status " + std::to_string(rc));
    }
    return photopic::readPng8(output);
}

ClipShare clipShare(const Image8& image) {
    std::size_t crushed = 0, clipped = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.at(x, y);
            const int high = std::max({p[0], p[1], p[2]});
            crushed += high < 10 ? 1 : 0;
            clipped += high > 250 ? 1 : 0;
        }
    }
    const double n = double(image.width) * double(image.height);
    return {100.0 * double(crushed) / n, 100.0 * double(clipped) / n};
}

std::pair<int, int> brightestPixel(const ImageF& image) {
    std::pair<int, int> best{0, 0};
    float bestLuma = -1.0f;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.at(x, y);
            const float luma = photopic::luma709({p[0], p[1], p[2]});
            if (luma > bestLuma) {
                bestLuma = luma;
                best = {x, y};
            }
        }
    }
    return best;
}

} // namespace looks
