#pragma once

#include "gl/GpuTimers.h"
#include "gl/Objects.h"

namespace photopic {

/// Input colour (any float format the host gives) -> RGBA16F with NaN/Inf/negative -> 0 and values < 65000.
class SanitizePass {
public:
    struct Inputs {
        const Texture* color = nullptr;
        GpuTimers* timers = nullptr;
    };
    SanitizePass();
    void resize(Extent extent);
    const Texture& execute(const Inputs& in);
    [[nodiscard]] const Texture& output() const { return mOutput; }

private:
    Program mProgram;
    Texture mOutput;
};

} // namespace photopic
