// What the commands share: the status lines (-q), the GL context a command opens, the frames a sequence keeps
// in flight, --size, reading an input image. Each command is a class in its own file (Command.h lists them).
#include "Commands.h"

#include "core/Environment.h"
#include "gl/Gl.h"

#include <fmt/format.h>

#include <algorithm>
#include <thread>

namespace photopic::cli {

namespace fs = std::filesystem;

namespace {
bool gGlDebug = false;
bool gStatusLines = true;
} // namespace

bool statusLines() {
    return gStatusLines;
}

void setStatusLines(bool on) {
    gStatusLines = on;
}

void setGlDebug(bool on) {
    gGlDebug = on;
}

HeadlessContextCreateInfo commandContext() {
    return {.debug = gGlDebug || environmentSwitch("PHOTOPIC_GL_DEBUG")};
}

int defaultFramesInFlight() {
    const int cores = int(std::thread::hardware_concurrency());
    return cores <= 4 ? 3 : std::clamp(cores / 2, 3, 8);
}

Extent parseSize(const std::string& text, int minSide) {
    const std::optional<Extent> size = parseExtent(text, minSide);
    if (!size) {
        throw InputError(
            fmt::format("size '{}' is not WIDTHxHEIGHT with each side in [{}, 16384]", text, minSide));
    }
    return *size;
}

ImageF readInput(const fs::path& path, std::int64_t maxPixels) {
    try {
        return readImage(path, {.maxPixels = maxPixels});
    } catch (const IoError& e) {
        throw InputError(e.what());
    }
}

void requireTextureFits(const fs::path& path, int width, int height) {
    GLint limit = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &limit);
    if (width > limit || height > limit) {
        throw InputError(fmt::format("\"{}\": image is {}x{}, larger than this GPU's largest texture ({}x{}, "
                                     "GL_MAX_TEXTURE_SIZE); scale it down first",
                                     path.string(), width, height, limit, limit));
    }
}

} // namespace photopic::cli
