// photopic-view's command line: parses it, then hands over to the Viewer. Exit codes match photopic's:
// 0 ok, 1 failure (no display included), 2 bad input.

#include "Viewer.h"

#include "common/Verbosity.h"
#include "core/settings/JsonVisitors.h"
#include "core/settings/SettingsJson.h"
#include "gl/Gl.h"
#include "scenes/Scene.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace photopic::viewer;

void parseSize(const std::string& text, ViewerOptions& options) {
    const std::optional<photopic::Extent> size = photopic::parseExtent(text);
    if (!size) {
        throw InputError("size '" + text + "' is not WIDTHxHEIGHT with each side in [1, 16384]");
    }
    options.width = size->width;
    options.height = size->height;
}

/// The key map for --help, from the same list the viewer's Keys panel shows.
std::string keysHelp() {
    std::string out = "Keys (when no panel has the keyboard) and mouse (outside the panels):\n";
    for (const KeyBinding& k : viewerKeys()) {
        out += fmt::format("  {:<6} {}\n", k.key, k.action);
    }
    return out;
}

/// What the command line fills: the viewer's options and the raw values turned into them after parsing.
struct CommandLine {
    ViewerOptions options;
    std::string size = "1280x720";
    float fixedDt = 0.0f;
    std::vector<std::string> press;
    photopic::Verbosity verbosity;
    CLI::Option* scene = nullptr;
    CLI::Option* fixedDtOption = nullptr;
    CLI::Option* save = nullptr;
    CLI::Option* screenshot = nullptr;
};

/// The files and how their channels, cameras and lens are read.
void addFileOptions(CLI::App& app, CommandLine& c) {
    ViewerOptions& options = c.options;
    app.add_option(
        "files", options.files,
        "image files (EXR, HDR, PNG) to view instead of a scene, or frame-numbered patterns "
        "(f%04d.exr, f.####.exr); several play as a sequence. EXR files bring their depth, normals, "
        "motion and camera as photopic image reads them");
    app.add_option("--aovs", options.aovPreset,
                   "the channel names of a renderer: photopic or blender "
                   "(default: blender for Blender's files)")
        ->check(CLI::IsMember({"photopic", "blender"}));
    app.add_option("--layer", options.layer, "the EXR layer to read (Blender's view layer)");
    app.add_option("--aov", options.aovs,
                   "KIND=CHANNELS[:CONVENTIONS], as photopic image takes it (docs/interop.md)")
        ->take_all()
        ->allow_extra_args(false);
    app.add_option("--camera", options.camera, "camera JSON or track for files without a camera")
        ->check(CLI::ExistingFile);
    app.add_option("--lens", options.lens,
                   "fNumber=N,focus=D,shutter=DEG: replaces the cameras' lens values");
}

/// The scene, the settings, the window and the scripted run.
void addViewOptions(CLI::App& app, CommandLine& c) {
    ViewerOptions& options = c.options;
    c.scene = app.add_option("--scene", options.scene, "built-in scene: " + photopic::builtInSceneNames())
                  ->capture_default_str();
    app.add_option("--settings", options.settingsFile, "settings JSON applied over the scene's defaults")
        ->check(CLI::ExistingFile);
    app.add_option("--preset", options.preset,
                   "look: " + photopic::settings_json::joinNames(photopic::presetNames()) +
                       " (default: stills for files, the scene's own for a scene)");
    app.add_option("--set", options.overrides, "override key=value (SCENE.key=value for the scene's own)");
    app.add_option("--size", c.size, "render and initial window size WIDTHxHEIGHT")->capture_default_str();
    app.add_option("--frames", options.frames, "run N frames, then exit")->check(CLI::Range(1, 1000000));
    c.fixedDtOption =
        app.add_option("--fixed-dt", c.fixedDt, "seconds per frame instead of the measured delta")
            ->check(CLI::Range(0.0001f, 1.0f));
    c.save = app.add_option("--save", options.save, "where Save JSON writes (with --frames: also on exit)")
                 ->capture_default_str();
    c.screenshot =
        app.add_option("--screenshot", options.screenshot, "with --frames: the last window frame as PNG");
    app.add_option("--press", c.press,
                   "scripted input, one event per frame from frame 1: keys (B, X, F12, ...), drag:DX:DY "
                   "(pixels), wheel:STEPS")
        ->delimiter(',');
}

/// Parses the command line; a usage error (or --help) is the exit code to return.
std::optional<int> parse(CLI::App& app, CommandLine& c, int argc, char** argv) {
    try {
        app.parse(argc, argv);
        if (c.scene->count() > 0 && !c.options.files.empty()) {
            throw CLI::ValidationError("--scene", "shows a scene; image files were named too (choose one)");
        }
        if (c.screenshot->count() > 0 && c.options.frames == 0) {
            throw CLI::ValidationError("--screenshot", "needs --frames N");
        }
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kOk : kBadInput;
    }
    return std::nullopt;
}

/// The viewer run with the parsed options; its errors become exit codes and a line on stderr.
int runViewer(CommandLine& c) {
    ViewerOptions& options = c.options;
    try {
        parseSize(c.size, options);
        for (const std::string& item : c.press) {
            try {
                options.press.push_back(parseScriptedEvent(item));
            } catch (const std::invalid_argument& e) {
                throw InputError(e.what());
            }
        }
        return run(options);
    } catch (const InputError& e) {
        std::fprintf(stderr, "photopic-view: %s\n", e.what());
        return kBadInput;
    } catch (const photopic::SettingsError& e) {
        std::fprintf(stderr, "photopic-view: %s\n", e.what());
        return kBadInput;
    } catch (const DisplayError& e) {
        std::fprintf(stderr, "photopic-view: %s\n", e.what());
        return kFailure;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photopic-view: %s\n", e.what());
        return kFailure;
    }
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "photopic-view: image files or a built-in scene through the Photopic pipeline, every setting "
        "tunable live"};
    app.footer("Examples:\n"
               "  photopic-view data/Desk.exr                  one image; drop other files on the window\n"
               "  photopic-view shot_*.exr                     a sequence, played with adaptation\n"
               "  photopic-view --scene testbed --set aa.mode=taa\n"
               "  photopic-view --scene orbit --set orbit.model=data/gltf/2CylinderEngine.glb\n"
               "\n" +
               keysHelp());
    app.set_version_flag("--version", std::string("photopic-view ") + PHOTOPIC_VERSION);
    CommandLine c;
    addFileOptions(app, c);
    addViewOptions(app, c);
    photopic::addVerbosityOptions(app, c.verbosity);
    if (const std::optional<int> code = parse(app, c, argc, argv)) {
        return *code;
    }
    photopic::applyVerbosity(c.verbosity);
    if (c.fixedDtOption->count() > 0) {
        c.options.fixedDt = c.fixedDt;
    }
    c.options.saveGiven = c.save->count() > 0;
    c.options.sizeGiven = app.get_option("--size")->count() > 0;
    return runViewer(c);
}
