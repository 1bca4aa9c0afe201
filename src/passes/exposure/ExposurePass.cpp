#include "passes/exposure/ExposurePass.h"

#include "passes/Bindings.h"

#include <algorithm>
#include <array>

namespace photopic {

ExposurePass::ExposurePass()
    : mProgram(makeComputeProgram("passes/exposure/exposure_adapt.comp.glsl", bindingDefines())) {}

void ExposurePass::execute(const Inputs& in) noexcept {
    DebugGroup group("exposure adaptation");
    ScopedGpuTimer timer(in.timers, "exposure adaptation", double(sizeof(GpuExposureState)) * 2 + 1024);
    const AutoExposureSettings& s = *in.settings;
    const Program& p = mProgram;
    setUniform(p, "uAutoEnabled", s.enabled ? 1 : 0);
    setUniform(p, "uMetered", in.metered ? 1 : 0);
    setUniform(p, "uHistogramBuilt", in.histogramBuilt ? 1 : 0);
    setUniform(p, "uMeteringMode", int(s.metering));
    setUniform(p, "uReset", in.reset ? 1 : 0);
    setUniform(p, "uDt", in.dt);
    setUniform(p, "uManualEV", in.manualEV);
    setUniform(p, "uKeyValue", s.keyValue);
    setUniform(p, "uCompensationEV", s.compensationEV);
    setUniform(p, "uMinEV", s.minEV);
    setUniform(p, "uMaxEV", s.maxEV);
    // Settings validation caps the curve at kMaxCompensationCurvePoints; the clamp keeps an unvalidated
    // struct from overrunning the shader's array.
    const int curveCount = int(std::min(s.compensationCurve.size(), kMaxCompensationCurvePoints));
    std::array<float, kMaxCompensationCurvePoints * 2> curve{};
    for (int i = 0; i < curveCount; ++i) {
        curve[std::size_t(2 * i)] = s.compensationCurve[std::size_t(i)].x;
        curve[std::size_t(2 * i + 1)] = s.compensationCurve[std::size_t(i)].y;
    }
    glProgramUniform2fv(p.id(), glGetUniformLocation(p.id(), "uCurve"), GLsizei(kMaxCompensationCurvePoints),
                        curve.data());
    setUniform(p, "uCurveCount", curveCount);
    setUniform(p, "uAdaptation", int(s.adaptation));
    setUniform(p, "uTauBrighten", s.tauBrighten);
    setUniform(p, "uTauDarken", s.tauDarken);
    setUniform(p, "uSpeedUp", s.speedUp);
    setUniform(p, "uSpeedDown", s.speedDown);
    setUniform(p, "uTransitionEV", s.transitionEV);
    setUniform(p, "uDeadbandEV", s.deadbandEV);
    setUniform(p, "uMaxDt", s.maxDt);
    setUniform(p, "uLog2Min", s.histogramLog2Min);
    setUniform(p, "uLog2Max", s.histogramLog2Max);
    setUniform(p, "uLowPercent", s.lowPercent);
    setUniform(p, "uHighPercent", s.highPercent);

    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingExposureState, in.exposureState->id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingHistogram, in.histogram->id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingMetering, in.metering->id());
    p.use();
    glDispatchCompute(1, 1, 1);
    // Later passes read the state as an SSBO; the readback copies it.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

} // namespace photopic
