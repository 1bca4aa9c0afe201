#include "core/ShownText.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace photopic {

namespace {

/// Byte length of the well-formed UTF-8 sequence at `text[i]`, or 0 when it is not one.
std::size_t utf8Length(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(i);
    std::size_t length = 0;
    unsigned char low = 0x80; // bounds of the second byte (they exclude overlong forms and surrogates)
    unsigned char high = 0xbf;
    if (lead < 0x80) {
        return 1;
    } else if (lead >= 0xc2 && lead <= 0xdf) {
        length = 2;
    } else if (lead >= 0xe0 && lead <= 0xef) {
        length = 3;
        low = lead == 0xe0 ? 0xa0 : 0x80;
        high = lead == 0xed ? 0x9f : 0xbf;
    } else if (lead >= 0xf0 && lead <= 0xf4) {
        length = 4;
        low = lead == 0xf0 ? 0x90 : 0x80;
        high = lead == 0xf4 ? 0x8f : 0xbf;
    } else {
        return 0;
    }
    if (i + length > text.size() || byte(i + 1) < low || byte(i + 1) > high) {
        return 0;
    }
    for (std::size_t k = 2; k < length; ++k) {
        if (byte(i + k) < 0x80 || byte(i + k) > 0xbf) {
            return 0;
        }
    }
    return length;
}

/// Appends `text` to `out` until `out` holds `limit` bytes; false when something was left out.
bool appendBounded(std::string& out, std::string_view text, std::size_t limit) {
    if (out.size() >= limit) {
        return text.empty();
    }
    const std::size_t room = limit - out.size();
    out.append(text.substr(0, room));
    return text.size() <= room;
}

/// Compact JSON of `value` into `out`, at most `limit` bytes; containers below `depth` levels are elided.
bool appendJson(std::string& out, const nlohmann::json& value, std::size_t limit, int depth) {
    if (out.size() >= limit) {
        return false;
    }
    if (value.is_array() || value.is_object()) {
        const bool object = value.is_object();
        if (!appendBounded(out, object ? "{" : "[", limit)) {
            return false;
        }
        if (depth <= 0 && !value.empty()) {
            return appendBounded(out, object ? "...}" : "...]", limit);
        }
        bool first = true;
        for (auto it = value.begin(); it != value.end(); ++it) {
            if (!first && !appendBounded(out, ",", limit)) {
                return false;
            }
            first = false;
            if (object) {
                const std::string key =
                    nlohmann::json(it.key()).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
                if (!appendBounded(out, key + ":", limit)) {
                    return false;
                }
            }
            if (!appendJson(out, *it, limit, depth - 1)) {
                return false;
            }
        }
        return appendBounded(out, object ? "}" : "]", limit);
    }
    // A scalar: nlohmann's own text (strings escaped, control characters as \u00XX, bad UTF-8 as U+FFFD).
    return appendBounded(out, value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), limit);
}

} // namespace

std::optional<std::size_t> invalidUtf8Offset(std::string_view text) {
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t length = utf8Length(text, i);
        if (length == 0) {
            return i;
        }
        i += length;
    }
    return std::nullopt;
}

std::string shownText(std::string_view raw, std::size_t maxBytes) {
    std::string out;
    std::size_t i = 0;
    while (i < raw.size() && out.size() < maxBytes) {
        const std::size_t length = utf8Length(raw, i);
        const auto byte = static_cast<unsigned char>(raw[i]);
        if (length == 0 || byte < 0x20 || byte == 0x7f) {
            out += fmt::format("\\x{:02x}", byte);
            ++i;
        } else if (byte == '\\') {
            out += "\\\\";
            ++i;
        } else {
            out.append(raw.substr(i, length));
            i += length;
        }
    }
    if (i < raw.size()) {
        out += fmt::format("... ({} bytes)", raw.size());
    }
    return out;
}

std::string shownJson(const nlohmann::json& value, std::size_t maxBytes) {
    // Eight levels show any settings value whole; a deeper one is elided, so no recursion follows its depth.
    constexpr int kShownDepth = 8;
    std::string out;
    try {
        if (!appendJson(out, value, maxBytes, kShownDepth) || out.size() > maxBytes) {
            out.resize(std::min(out.size(), maxBytes));
            out += "...";
        }
    } catch (const nlohmann::json::exception&) {
        out += "...";
    }
    return out;
}

} // namespace photopic
