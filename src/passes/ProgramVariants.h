#pragma once
// A pass's programs with their slots, and the compile-time variants of one shader a pass builds on first use
// (a define per setting or input the frame has, so that no program carries a path its frame cannot take:
// SIMD CPU renderers run every side of a branch; docs/architecture.md, "Compute passes").

#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"
#include "passes/Bindings.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <utility>

namespace photopic {

/// Base of a program-and-slots struct; the derived struct's slots are looked up after the program is made:
///     struct Resolve : ProgramSlots {
///         using ProgramSlots::ProgramSlots;
///         SamplerSlot depth = program.sampler("uLinearDepth");
///     };
struct ProgramSlots {
    explicit ProgramSlots(Program p)
        : program(std::move(p)) {}
    Program program;
};

/// Up to N variants of one compute shader, each built with its defines (and the binding defines) the first
/// time the pass asks for it, as `Slots` (a ProgramSlots).
template <class Slots, std::size_t N>
class ProgramVariants {
public:
    explicit ProgramVariants(std::string shader)
        : mShader(std::move(shader)) {}
    /// Variant `key` (below N), built with `defines` when it is first asked for; a key names one set of
    /// defines for the pass's life.
    const Slots& get(std::size_t key, const ShaderDefines& defines) {
        std::optional<Slots>& variant = mVariants.at(key);
        if (!variant) {
            variant.emplace(makeComputeProgram(mShader, bindingDefines(defines)));
        }
        return *variant;
    }

private:
    std::string mShader;
    std::array<std::optional<Slots>, N> mVariants;
};

/// The position of `format` in `formats` (a program per format of an input loaded as an image, which its
/// shader declares in the texture's format); formats.size() when absent.
inline std::size_t formatIndex(GLenum format, std::span<const GLenum> formats) noexcept {
    return std::size_t(std::find(formats.begin(), formats.end(), format) - formats.begin());
}

/// The define that names an image's format qualifier, `name` = "rg16f" for an RG16F texture.
inline std::pair<std::string, std::string> imageFormatDefine(std::string name, GLenum format) {
    return {std::move(name), std::string(imageFormatQualifier(format))};
}

} // namespace photopic
