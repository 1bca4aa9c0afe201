#pragma once
// What the current context can do, and which colour path Photopic takes because of it.

#include <string>

namespace photopic {

enum class ColorPath { Hdr, Ldr };

struct Capabilities {
    bool rgba16fRenderable = false; ///< RGBA16F colour attachments complete and renderable
    bool rgba32fRenderable = false;
    bool computeShaders = false;
    bool timerQueries = false;
    ColorPath path = ColorPath::Ldr;
    std::string pathReason; ///< why this path: "RGBA16F is colour-renderable" or what was missing / forced
};

/// Probes the current context. `forceLdr` (CLI --force-ldr, quality=legacy, PHOTOPIC_FORCE_LDR=1) takes the
/// LDR path whatever the hardware can do; the reason says so.
Capabilities detectCapabilities(bool forceLdr = false);

/// True when the current context renders on the CPU (Mesa llvmpipe or softpipe, SwiftShader): there a
/// workgroup barrier costs more than the work between two, on a GPU it costs next to nothing.
bool isSoftwareRenderer();

} // namespace photopic
