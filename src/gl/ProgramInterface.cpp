// Program's samplers and images by name (SamplerSlot, ImageSlot), binding through them, and the check that a
// dispatch found every one its program declares bound.

#include "gl/Objects.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string_view>

namespace photopic {

namespace {

/// Per unit (0-63), the bind count when a slot last bound it: a program's sampler or image is bound for a
/// dispatch when its unit's count is past the program's last check.
std::array<std::uint64_t, 64> gSamplerBound{};
std::array<std::uint64_t, 64> gImageBound{};
std::uint64_t gBinds = 0;
BindingProblemHandler gBindingProblemHandler;

void stamp(std::array<std::uint64_t, 64>& bound, GLint unit) noexcept {
    if (unit < 64) {
        bound[std::size_t(unit)] = ++gBinds;
    }
}

bool isIdentifierChar(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

/// The position of each whole-identifier occurrence of `name` in `source`, in order, to `visit` until it
/// returns true; whether one did.
template <class Visit>
bool findIdentifier(std::string_view source, std::string_view name, Visit visit) {
    for (auto at = source.find(name); at != std::string_view::npos; at = source.find(name, at + 1)) {
        const bool startsWord = at == 0 || !isIdentifierChar(source[at - 1]);
        const std::size_t end = at + name.size();
        const bool endsWord = end == source.size() || !isIdentifierChar(source[end]);
        if (startsWord && endsWord && visit(at)) {
            return true;
        }
    }
    return false;
}

/// Whether `source` names `name` as a whole identifier.
bool names(std::string_view source, std::string_view name) {
    return findIdentifier(source, name, [](std::size_t) { return true; });
}

std::string_view trimmed(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) {
        return {};
    }
    return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

/// The format a format-qualifier word names: the qualifier itself (`rgba16f`), or the value of the define it
/// names when every definition (in whichever branch of the preprocessor) names the same format. 0 for a word
/// that names none, or a define whose branches name different ones.
GLenum formatOfWord(std::string_view source, std::string_view word) {
    if (const GLenum format = imageFormatFromQualifier(word)) {
        return format;
    }
    GLenum defined = 0;
    bool ambiguous = false;
    findIdentifier(source, word, [&](std::size_t at) {
        const std::string_view before = source.substr(0, at);
        const auto hash = before.rfind('#');
        if (hash == std::string_view::npos || trimmed(before.substr(hash + 1)) != "define") {
            return false;
        }
        std::string_view value = source.substr(at + word.size());
        value = trimmed(value.substr(0, value.find('\n')));
        const GLenum format = imageFormatFromQualifier(value);
        ambiguous = ambiguous || format == 0 || (defined != 0 && format != defined);
        defined = format;
        return false;
    });
    return ambiguous ? 0 : defined;
}

/// The uniform `name` of kind `image`; nullptr when the program has none active (optimised away, when its
/// source names it). Throws GlError when the program declares no such sampler or image.
const ProgramInterface::Uniform* lookUp(const ProgramInterface* interface, std::string_view name,
                                        bool image) {
    const char* kind = image ? "image" : "sampler";
    if (interface == nullptr) {
        throw GlError(fmt::format("{} {}: the program was not reflected", kind, name));
    }
    const auto& all = interface->uniforms;
    const auto it = std::find_if(all.begin(), all.end(), [&](const auto& u) { return u.name == name; });
    if (it != all.end()) {
        if (it->image != image) {
            throw GlError(
                fmt::format("{}: {} is not {} {}", interface->label, name, image ? "an" : "a", kind));
        }
        return &*it;
    }
    if (!names(interface->source, name)) {
        throw GlError(fmt::format("{} declares no {} {}", interface->label, kind, name));
    }
    return nullptr; // declared, and the compiler optimised it away: the slot binds nothing
}

} // namespace

GLenum declaredImageFormat(std::string_view source, std::string_view name) {
    GLenum found = 0;
    bool ambiguous = false;
    findIdentifier(source, name, [&](std::size_t at) {
        // The statement up to the name: `layout(...) <qualifiers> <image type>`, the name then ending it.
        const std::string_view before = source.substr(0, at);
        const std::string_view statement = before.substr(before.find_last_of(";{}") + 1);
        const auto next = source.find_first_not_of(" \t\r\n", at + name.size());
        const auto layout = statement.rfind("layout");
        const auto open =
            layout == std::string_view::npos ? layout : statement.find_first_not_of(" \t", layout + 6);
        const auto close = open == std::string_view::npos || statement[open] != '('
                               ? std::string_view::npos
                               : statement.find(')', open);
        if (next == std::string_view::npos || source[next] != ';' || close == std::string_view::npos ||
            statement.find_first_of("()", close + 1) != std::string_view::npos ||
            statement.find("image", close) == std::string_view::npos) {
            return false; // a use, or a declaration of something else
        }
        GLenum format = 0;
        std::string_view entries = statement.substr(open + 1, close - open - 1);
        while (!entries.empty() && format == 0) {
            const auto comma = entries.find(',');
            const std::string_view entry = trimmed(entries.substr(0, comma));
            entries = comma == std::string_view::npos ? std::string_view{} : entries.substr(comma + 1);
            if (entry.find('=') == std::string_view::npos) {
                format = formatOfWord(source, entry);
            }
        }
        ambiguous = ambiguous || format == 0 || (found != 0 && format != found);
        found = format;
        return false;
    });
    return ambiguous ? 0 : found;
}

SamplerSlot Program::sampler(std::string_view name) const {
    const ProgramInterface::Uniform* u = lookUp(mInterface.get(), name, false);
    return SamplerSlot{u ? u->unit : -1};
}

ImageSlot Program::image(std::string_view name) const {
    const ProgramInterface::Uniform* u = lookUp(mInterface.get(), name, true);
    return u ? ImageSlot{u->unit, u->format, mInterface->label, u->name} : ImageSlot{};
}

void bind(SamplerSlot slot, const Texture& texture) noexcept {
    if (slot.active()) {
        glBindTextureUnit(GLuint(slot.unit), texture.id());
        stamp(gSamplerBound, slot.unit);
    }
}

void bind(SamplerSlot slot, const Texture& texture, const Sampler& sampler) noexcept {
    bind(slot, texture);
    bindSampler(slot, &sampler);
}

void unbind(SamplerSlot slot) noexcept {
    if (slot.active()) {
        glBindTextureUnit(GLuint(slot.unit), 0);
        if (slot.unit < 64) {
            gSamplerBound[std::size_t(slot.unit)] = 0; // a program reading it next finds it unbound
        }
    }
}

void bindSampler(SamplerSlot slot, const Sampler* sampler) noexcept {
    if (slot.active()) {
        glBindSampler(GLuint(slot.unit), sampler ? sampler->id() : 0);
    }
}

void bind(ImageSlot slot, const Texture& texture, ImageAccess access, int level) {
    if (slot.active()) {
        if (slot.format != 0 && slot.format != texture.format() && gBindingProblemHandler) {
            gBindingProblemHandler(fmt::format(
                "{}: image {} (unit {}) is declared {}, bound to a {} texture", slot.label, slot.name,
                slot.unit, imageFormatQualifier(slot.format), formatName(texture.format())));
        }
        glBindImageTexture(GLuint(slot.unit), texture.id(), level, GL_FALSE, 0, GLenum(access),
                           texture.format());
        stamp(gImageBound, slot.unit);
    }
}

bool checkBindings(const Program& program) {
    const ProgramInterface* interface = program.interface();
    if (interface == nullptr) {
        return true;
    }
    bool bound = true;
    for (const ProgramInterface::Uniform& u : interface->uniforms) {
        if (u.unit < 0 || u.unit >= 64 ||
            (u.image ? gImageBound : gSamplerBound)[std::size_t(u.unit)] > interface->checked) {
            continue;
        }
        bound = false;
        if (gBindingProblemHandler) {
            gBindingProblemHandler(
                fmt::format("{}: {} {} (unit {}) was not bound since the program's last dispatch",
                            interface->label, u.image ? "image" : "sampler", u.name, u.unit));
        }
    }
    interface->checked = gBinds;
    return bound;
}

BindingProblemHandler setBindingProblemHandler(BindingProblemHandler handler) {
    return std::exchange(gBindingProblemHandler, std::move(handler));
}

} // namespace photopic
