#pragma once
// GLSL embedded at build time (cmake/EmbedShaders.cmake), keyed by path below src/
// ("passes/x/x_y.frag.glsl"). Preprocessing: "#version 450 core", then the variant's #defines, then the
// source with #include "file" resolved (relative to the including file, else to src/), each file once.

#include "gl/Objects.h"

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace photopic {

/// Every embedded shader source (generated).
const std::map<std::string, std::string_view>& embeddedShaders();

using ShaderDefines = std::vector<std::pair<std::string, std::string>>;

/// Full source of `name` ready for glShaderSource; throws GlError naming the file when a source or include is
/// missing.
std::string preprocessShader(std::string_view name, const ShaderDefines& defines = {});

/// Compiles and links; throws GlError with the file name and the driver's log.
Program makeComputeProgram(std::string_view computeName, const ShaderDefines& defines = {});
Program makeGraphicsProgram(std::string_view vertexName, std::string_view fragmentName,
                            const ShaderDefines& defines = {});

/// Work groups of a full-screen compute pass: 8x8 invocations, one pixel each, covering `extent` (shaders
/// return early outside the image).
inline constexpr int kPixelGroupSize = 8;
void dispatchPixels(Extent extent) noexcept;
/// After a pass's image stores: whatever reads the image next (a sampler, an image load, a blit, a readback
/// or a copy) sees the stores.
void imageWriteBarrier() noexcept;

/// Set uniforms by name on a program (DSA: no bind needed). Missing names are ignored (optimised away).
void setUniform(const Program& p, const char* name, float v);
void setUniform(const Program& p, const char* name, int v);
void setUniform(const Program& p, const char* name, float x, float y);
void setUniform(const Program& p, const char* name, float x, float y, float z);
void setUniform(const Program& p, const char* name, float x, float y, float z, float w);

} // namespace photopic
