#include "core/Environment.h"

#include <cstdlib>

namespace photopic {

std::optional<std::string_view> environmentValue(const char* name) {
    const char* value = std::getenv(name);
    if (value == nullptr || *value == '\0') {
        return std::nullopt;
    }
    return std::string_view(value);
}

bool environmentSwitch(const char* name) {
    const std::optional<std::string_view> value = environmentValue(name);
    return value.has_value() && *value != "0";
}

} // namespace photopic
