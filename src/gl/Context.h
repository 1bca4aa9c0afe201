#pragma once
// Headless OpenGL 4.5 core context through EGL, without a window: a hardware device found by EGL device
// enumeration when there is one, else Mesa's surfaceless platform (llvmpipe on machines without a GPU).

#include "gl/Gl.h"

#include <memory>
#include <string>

namespace photopic {

struct HeadlessContextCreateInfo {
    /// A KHR_debug context with synchronous debug output routed to the log (gl/Debug.h): for tests and
    /// diagnosis. It costs CPU time in every GL call on some drivers, so a production context has none.
    bool debug = false;
    bool preferHardware = true; ///< try EGL devices that are not software rasterisers first
};

struct ContextInfo {
    std::string vendor;
    std::string renderer;
    std::string version;
    std::string glslVersion;
    std::string platform;     ///< "EGL device N (hardware)", "EGL device N (software)" or "Mesa surfaceless"
    bool debugOutput = false; ///< the driver's debug messages reach the log (a debug context)
};

class HeadlessContext {
public:
    /// Creates the context and makes it current on this thread. Throws GlError saying what was tried.
    explicit HeadlessContext(const HeadlessContextCreateInfo& info = {});
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    void makeCurrent() const;
    [[nodiscard]] const ContextInfo& info() const { return mInfo; }

    struct Egl; ///< EGL handles (kept out of this header so hosts need no EGL include)

private:
    std::unique_ptr<Egl> mEgl;
    ContextInfo mInfo;
};

/// Strings of the current context.
ContextInfo currentContextInfo();

} // namespace photopic
