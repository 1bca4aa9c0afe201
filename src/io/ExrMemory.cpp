#include "io/ExrMemory.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace photopic::detail {

namespace {

int64_t readMemory(exr_const_context_t, void* user, void* buffer, uint64_t size, uint64_t offset,
                   exr_stream_error_func_ptr_t) {
    const std::span<const unsigned char> bytes = static_cast<const MemorySource*>(user)->bytes;
    if (offset >= bytes.size())
        return 0;
    const std::uint64_t n = std::min<std::uint64_t>(size, bytes.size() - offset);
    std::memcpy(buffer, bytes.data() + offset, n);
    return int64_t(n);
}

int64_t memorySize(exr_const_context_t, void* user) {
    return int64_t(static_cast<const MemorySource*>(user)->bytes.size());
}

} // namespace

void quiet(exr_const_context_t, exr_result_t, const char*) {}

void keepMessage(exr_const_context_t context, exr_result_t, const char* message) {
    void* user = nullptr;
    if (exr_get_user_data(context, &user) == EXR_ERR_SUCCESS && user != nullptr && message != nullptr)
        static_cast<MemorySource*>(user)->error = message;
}

bool startMemoryRead(ExrReadContext& context, MemorySource& source, exr_error_handler_cb_t onError) {
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = &source;
    init.read_fn = &readMemory;
    init.size_fn = &memorySize;
    init.error_handler_fn = onError;
    return exr_start_read(&context.handle, "memory", &init) == EXR_ERR_SUCCESS;
}

} // namespace photopic::detail
