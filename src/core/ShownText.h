#pragma once
// One formatter for "the value you gave" in an error message: whatever a user or a file supplied (a
// `--set` value, an option's argument, a JSON value) is shown bounded in length and safe for a terminal.

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace photopic {

/// The default cut of shownText and shownJson: enough for any real value, a line at most.
inline constexpr std::size_t kShownMaxBytes = 120;

/// The offset of the first byte that does not belong to well-formed UTF-8 (RFC 3629: no overlong forms, no
/// surrogates, nothing above U+10FFFF), or nullopt when all of `text` is UTF-8.
[[nodiscard]] std::optional<std::size_t> invalidUtf8Offset(std::string_view text);

/// `raw` for a message: control characters (ESC included) and bytes that are not UTF-8 written as \xNN, a
/// backslash as \\, and text longer than `maxBytes` cut there with "... (N bytes)" naming the whole length.
[[nodiscard]] std::string shownText(std::string_view raw, std::size_t maxBytes = kShownMaxBytes);

/// A JSON value as compact JSON text for a message, built without recursion past a few levels (a value
/// nested 70,000 deep is shown as "[[[[[[[[...") and cut like shownText. Never throws.
[[nodiscard]] std::string shownJson(const nlohmann::json& value, std::size_t maxBytes = kShownMaxBytes);

} // namespace photopic
