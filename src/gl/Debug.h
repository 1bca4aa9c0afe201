#pragma once
// KHR_debug routing: driver messages go to the Photopic log; errors are counted so tests fail on any of them.

#include <cstdint>

namespace photopic {

/// Enables synchronous debug output in the current context and routes it to the log.
void installDebugOutput();
/// Number of GL_DEBUG_TYPE_ERROR / high-severity messages seen since start (or the last reset).
std::uint64_t glDebugErrorCount();
/// Number of GL_DEBUG_TYPE_PERFORMANCE messages of medium or high severity since start (or the last reset):
/// the driver saying that it moves or copies memory or stalls because of how it is used. Its compiles of a
/// program for a draw state are counted apart (glDebugRecompileCount).
std::uint64_t glDebugPerformanceWarningCount();
/// Number of NVIDIA's "shader in program N is being recompiled based on GL state" since start (or the last
/// reset). The driver compiles a graphics program's final code for each draw state it meets, once: its
/// in-memory and disk caches keep each (a warm disk cache reports none). So compiles while a renderer meets
/// its states are warm-up, and only a compile in a frame that repeats an earlier frame's states is a cost
/// (the steady-state tests check that).
std::uint64_t glDebugRecompileCount();
/// Number of GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR messages of medium or high severity since start (or the last
/// reset): e.g. a shadow sampler over a unit with no depth texture.
std::uint64_t glDebugUndefinedBehaviourCount();
/// Resets the counts.
void resetGlDebugErrorCount();

} // namespace photopic
