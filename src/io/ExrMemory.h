#pragma once
// Internal to the io library: an OpenEXR file in memory opened with OpenEXR's core library (openexr.h), for
// the chunk checks (ExrChunks.cpp) and the ZIP scanline reader (ExrZip.cpp).

#include <openexr.h>

#include <span>
#include <string>

namespace photopic::detail {

/// An OpenEXR file in memory, as the core library's read callbacks see it, and the library's last error
/// message about it (kept by keepMessage; `quiet` keeps none).
struct MemorySource {
    std::span<const unsigned char> bytes;
    std::string error;
};

/// Any failure here falls back to Imf::InputFile, which reports it in its own words: nothing to print.
void quiet(exr_const_context_t, exr_result_t, const char*);

/// Collects the core library's last error message (its error handler's user data).
void keepMessage(exr_const_context_t context, exr_result_t, const char* message);

/// A core library read context, finished when it goes.
struct ExrReadContext {
    exr_context_t handle = nullptr;
    ExrReadContext() = default;
    ExrReadContext(const ExrReadContext&) = delete;
    ExrReadContext& operator=(const ExrReadContext&) = delete;
    ~ExrReadContext() {
        if (handle != nullptr)
            exr_finish(&handle);
    }
};

/// Opens `source` for reading with the core library, its errors going to `onError`; false when the header
/// cannot be read.
bool startMemoryRead(ExrReadContext& context, MemorySource& source, exr_error_handler_cb_t onError);

} // namespace photopic::detail
