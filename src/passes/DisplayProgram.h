#pragma once
// The display domain's storage depth. Every pass after tone mapping writes the display image with an image
// store, whose format qualifier is fixed when the shader compiles; output.bitDepth picks RGBA8 or RGBA16
// (unorm) storage, so each such shader is built per depth, selected by DISPLAY_16
// (passes/common/display_format.h.glsl).

#include "gl/ShaderLibrary.h"

#include <optional>
#include <string>

namespace photopic {

/// GL_RGBA8 at 8 bits, GL_RGBA16 at 16: the format of displayColor and debugColor.
[[nodiscard]] GLenum displayFormat(int bitDepth) noexcept;

/// Whether the display passes put each value on its code themselves before the image store
/// (passes/common/display_format.h.glsl onDisplayCode): on a GPU, whose store may round a value near a half
/// code either way; not on a software renderer, whose store rounds to nearest even itself (the same bits, and
/// the tone-map pass's rounding was 1.5% of a 1080p chain there). Programs read it when they are built; tests
/// force either value (nullopt: by the renderer again).
[[nodiscard]] bool displayStoresRound();
void forceDisplayRounding(std::optional<bool> round);
/// `defines` plus the display store's: DISPLAY_16 at 16 bits, DISPLAY_ROUNDING where displayStoresRound().
[[nodiscard]] ShaderDefines withDisplayStore(ShaderDefines defines, int bitDepth);

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
    /// A sampler or image of the program by name (Program::sampler/image): one slot serves both depths, whose
    /// builds differ only in the image format, never in a unit.
    [[nodiscard]] SamplerSlot sampler(std::string_view name) const { return m8.sampler(name); }
    [[nodiscard]] ImageSlot image(std::string_view name) const { return m8.image(name); }

private:
    std::string mName;
    ShaderDefines mDefines; ///< bindings and the shader's own variant, without DISPLAY_16
    Program m8;
    Program m16;
};

} // namespace photopic
