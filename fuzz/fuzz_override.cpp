// libFuzzer harness: fuzz/FuzzTargets.h's settingsOverride.
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    photopic::fuzz::settingsOverride(data, size);
    return 0;
}
