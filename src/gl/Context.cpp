#include "gl/Context.h"

#include "core/Log.h"
#include "gl/Debug.h"

#include <epoxy/egl.h>

#include <fmt/format.h>

#include <vector>

namespace photopic {

struct HeadlessContext::Egl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
};

namespace {

std::string glString(GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return s ? s : "";
}

bool isSoftware(const std::string& renderer) {
    return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos ||
           renderer.find("SwiftShader") != std::string::npos;
}

/// Initialises `display` and creates a current GL 4.5 core context on it; returns false (and cleans up) on
/// failure.
bool createOn(EGLDisplay display, bool debug, HeadlessContext::Egl& out, std::string& why) {
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
        why = fmt::format("eglInitialize failed (0x{:x})", eglGetError());
        return false;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        why = "eglBindAPI(EGL_OPENGL_API) failed";
        eglTerminate(display);
        return false;
    }
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    const bool noConfig = epoxy_has_egl_extension(display, "EGL_KHR_no_config_context");
    if (!noConfig && (!eglChooseConfig(display, configAttribs, &config, 1, &count) || count == 0)) {
        why = "no EGL config with EGL_OPENGL_BIT";
        eglTerminate(display);
        return false;
    }
    // The version and profile attributes are EGL 1.5's and EGL_KHR_create_context's alike (the same values);
    // the debug flag is EGL_CONTEXT_OPENGL_DEBUG only from EGL 1.5 on: an EGL 1.4 display (softpipe's, some
    // drivers') rejects that attribute and takes the extension's flags bit instead.
    const bool egl15 = major > 1 || (major == 1 && minor >= 5);
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     4,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     egl15 ? EGL_CONTEXT_OPENGL_DEBUG : EGL_CONTEXT_FLAGS_KHR,
                                     egl15 ? (debug ? EGL_TRUE : EGL_FALSE)
                                           : (debug ? EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR : 0),
                                     EGL_NONE};
    EGLContext context =
        eglCreateContext(display, noConfig ? EGL_NO_CONFIG_KHR : config, EGL_NO_CONTEXT, contextAttribs);
    if (context == EGL_NO_CONTEXT) {
        why = fmt::format("no OpenGL 4.5 core context (0x{:x})", eglGetError());
        eglTerminate(display);
        return false;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        why = fmt::format("eglMakeCurrent without a surface failed (0x{:x})", eglGetError());
        eglDestroyContext(display, context);
        eglTerminate(display);
        return false;
    }
    out.display = display;
    out.context = context;
    return true;
}

void destroy(HeadlessContext::Egl& egl) {
    if (egl.display != EGL_NO_DISPLAY) {
        eglMakeCurrent(egl.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (egl.context != EGL_NO_CONTEXT) {
            eglDestroyContext(egl.display, egl.context);
        }
        eglTerminate(egl.display);
    }
    egl = {};
}

} // namespace

ContextInfo currentContextInfo() {
    return {glString(GL_VENDOR), glString(GL_RENDERER), glString(GL_VERSION),
            glString(GL_SHADING_LANGUAGE_VERSION), ""};
}

namespace {

/// The contexts made on the EGL devices, and why each device was passed over.
struct DeviceSearch {
    HeadlessContext::Egl hardware; ///< the first device with a hardware renderer, current; else none
    std::string hardwarePlatform;
    HeadlessContext::Egl software; ///< else the first device with a software renderer; else none
    std::string softwarePlatform;
    std::vector<std::string> tried; ///< "EGL device i: why not"
};

/// Makes a context on each EGL device in turn, until one has a hardware renderer; of those with a software
/// renderer the first is kept, the others destroyed.
DeviceSearch searchDevices(bool debug) {
    DeviceSearch search;
    EGLint count = 0;
    eglQueryDevicesEXT(0, nullptr, &count);
    std::vector<EGLDeviceEXT> devices(std::size_t(std::max(count, 0)));
    if (count <= 0 || !eglQueryDevicesEXT(count, devices.data(), &count)) {
        return search;
    }
    for (EGLint i = 0; i < count; ++i) {
        HeadlessContext::Egl candidate;
        std::string why;
        EGLDisplay display =
            eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[std::size_t(i)], nullptr);
        if (!createOn(display, debug, candidate, why)) {
            search.tried.push_back(fmt::format("EGL device {}: {}", i, why));
            continue;
        }
        if (!isSoftware(glString(GL_RENDERER))) {
            search.hardware = candidate;
            search.hardwarePlatform = fmt::format("EGL device {} (hardware)", i);
            break;
        }
        search.tried.push_back(fmt::format("EGL device {}: software renderer {}", i, glString(GL_RENDERER)));
        if (search.software.display == EGL_NO_DISPLAY) {
            search.software = candidate;
            search.softwarePlatform = fmt::format("EGL device {} (software)", i);
        } else {
            destroy(candidate);
        }
    }
    return search;
}

/// A context on Mesa's surfaceless platform into `egl`; else a GlError listing every way tried.
void createSurfaceless(bool debug, HeadlessContext::Egl& egl, std::vector<std::string>& tried) {
    std::string why;
    EGLDisplay display = EGL_NO_DISPLAY;
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
        display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    }
    if (!createOn(display, debug, egl, why)) {
        tried.push_back("Mesa surfaceless: " +
                        (display == EGL_NO_DISPLAY ? std::string("not available") : why));
        std::string all;
        for (const auto& t : tried) {
            all += "\n  " + t;
        }
        throw GlError("cannot create a headless OpenGL 4.5 core context; tried:" + all);
    }
}

} // namespace

HeadlessContext::HeadlessContext(const HeadlessContextCreateInfo& info)
    : mEgl(std::make_unique<Egl>()) {
    DeviceSearch search;
    const bool hasDeviceEnumeration = epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration") ||
                                      epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_base");
    if (info.preferHardware && hasDeviceEnumeration) {
        search = searchDevices(info.debug);
    }
    if (search.hardware.display != EGL_NO_DISPLAY) {
        *mEgl = search.hardware;
        mInfo = currentContextInfo();
        mInfo.platform = search.hardwarePlatform;
    } else if (search.software.display != EGL_NO_DISPLAY) {
        *mEgl = search.software;
        eglMakeCurrent(mEgl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, mEgl->context);
        mInfo = currentContextInfo();
        mInfo.platform = search.softwarePlatform;
    } else {
        createSurfaceless(info.debug, *mEgl, search.tried);
        mInfo = currentContextInfo();
        mInfo.platform = "Mesa surfaceless";
    }
    if (info.debug) {
        installDebugOutput();
    }
    mInfo.debugOutput = glIsEnabled(GL_DEBUG_OUTPUT) == GL_TRUE;
}

HeadlessContext::~HeadlessContext() {
    destroy(*mEgl);
}

void HeadlessContext::makeCurrent() const {
    eglMakeCurrent(mEgl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, mEgl->context);
}

} // namespace photopic
