// libFuzzer harness: fuzz/FuzzTargets.h's gltfModel.
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    photopic::fuzz::gltfModel(data, size);
    return 0;
}
