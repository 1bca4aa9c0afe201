#pragma once
// The display domain's storage depth. Every pass after tone mapping writes the display image with an image
// store, whose format qualifier is fixed when the shader compiles; output.bitDepth picks RGBA8 or RGBA16
// (unorm) storage, so each such shader is built per depth, selected by DISPLAY_16
// (passes/common/display_format.h.glsl).

#include "gl/ShaderLibrary.h"

#include <string>

namespace photopic {

/// GL_RGBA8 at 8 bits, GL_RGBA16 at 16: the format of displayColor and debugColor.
[[nodiscard]] GLenum displayFormat(int bitDepth) noexcept;

/// One display-domain compute program, built for each storage depth it is asked for: the 8-bit program at
/// construction (a set-up boundary: throws GlError with the log), the 16-bit one by prepare(16) (called from
/// a pass's configure()) or, failing that, on first use.
class DisplayProgram {
public:
    DisplayProgram(std::string computeName, ShaderDefines defines);
    /// Builds the program for `bitDepth` if it is not built yet; throws GlError with the log.
    void prepare(int bitDepth);
    /// The program writing the display image at `bitDepth` (built first if need be).
    const Program& at(int bitDepth);

private:
    std::string mName;
    ShaderDefines mDefines; ///< bindings and the shader's own variant, without DISPLAY_16
    Program m8;
    Program m16;
};

} // namespace photopic
