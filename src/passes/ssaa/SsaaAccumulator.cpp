#include "passes/ssaa/SsaaAccumulator.h"

#include "passes/Bindings.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace photopic {

float ssaaWeight(SsaaFilter filter, glm::vec2 offset) noexcept {
    if (filter == SsaaFilter::Box) {
        return 1.0f;
    }
    // Blackman-Harris window (Harris 1978, four terms) over a radius of one pixel around the centre: a
    // sample at the pixel's corner (0.71 px) still counts about 4%, one at the centre fully.
    constexpr float kRadius = 1.0f;
    const float x = std::clamp(0.5f + 0.5f * glm::length(offset) / kRadius, 0.0f, 1.0f); // 0.5 at the centre
    const float t = 2.0f * std::numbers::pi_v<float> * x;
    return 0.35875f - 0.48829f * std::cos(t) + 0.14128f * std::cos(2.0f * t) - 0.01168f * std::cos(3.0f * t);
}

SsaaAccumulator::SsaaAccumulator()
    : mProgram(makeComputeProgram("passes/ssaa/ssaa_accumulate.comp.glsl", bindingDefines()))
    , mParameters("ssaa accumulate parameters") {}

void SsaaAccumulator::begin(Extent extent) {
    if (!mMean.valid() || mMean.extent() != extent) {
        mMean = Texture({.extent = extent, .format = GL_RGBA32F, .debugName = "ssaa mean"});
    }
    mWeightSum = 0.0f;
    mCount = 0;
}

void SsaaAccumulator::add(const Texture& subframe, float weight, GpuTimers* timers) {
    const Extent e = mMean.extent();
    ScopedGpuTimer timer(timers, "ssaa accumulate",
                         double(e.width) * e.height * (bytesPerTexel(subframe.format()) + 32.0));
    weight = std::max(weight, 1e-6f);
    mWeightSum += weight;
    mParameters.update({.fraction = mCount == 0 ? 1.0f : weight / mWeightSum});
    mParameters.bind(kBindingParameters);
    mProgram.use();
    bind(mSubframe, subframe);
    bind(mMeanSlot, mMean, ImageAccess::ReadWrite);
    dispatch(mProgram, e, Barrier::ComputeRead);
    ++mCount;
}

} // namespace photopic
