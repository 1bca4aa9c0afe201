#pragma once
// Photopic's environment variables (PHOTOPIC_FORCE_LDR, PHOTOPIC_GL_DEBUG, PHOTOPIC_DATA_DIR, the bloom
// kernel overrides): one reading of what "set" means for all of them.

#include <optional>
#include <string_view>

namespace photopic {

/// The value of the environment variable `name`, or nothing when it is unset or empty.
[[nodiscard]] std::optional<std::string_view> environmentValue(const char* name);

/// Whether the switch `name` is on: set to anything but empty or "0" (PHOTOPIC_FORCE_LDR=1).
[[nodiscard]] bool environmentSwitch(const char* name);

} // namespace photopic
