// `photopic info`: the GL context, the colour path the device allows and the quality tier's path.
#include "InfoCommand.h"

#include "CommandOptions.h"

#include "gl/Context.h"
#include "pipeline/Pipeline.h"

#include <cstdio>
#include <string>

namespace photopic::cli {

InfoCommand::InfoCommand(CLI::App& parent)
    : Command(parent.add_subcommand("info",
                                    "GL vendor, renderer, version, and whether the HDR or LDR path runs")) {
    CLI::App& cmd = app();
    cmd.add_flag("--force-ldr", mForceLdr, "report as if the LDR path were forced");
    addSettingsOptions(&cmd, mSettings, "the defaults (realtime)");
    cmd.footer("Examples:\n"
               "  photopic info\n"
               "  photopic info --force-ldr\n"
               "  photopic info --set quality=low     the quality tier and the path it takes");
}

int InfoCommand::run() {
    const Settings settings = resolveSettings(mSettings);
    HeadlessContext context(commandContext());
    const ContextInfo& info = context.info();
    const Capabilities caps = detectCapabilities(mForceLdr);
    std::printf("GL vendor:    %s\n", info.vendor.c_str());
    std::printf("GL renderer:  %s\n", info.renderer.c_str());
    std::printf("GL version:   %s\n", info.version.c_str());
    std::printf("GLSL version: %s\n", info.glslVersion.c_str());
    std::printf("platform:     %s\n", info.platform.c_str());
    std::printf("GL debug:     %s\n", info.debugOutput
                                          ? "on (driver messages to the log)"
                                          : "off (--gl-debug or PHOTOPIC_GL_DEBUG=1 turns it on)");
    std::printf("colour path:  %s (%s)\n", caps.path == ColorPath::Hdr ? "HDR, RGBA16F" : "LDR, RGBA8",
                caps.pathReason.c_str());
    std::printf("RGBA16F renderable: %s, RGBA32F renderable: %s, compute: %s, timer queries: %s\n",
                caps.rgba16fRenderable ? "yes" : "no", caps.rgba32fRenderable ? "yes" : "no",
                caps.computeShaders ? "yes" : "no", caps.timerQueries ? "yes" : "no");
    const Pipeline pipeline({.settings = settings, .forceLdr = mForceLdr});
    const PipelineStatus t = pipeline.status();
    std::printf("quality:      %s -> %s path (%s)\n",
                std::string(qualityNames()[std::size_t(settings.quality)]).c_str(),
                t.path == ColorPath::Hdr ? "HDR" : "LDR, RGBA8", t.pathReason.c_str());
    return kOk;
}

} // namespace photopic::cli
