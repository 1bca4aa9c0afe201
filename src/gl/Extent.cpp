#include "gl/Gl.h"

#include <charconv>

namespace photopic {

std::optional<Extent> parseExtent(std::string_view text, int minSide, int maxSide) {
    const auto x = text.find_first_of("xX");
    if (x == std::string_view::npos) {
        return std::nullopt;
    }
    const auto side = [&](std::string_view digits) -> std::optional<int> {
        int value = 0;
        const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (digits.empty() || error != std::errc{} || end != digits.data() + digits.size() ||
            value < minSide || value > maxSide) {
            return std::nullopt;
        }
        return value;
    };
    const auto w = side(text.substr(0, x));
    const auto h = side(text.substr(x + 1));
    if (!w || !h) {
        return std::nullopt;
    }
    return Extent{*w, *h};
}

} // namespace photopic
