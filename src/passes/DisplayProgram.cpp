#include "passes/DisplayProgram.h"

#include "passes/Bindings.h"

#include <utility>

namespace photopic {

GLenum displayFormat(int bitDepth) noexcept {
    return bitDepth == 16 ? GL_RGBA16 : GL_RGBA8;
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
    ShaderDefines defines = mDefines;
    if (bitDepth == 16) {
        defines.emplace_back("DISPLAY_16", "1");
    }
    program = makeComputeProgram(mName, defines);
}

const Program& DisplayProgram::at(int bitDepth) {
    prepare(bitDepth);
    return bitDepth == 16 ? m16 : m8;
}

} // namespace photopic
