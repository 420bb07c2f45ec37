#include "gui/window/GlfwWindow.hpp"

#include "gui/platform/FramePacing.hpp"
#include "gui/window/GlfwInput.hpp"
#include "render/RenderError.hpp"

#define GLFW_INCLUDE_NONE  // GLFW only; every GL function goes through render::GlFunctions
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <optional>
#include <ostream>
#include <string_view>

namespace dropscope::gui {

namespace {

constexpr std::string_view kSnapshotHint = "for images without a window use: dropscope snapshot SCENE --out image.png";

// While minimised there is nothing to draw: wait for events (restore, close) up to this long instead of
// spinning through frames whose buffer swaps need not block.
constexpr double kIconifiedWaitSeconds = 0.1;

bool environmentSet(const char* name) {
    const char* value = std::getenv(name);
    return value && *value;
}

int cannotOpen(std::ostream& err, std::string_view reason) {
    err << "dropscope: cannot open a window (" << reason << "); " << kSnapshotHint << '\n';
    return kNoWindowExitCode;
}

// The description of GLFW's last error on this thread.
std::string_view lastGlfwError() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}

// GLFW's error callback takes no user pointer, so the stream it writes to is the one global here. Set
// only while runWindow runs; until the window is up, errors are not printed but read back with
// glfwGetError for the one-line failure message.
std::ostream* gErrorStream = nullptr;

void printGlfwError(int, const char* description) {
    if (gErrorStream) *gErrorStream << "dropscope: GLFW: " << description << '\n';
}

// glfwInit .. glfwTerminate, with the error callback installed around it.
class GlfwLibrary {
public:
    GlfwLibrary() {
        glfwSetErrorCallback(printGlfwError);
        initialised_ = glfwInit() == GLFW_TRUE;
    }
    ~GlfwLibrary() {
        if (initialised_) glfwTerminate();
        gErrorStream = nullptr;
        glfwSetErrorCallback(nullptr);
    }
    GlfwLibrary(const GlfwLibrary&) = delete;
    GlfwLibrary& operator=(const GlfwLibrary&) = delete;

    bool initialised() const { return initialised_; }
    static void reportErrorsTo(std::ostream& err) { gErrorStream = &err; }

private:
    bool initialised_ = false;
};

class Window {
public:
    explicit Window(GLFWwindow* window) : window_(window) {}
    ~Window() {
        if (window_) glfwDestroyWindow(window_);
    }
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* get() const { return window_; }

private:
    GLFWwindow* window_;
};

GLFWwindow* createWindow(const WindowOptions& options, WindowSize size) {
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    return glfwCreateWindow(size.width, size.height, options.title.c_str(), nullptr, nullptr);
}

void* glfwProcAddress(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

// The remembered size (else the requested one), no larger than the primary monitor: a size remembered
// on a bigger screen must not open a window past this one's edges.
WindowSize initialSize(const WindowOptions& options) {
    const WindowSize requested = clampWindowSize({options.width, options.height});
    WindowSize size =
        options.settingsFile.empty() ? requested : readWindowSize(options.settingsFile).value_or(requested);
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    if (const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr) {
        size = clampWindowSize({std::min(size.width, mode->width), std::min(size.height, mode->height)});
    }
    return size;
}

void rememberSize(const std::filesystem::path& file, WindowSize size, std::ostream& err) {
    try {
        writeWindowSize(file, clampWindowSize(size));
    } catch (const std::exception& error) {
        err << "dropscope: cannot remember the window size: " << error.what() << '\n';
    }
}

}  // namespace

int runWindow(const WindowOptions& options, const ClientFactory& makeClient, std::ostream& err) {
    if (!environmentSet("DISPLAY") && !environmentSet("WAYLAND_DISPLAY")) {
        err << "dropscope: no display (DISPLAY is not set); " << kSnapshotHint << '\n';
        return kNoWindowExitCode;
    }
    const GlfwLibrary glfw;
    if (!glfw.initialised()) return cannotOpen(err, lastGlfwError());
    const Window window(createWindow(options, initialSize(options)));
    if (!window.get()) return cannotOpen(err, lastGlfwError());
    glfwMakeContextCurrent(window.get());
    glfwSwapInterval(1);
    render::GlFunctions gl;
    try {
        gl = render::GlFunctions::load(glfwProcAddress);
        // Mesa's rasterisers on the processor keep the window as X11's and Wayland's 32-bit visuals lay it out; a GPU's
        // driver is left OpenGL's own (its blit is the GPU's work either way).
        if (gl.isSoftware()) gl.windowLayout = {.topRowFirst = true, .bgra = true};
    } catch (const render::RenderError& error) {
        return cannotOpen(err, error.what());
    }
    GlfwLibrary::reportErrorsTo(err);

    GlfwInput input(window.get());
    const std::unique_ptr<FrameClient> client = makeClient(gl);
    std::optional<WindowSize> lastSize;
    double lastTime = glfwGetTime();
    FramePacing pacing;
    while (!glfwWindowShouldClose(window.get())) {
        if (const double wait = pacing.waitSeconds(); wait > 0.0) {
            glfwWaitEventsTimeout(wait);
        } else {
            glfwPollEvents();
        }
        if (glfwGetWindowAttrib(window.get(), GLFW_ICONIFIED) == GLFW_TRUE) {
            glfwWaitEventsTimeout(kIconifiedWaitSeconds);
            continue;
        }
        const double now = glfwGetTime();
        const InputFrame frame = input.nextFrame(now - lastTime);
        lastTime = now;
        if (frame.windowWidth > 0 && frame.windowHeight > 0) {
            lastSize = WindowSize{frame.windowWidth, frame.windowHeight};
        }
        client->frame(frame);
        glfwSwapBuffers(window.get());
        pacing.frameDrawn(frame, client->busy(), glfwGetTime() - now);
        if (client->quitRequested()) break;
    }
    // The client waits for work still running when it is destroyed (a ray tree's optical scene, seconds at 1e6
    // droplets; a trace's threads, up to a second): the window leaves the screen first, not frozen meanwhile.
    glfwHideWindow(window.get());
    glfwPollEvents();  // the request sent (a Wayland backend queues it until events are handled)
    if (lastSize && !options.settingsFile.empty()) rememberSize(options.settingsFile, *lastSize, err);
    return 0;
}

}  // namespace dropscope::gui
