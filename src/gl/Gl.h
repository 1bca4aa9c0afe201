#pragma once
// The one include for GL declarations (libepoxy resolves entry points for whatever context is current).

#include <epoxy/gl.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace photopic {

/// Size of a 2D image in pixels.
struct Extent {
    int width = 0;
    int height = 0;
    friend bool operator==(const Extent&, const Extent&) = default;
    [[nodiscard]] bool empty() const { return width <= 0 || height <= 0; }
};

/// "1920x1080" (or "1920X1080") -> {1920, 1080}, each side in [minSide, maxSide]; nothing for any other text.
std::optional<Extent> parseExtent(std::string_view text, int minSide = 1, int maxSide = 16384);

/// Thrown at GL set-up boundaries (context creation, shader compilation, incomplete framebuffers).
class GlError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace photopic
