#pragma once
// Supersampling anti-aliasing for hosts that can render a frame several times: each sub-frame is rendered
// with its own sub-pixel jitter and folded into a weighted mean in HDR; the mean is the frame's colour.
// Weights come from the reconstruction filter evaluated at each sub-frame's offset from the pixel centre: a
// box (every sample alike) or Blackman-Harris (samples near the centre count more, less aliasing of fine
// detail).

#include "core/Settings.h"
#include "gl/GpuTimers.h"
#include "gl/Objects.h"

#include <cstddef>
#include <glm/vec2.hpp>

namespace photopic {

/// std140 mirror of ssaa_accumulate.comp.glsl's parameter block.
struct SsaaAccumulateParameters {
    float fraction = 1.0f; ///< w_i / W_i; 1 for the first sub-frame
    float padding[3] = {};
};
static_assert(sizeof(SsaaAccumulateParameters) == 16 && offsetof(SsaaAccumulateParameters, fraction) == 0);

/// The reconstruction weight of a sample `offset` pixels from the pixel centre.
[[nodiscard]] float ssaaWeight(SsaaFilter filter, glm::vec2 offset) noexcept;

class SsaaAccumulator {
public:
    SsaaAccumulator();
    /// Starts a frame's mean at `extent` (the texture is remade only when the extent changes).
    void begin(Extent extent);
    /// Folds one sub-frame (any float colour format, `extent`) into the mean with weight `weight`.
    void add(const Texture& subframe, float weight, GpuTimers* timers);
    /// The weighted mean of the sub-frames added since begin() (RGBA32F).
    [[nodiscard]] const Texture& mean() const { return mMean; }

private:
    Program mProgram;
    SamplerSlot mSubframe = mProgram.sampler("uSubframe");
    ImageSlot mMeanSlot = mProgram.image("uMean");
    ParameterBlock<SsaaAccumulateParameters> mParameters;
    Texture mMean;
    float mWeightSum = 0.0f;
    int mCount = 0;
};

} // namespace photopic
