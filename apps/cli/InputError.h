#pragma once
// The CLI's error for bad usage or bad input, on its own so that GL-free pieces (the camera JSON reader) can
// throw it without the commands' headers.

#include <stdexcept>

namespace photopic::cli {

/// Bad usage or bad input (a file that cannot be read, settings that do not validate): exit 2.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace photopic::cli
