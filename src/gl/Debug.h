#pragma once
// KHR_debug routing: driver messages go to the Photopic log; errors are counted so tests fail on any of them.

#include <cstdint>

namespace photopic {

/// Enables synchronous debug output in the current context and routes it to the log.
void installDebugOutput();
/// Number of GL_DEBUG_TYPE_ERROR / high-severity messages seen since start (or the last reset).
std::uint64_t glDebugErrorCount();
/// Number of GL_DEBUG_TYPE_PERFORMANCE messages of medium or high severity since start (or the last reset):
/// the driver saying that it moves or copies memory, recompiles a shader or stalls because of how it is used.
/// NVIDIA's compile of a program for the draw state at its first draw is not counted (once per program and
/// stage since the reset); that program compiled again is.
std::uint64_t glDebugPerformanceWarningCount();
/// Number of GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR messages of medium or high severity since start (or the last
/// reset): e.g. a shadow sampler over a unit with no depth texture.
std::uint64_t glDebugUndefinedBehaviourCount();
/// Resets the counts, and forgets which programs were compiled for their draw state.
void resetGlDebugErrorCount();

} // namespace photopic
