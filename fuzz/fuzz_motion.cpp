// libFuzzer harness: fuzz/FuzzTargets.h's motionCsv.
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    photopic::fuzz::motionCsv(data, size);
    return 0;
}
