// libFuzzer harness: fuzz/FuzzTargets.h's settingsJson.
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    photopic::fuzz::settingsJson(data, size);
    return 0;
}
