#include "passes/Bindings.h"

#include <string>

namespace photopic {

ShaderDefines bindingDefines(ShaderDefines extra) {
    ShaderDefines defines = {
        {"BINDING_EXPOSURE_STATE", std::to_string(kBindingExposureState)},
        {"BINDING_EXPOSURE_UNIFORM", std::to_string(kBindingExposureUniform)},
        {"BINDING_HISTOGRAM", std::to_string(kBindingHistogram)},
        {"BINDING_METERING", std::to_string(kBindingMetering)},
        {"BINDING_PROBE", std::to_string(kBindingProbe)},
        {"BINDING_SUBJECT_STATE", std::to_string(kBindingSubjectState)},
        {"BINDING_TILE_LIST", std::to_string(kBindingTileList)},
        {"BINDING_PARAMETERS", std::to_string(kBindingParameters)},
    };
    defines.insert(defines.end(), extra.begin(), extra.end());
    return defines;
}

void bindExposureStateForReading(const Buffer& state) {
    glBindBufferBase(GL_UNIFORM_BUFFER, kBindingExposureUniform, state.id());
}

} // namespace photopic
