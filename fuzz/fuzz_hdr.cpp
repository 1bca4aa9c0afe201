// libFuzzer harness: fuzz/FuzzTargets.h's hdrImage.
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    photopic::fuzz::hdrImage(data, size);
    return 0;
}
