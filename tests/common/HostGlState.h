#pragma once
// A host's GL state for the tests that run Photopic inside one: objects of the host's own bound at every
// binding point the library uses, and the state a host may leave on (scissor, masks, culling, polygon mode,
// rasterizer discard, sRGB writes, blending, depth, stencil, logic op). Shared by the GL tests of the
// pipeline and of the public API, which reach GL through different doors: both use libepoxy here.

#include <epoxy/gl.h>

#include <functional>
#include <string>
#include <vector>

namespace photopic::test {

/// What the host leaves bound: objects of its own at every binding point the pipeline uses.
struct HostObjects {
    GLuint framebuffer = 0, target = 0, program = 0, vao = 0, texture0 = 0, texture3 = 0, image = 0;
    GLuint ssbo = 0, ubo = 0, array = 0, sampler = 0;

    HostObjects();
    ~HostObjects();
    HostObjects(const HostObjects&) = delete;
    HostObjects& operator=(const HostObjects&) = delete;

    /// Binds every object and sets the host's viewport, scissor box and pixel-store alignments.
    void bind() const;
    /// Every binding bind() made, as the host left it; names what differs.
    [[nodiscard]] std::vector<std::string> changedBindings() const;
};

/// One piece of state a host may leave on.
struct HostState {
    const char* name;
    std::function<void()> set;
    std::function<bool()> stillSet; ///< the host's setting is in place after the call
};

/// Every host state the library must neither depend on nor change.
const std::vector<HostState>& hostStates();

/// GL's defaults, as a fresh context has them (bindings, capabilities, masks, functions), so a test can read
/// textures back after a host state.
void defaultState();

} // namespace photopic::test
