#pragma once
// The one include for GL declarations (libepoxy resolves entry points for whatever context is current).

#include <epoxy/gl.h>

#include <stdexcept>
#include <string>

namespace photopic {

/// Size of a 2D image in pixels.
struct Extent {
    int width = 0;
    int height = 0;
    friend bool operator==(const Extent&, const Extent&) = default;
    [[nodiscard]] bool empty() const { return width <= 0 || height <= 0; }
};

/// Thrown at GL set-up boundaries (context creation, shader compilation, incomplete framebuffers).
class GlError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace photopic
