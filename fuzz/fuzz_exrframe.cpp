// libFuzzer harness: fuzz/FuzzTargets.h's exrFrame.
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    photopic::fuzz::exrFrame(data, size);
    return 0;
}
