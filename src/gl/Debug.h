#pragma once
// KHR_debug routing: driver messages go to the Photopic log; errors are counted so tests fail on any of them.

#include <cstdint>

namespace photopic {

/// Enables synchronous debug output in the current context and routes it to the log.
void installDebugOutput();
/// Number of GL_DEBUG_TYPE_ERROR / high-severity messages seen since start (or the last reset).
std::uint64_t glDebugErrorCount();
void resetGlDebugErrorCount();

} // namespace photopic
