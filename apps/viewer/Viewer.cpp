#include "Viewer.h"

#include "FileScene.h"
#include "InputSequence.h"
#include "SettingsEditor.h"
#include "ViewerKeys.h"
#include "ViewerPanels.h"

#include "core/settings/SettingsJson.h"
#include "gl/Gl.h"
#include "gl/Objects.h"
#include "io/ImageIO.h"
#include "pipeline/Pipeline.h"
#include "scenes/Scene.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace photopic::viewer {
namespace {

constexpr const char* kNoDisplay =
    "photopic-view needs a display; run under xvfb-run or use `photopic scene`";
/// A stall (window drag, a slow first frame on llvmpipe) must not read as a long step of eye adaptation.
constexpr float kMaxDt = 0.1f;
constexpr float kMinDt = 1.0f / 1000.0f;

std::string gGlfwError;
/// Paths dropped on the window since the last frame (GLFW calls back from glfwPollEvents, on this thread).
std::vector<std::string> gDropped;
/// Bound keys pressed since the last frame, by their viewerKeys() names, and wheel steps (same thread).
std::vector<std::string> gPressed;
double gScroll = 0.0;

void onGlfwError(int code, const char* text) {
    gGlfwError = fmt::format("GLFW error 0x{:x}: {}", code, text ? text : "");
}

/// glfwInit/glfwTerminate as a scope, so every exit path below releases the display connection.
struct GlfwSession {
    GlfwSession() {
        glfwSetErrorCallback(onGlfwError);
        if (glfwInit() != GLFW_TRUE) {
            throw DisplayError(fmt::format("{} ({})", kNoDisplay, gGlfwError));
        }
    }
    ~GlfwSession() { glfwTerminate(); }
    GlfwSession(const GlfwSession&) = delete;
    GlfwSession& operator=(const GlfwSession&) = delete;
};

struct WindowDeleter {
    void operator()(GLFWwindow* w) const { glfwDestroyWindow(w); }
};
using WindowPtr = std::unique_ptr<GLFWwindow, WindowDeleter>;

/// Dear ImGui's context and its GLFW + OpenGL3 backends (both built into Debian's libimgui.a).
struct ImGuiSession {
    explicit ImGuiSession(GLFWwindow* window) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename =
            nullptr; // panel layout is part of the program, not state left in the cwd
        ImGui::StyleColorsDark();
        ImGui::GetStyle().Alpha = 0.92f;
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        ImGui_ImplOpenGL3_Init("#version 450 core");
    }
    ~ImGuiSession() {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    ImGuiSession(const ImGuiSession&) = delete;
    ImGuiSession& operator=(const ImGuiSession&) = delete;
};

/// The letterboxed rectangle of the window that shows a `src` image at its aspect ratio.
std::array<int, 4> fitRect(Extent src, int w, int h) {
    const float scale = std::min(float(w) / float(src.width), float(h) / float(src.height));
    const int dw = std::max(1, int(std::lround(float(src.width) * scale)));
    const int dh = std::max(1, int(std::lround(float(src.height) * scale)));
    const int x = (w - dw) / 2, y = (h - dh) / 2;
    return {x, y, x + dw, y + dh};
}

Image8 readBackBuffer(int width, int height) {
    Image8 image(width, height);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    // GL's row 0 is the bottom; PNG's is the top.
    const std::size_t stride = std::size_t(width) * 4;
    for (int y = 0; y < height / 2; ++y) {
        std::swap_ranges(image.rgba.begin() + std::ptrdiff_t(std::size_t(y) * stride),
                         image.rgba.begin() + std::ptrdiff_t(std::size_t(y + 1) * stride),
                         image.rgba.begin() + std::ptrdiff_t(std::size_t(height - 1 - y) * stride));
    }
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) {
        image.rgba[i] = 255; // the default framebuffer's alpha is whatever ImGui blended into it
    }
    return image;
}

} // namespace

/// Everything that needs no GL is checked before the display is opened: bad input exits 2 everywhere.
SplitOverrides checkOptions(const ViewerOptions& options) {
    const auto& scenes = builtInScenes();
    if (!options.files.empty()) {
        SplitOverrides overrides = splitSceneOverrides("file", options.overrides);
        Settings probe;
        for (const std::string& o : overrides.post) {
            applySettingsOverride(probe, o);
        }
        return overrides;
    }
    if (std::none_of(scenes.begin(), scenes.end(),
                     [&](const SceneInfo& s) { return s.name == options.scene; })) {
        throw InputError(fmt::format("unknown scene '{}' (known: {})", options.scene, builtInSceneNames()));
    }
    SplitOverrides overrides = splitSceneOverrides(options.scene, options.overrides);
    Settings probe;
    for (const std::string& o : overrides.post) {
        applySettingsOverride(probe, o);
    }
    return overrides;
}

WindowPtr openWindow(const ViewerOptions& options) {
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    WindowPtr window(glfwCreateWindow(options.width, options.height, "photopic-view", nullptr, nullptr));
    if (!window) {
        throw DisplayError(fmt::format("{} (no OpenGL 4.5 core window: {})", kNoDisplay, gGlfwError));
    }
    glfwMakeContextCurrent(window.get());
    // --frames runs as fast as it can (tests, screenshots); interactive use follows the display.
    glfwSwapInterval(options.frames > 0 ? 0 : 1);
    return window;
}

/// The scene with its --set values, sized for the window, and the post settings it starts with.
std::unique_ptr<Scene> makeViewerScene(const ViewerOptions& options, const SplitOverrides& overrides,
                                       Settings& settings, std::unique_ptr<Scene> scene) {
    if (!scene) {
        scene = makeScene(options.scene);
    }
    applySceneOverrides(*scene, overrides.scene);
    settings = scene->defaultSettings();
    if (!options.preset.empty()) {
        const std::optional<Settings> look = Settings::preset(options.preset);
        if (!look) {
            throw InputError(unknownPresetMessage(options.preset));
        }
        settings.applyLook(*look);
    } else if (!options.files.empty()) {
        settings.applyLook(Settings::stills()); // photographs: the look `photopic image` gives them
    }
    if (!options.settingsFile.empty()) {
        settings = loadSettingsFile(options.settingsFile, std::move(settings));
    }
    for (const std::string& o : overrides.post) {
        applySettingsOverride(settings, o);
    }
    try {
        scene->resize({options.width, options.height});
    } catch (const SceneInputError& e) {
        throw InputError(e.what());
    }
    return scene;
}

/// Letterboxes the display image into the window's default framebuffer, through one framebuffer re-pointed at
/// each frame's display texture (the pipeline hands out a few pooled ones, and a framebuffer kept per texture
/// name would outlive a texture whose name GL then reuses).
class Presenter {
public:
    void present(const Texture& display, int fbw, int fbh) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fbw, fbh);
        glDisable(GL_FRAMEBUFFER_SRGB); // the display texture already holds sRGB-encoded bytes
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        if (fbw <= 0 || fbh <= 0) {
            return;
        }
        if (mSource.id() == 0) {
            mSource = Framebuffer(display, 0, "photopic-view display");
        } else {
            mSource.attach(display, 0, "photopic-view display");
        }
        const auto r = fitRect(display.extent(), fbw, fbh);
        glBlitNamedFramebuffer(mSource.id(), 0, 0, 0, display.extent().width, display.extent().height, r[0],
                               r[1], r[2], r[3], GL_COLOR_BUFFER_BIT, GL_LINEAR);
    }

private:
    Framebuffer mSource;
};

/// The viewerKeys() name of a GLFW key; empty for keys the viewer does not bind.
std::string keyName(int key) {
    if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) {
        return std::string(1, char('0' + (key - GLFW_KEY_0)));
    }
    if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) {
        return std::string(1, char('A' + (key - GLFW_KEY_A)));
    }
    return key == GLFW_KEY_F12 ? "F12" : "";
}

/// Installed before ImGui's own callbacks, which then call these after theirs.
void installInputCallbacks(GLFWwindow* window) {
    glfwSetKeyCallback(window, [](GLFWwindow*, int key, int, int action, int) {
        if (action == GLFW_PRESS) {
            if (std::string name = keyName(key); !name.empty()) {
                gPressed.push_back(std::move(name));
            }
        }
    });
    glfwSetScrollCallback(window, [](GLFWwindow*, double, double dy) { gScroll += dy; });
}

void report(UiState& ui, std::string message) {
    std::printf("photopic-view: %s\n", message.c_str());
    std::fflush(stdout);
    ui.message = std::move(message);
}

/// One key press: a toggle of the live settings, or F12's save.
void pressKey(const std::string& key, Pipeline& pipeline, const ViewerOptions& options, UiState& ui) {
    if (key == "F12") {
        saveSettings(pipeline.settings(), options.save, ui);
        report(ui, ui.message + " (F12)");
        return;
    }
    if (std::optional<std::string> done = applyToggleKey(key, ui.edited)) {
        applyEdited(pipeline, ui);
        report(ui, *done);
    }
}

void orbitCamera(Scene& scene, double dx, double dy) {
    if (InteractiveCamera* camera = scene.interactiveCamera()) {
        // Dragging right turns the scene with the cursor: the eye moves to its left.
        camera->orbit(float(-dx) * kOrbitRadiansPerPixel, float(dy) * kOrbitRadiansPerPixel);
    }
}

void zoomCamera(Scene& scene, double steps) {
    if (InteractiveCamera* camera = scene.interactiveCamera(); camera && steps != 0.0) {
        camera->zoom(std::pow(kZoomPerWheelStep, float(steps))); // wheel away from the user: closer
    }
}

/// --press: one scripted event per frame from frame 1, through the same paths as the keyboard and mouse.
void scriptedInput(const FrameTime& time, Scene& scene, Pipeline& pipeline, const ViewerOptions& options,
                   UiState& ui) {
    if (time.frameIndex == 0 || ui.scripted >= options.press.size()) {
        return;
    }
    const ScriptedEvent& e = options.press[ui.scripted++];
    if (e.kind == ScriptedEvent::Kind::Key) {
        pressKey(e.key, pipeline, options, ui);
    } else if (e.kind == ScriptedEvent::Kind::Drag) {
        orbitCamera(scene, e.x, e.y);
    } else {
        zoomCamera(scene, e.x);
    }
}

/// Keys and mouse since the last frame, unless a panel has the keyboard (typing) or the pointer.
void handleInput(GLFWwindow* window, Scene& scene, Pipeline& pipeline, const ViewerOptions& options,
                 UiState& ui) {
    const ImGuiIO& io = ImGui::GetIO();
    std::vector<std::string> keys = std::exchange(gPressed, {});
    if (!io.WantCaptureKeyboard) {
        for (const std::string& key : keys) {
            pressKey(key, pipeline, options, ui);
        }
    }
    const double scroll = std::exchange(gScroll, 0.0);
    if (!io.WantCaptureMouse) {
        zoomCamera(scene, scroll);
    }
    const bool down = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window, &x, &y);
    if (down && !ui.dragging && !io.WantCaptureMouse) {
        ui.dragging = true;
    } else if (down && ui.dragging) {
        orbitCamera(scene, x - ui.cursorX, y - ui.cursorY);
    } else if (!down) {
        ui.dragging = false;
    }
    ui.cursorX = x;
    ui.cursorY = y;
}

void drawUi(GLFWwindow* window, Scene& scene, Pipeline& pipeline, const ViewerOptions& options, UiState& ui,
            const FrameTime& time) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    handleInput(window, scene, pipeline, options, ui);
    scriptedInput(time, scene, pipeline, options, ui);
    drawPanels(pipeline, options, ui);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

namespace {

/// The files to view (patterns expanded) and how to read them, as `photopic image` has them.
std::pair<std::vector<std::filesystem::path>, FileInputs> fileInputs(const ViewerOptions& options) {
    try {
        cli::ImageOptions image;
        image.inputs = options.files;
        const std::vector<cli::InputFile> expanded = cli::expandInputs(image);
        std::vector<std::filesystem::path> paths;
        for (const cli::InputFile& f : expanded)
            paths.push_back(f.path);
        FileInputs inputs;
        inputs.aovs = cli::aovRequest(options.aovPreset, options.layer, options.aovs);
        if (!options.camera.empty())
            inputs.cameras = cli::loadCameraTrack(options.camera);
        if (!options.lens.empty())
            inputs.lens = cli::parseLensOverride(options.lens);
        inputs.frameNumbers = cli::inputFrameNumbers(expanded);
        return {std::move(paths), std::move(inputs)};
    } catch (const cli::InputError& e) {
        throw InputError(e.what());
    }
}

/// The files' scene (none without files), with the window's size and title from them unless --size.
std::unique_ptr<Scene> openFiles(ViewerOptions& options) {
    if (options.files.empty()) {
        return nullptr;
    }
    std::unique_ptr<Scene> files;
    auto [paths, inputs] = fileInputs(options);
    try {
        files = makeFileScene(std::move(paths), std::move(inputs));
    } catch (const SceneInputError& e) {
        throw InputError(e.what());
    }
    if (!options.sizeGiven) { // the image's size, scaled down to fit a 1600x900 window
        const Extent image = fileSceneExtent(*files);
        const double scale = std::min({1.0, 1600.0 / image.width, 900.0 / image.height});
        options.width = std::max(1, int(std::lround(image.width * scale)));
        options.height = std::max(1, int(std::lround(image.height * scale)));
    }
    options.scene = options.files.front().filename().string();
    return files;
}

/// The files dropped on the window since the last frame, in place of `scene`; kept as it was when they
/// cannot be read.
void viewDropped(std::unique_ptr<Scene>& scene, Pipeline& pipeline) {
    std::vector<std::filesystem::path> dropped(gDropped.begin(), gDropped.end());
    gDropped.clear();
    const std::string first = dropped.front().string();
    try {
        scene = makeFileScene(std::move(dropped));
        pipeline.reset();
        std::printf("photopic-view: viewing %s\n", first.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photopic-view: %s (kept the current view)\n", e.what());
    }
}

} // namespace

int run(const ViewerOptions& givenOptions) {
    const SplitOverrides overrides = checkOptions(givenOptions);
    ViewerOptions options = givenOptions;
    std::unique_ptr<Scene> files = openFiles(options);
    GlfwSession glfw;
    WindowPtr window = openWindow(options);
    glfwSetDropCallback(window.get(), [](GLFWwindow*, int count, const char** paths) {
        gDropped.assign(paths, paths + std::max(count, 0));
    });
    installInputCallbacks(window.get());
    // From here on the window's context is current: the pipeline runs in the host's context.
    Settings settings;
    std::unique_ptr<Scene> scene = makeViewerScene(options, overrides, settings, std::move(files));
    Pipeline pipeline({.settings = settings});
    ImGuiSession imgui(window.get());
    UiState ui;
    ui.edited = settings;
    std::printf("photopic-view: %s at %dx%d, GL %s on %s\n", options.scene.c_str(), options.width,
                options.height, reinterpret_cast<const char*>(glGetString(GL_VERSION)),
                reinterpret_cast<const char*>(glGetString(GL_RENDERER)));

    Presenter presenter;
    std::vector<double> sceneTelemetry;
    double last = glfwGetTime();
    for (std::uint64_t frame = 0; !glfwWindowShouldClose(window.get()); ++frame) {
        glfwPollEvents();
        if (!gDropped.empty()) { // files dropped on the window replace what is shown
            viewDropped(scene, pipeline);
        }
        // The measured delta feeds FrameTime (the pipeline never reads a clock); --fixed-dt replaces it.
        const double now = glfwGetTime();
        ui.dt = options.fixedDt ? *options.fixedDt : std::clamp(float(now - last), kMinDt, kMaxDt);
        last = now;
        const FrameTime time{.dt = ui.dt, .frameIndex = frame};
        sceneTelemetry.clear();
        const FrameInputs inputs = scene->render(time, pipeline, sceneTelemetry);
        const Texture& display = pipeline.execute(inputs, time);
        int fbw = 0, fbh = 0;
        glfwGetFramebufferSize(window.get(), &fbw, &fbh);
        presenter.present(display, fbw, fbh);
        drawUi(window.get(), *scene, pipeline, options, ui, time);

        const bool lastFrame = options.frames > 0 && frame + 1 >= std::uint64_t(options.frames);
        if (lastFrame && !options.screenshot.empty()) {
            writePng(options.screenshot, readBackBuffer(fbw, fbh));
            std::printf("photopic-view: screenshot %s\n", options.screenshot.string().c_str());
        }
        glfwSwapBuffers(window.get());
        if (lastFrame) {
            break;
        }
    }
    if (options.frames > 0 && options.saveGiven) {
        writeTextFile(options.save, settingsToJson(pipeline.settings()));
        std::printf("photopic-view: settings saved to %s\n", options.save.string().c_str());
    }
    return kOk;
}

} // namespace photopic::viewer
