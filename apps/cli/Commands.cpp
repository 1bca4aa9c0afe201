// What the commands share: the status lines (-q), the GL context a command opens, the frames a sequence keeps
// in flight. Each command lives in its own file: ImageCommand.cpp, InfoCommand.cpp, SettingsCommand.cpp,
// SceneCommand.cpp, ExposeCommand.cpp, MeterCommand.cpp, FarmCommand.cpp, Bench.cpp and the demos.
#include "Commands.h"

#include "core/Environment.h"

#include <algorithm>
#include <thread>

namespace photopic::cli {

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

} // namespace photopic::cli
