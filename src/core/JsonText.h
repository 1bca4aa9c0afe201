#pragma once
// JSON documents that people write (settings, cameras, models): parsed with a nesting limit, so a hostile
// file cannot exhaust the stack of whatever walks or prints the value later, and with duplicate keys
// refused, since a key written twice is a mistake that "the last one wins" would hide.

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <string_view>

namespace photopic {

struct JsonTextLimits {
    int maxDepth = 64;               ///< nesting of arrays and objects; the deepest real document uses 6
    bool rejectDuplicateKeys = true; ///< a key twice in one object is an error naming it and its path
};

/// A document that parsed as JSON but breaks a limit, or does not parse: the message reads on its own
/// ("duplicate key \"mode\" at /postEffects/bloom", "nested deeper than 64 levels at /a/0/0/...", or
/// nlohmann's parse message without its "[json.exception...]" prefix).
class JsonTextError : public std::runtime_error {
public:
    enum class Kind { Syntax, TooDeep, DuplicateKey, NumberOutOfRange };
    JsonTextError(Kind what, const std::string& message)
        : std::runtime_error(message)
        , kind(what) {}
    Kind kind;
};

/// Parses `text` under `limits`; throws JsonTextError. Numbers beyond double range (1e400) are errors
/// that say so.
[[nodiscard]] nlohmann::json parseJsonText(std::string_view text, const JsonTextLimits& limits = {});

} // namespace photopic
