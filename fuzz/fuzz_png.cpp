// libFuzzer harness: fuzz/FuzzTargets.h's pngImage.
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    photopic::fuzz::pngImage(data, size);
    return 0;
}
