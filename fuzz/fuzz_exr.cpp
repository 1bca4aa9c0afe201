// libFuzzer harness: fuzz/FuzzTargets.h's exrImage.
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    photopic::fuzz::exrImage(data, size);
    return 0;
}
