// libFuzzer harness: fuzz/FuzzTargets.h's cameraJson.
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    photopic::fuzz::cameraJson(data, size);
    return 0;
}
