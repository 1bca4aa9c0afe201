#include "passes/DisplayProgram.h"

#include "gl/Capabilities.h"
#include "passes/Bindings.h"

#include <utility>

namespace photopic {

GLenum displayFormat(int bitDepth) noexcept {
    return bitDepth == 16 ? GL_RGBA16 : GL_RGBA8;
}

namespace {
std::optional<bool> gForcedRounding;
} // namespace

bool displayStoresRound() {
    return gForcedRounding.value_or(!isSoftwareRenderer());
}

void forceDisplayRounding(std::optional<bool> round) {
    gForcedRounding = round;
}

ShaderDefines withDisplayStore(ShaderDefines defines, int bitDepth) {
    if (bitDepth == 16) {
        defines.emplace_back("DISPLAY_16", "1");
    }
    if (displayStoresRound()) {
        defines.emplace_back("DISPLAY_ROUNDING", "1");
    }
    return defines;
}

DisplayProgram::DisplayProgram(std::string computeName, ShaderDefines defines)
    : mName(std::move(computeName))
    , mDefines(bindingDefines(std::move(defines))) {
    prepare(8);
}

void DisplayProgram::prepare(int bitDepth) {
    Program& program = bitDepth == 16 ? m16 : m8;
    if (program.valid()) {
        return;
    }
    program = makeComputeProgram(mName, withDisplayStore(mDefines, bitDepth));
}

const Program& DisplayProgram::at(int bitDepth) {
    prepare(bitDepth);
    return bitDepth == 16 ? m16 : m8;
}

} // namespace photopic
