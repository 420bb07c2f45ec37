#include "gui/App.hpp"

#include "gui/Actions.hpp"
#include "gui/Panels.hpp"
#include "gui/Screenshot.hpp"
#include "gui/Shortcuts.hpp"
#include "gui/TraceActions.hpp"
#include "gui/platform/ImGuiInput.hpp"
#include "gui/platform/ImGuiRasteriser.hpp"
#include "gui/platform/ImGuiRenderer.hpp"
#include "gui/platform/KeptPanels.hpp"

#include <imgui.h>

#include <algorithm>
#include <chrono>

namespace dropscope::gui {

App::App(const render::GlFunctions& gl, Scene scene, const AppOptions& options)
    : gl_(gl), options_(options), iniFile_(options.iniFile.string()), state_(std::move(scene), options.scenePath) {
    context_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = iniFile_.empty() ? nullptr : iniFile_.c_str();
    configureImGuiIo(io);
    ImGui::StyleColorsDark();
    imguiRenderer_ = std::make_unique<ImGuiRenderer>(gl);
    keptPanels_ = std::make_unique<KeptPanels>();
    scene_ = std::make_unique<ViewportScene>(gl);

    const SceneDocument& document = state_.scene.document();
    // A debugger shows where the light comes from (with the source's handles) and, once a path segment is
    // selected, the octree cells its search visited.
    state_.view.layers.sources = true;
    state_.view.layers.traversal = true;
    // On a software OpenGL a frame of droplets and paths is drawn faster on the processor (docs/gui.md).
    state_.view.layers.render.processorRaster = gl.isSoftware();
    state_.view.layers.detectors = !document.detectors().empty();  // the layer and the Detectors panel
    state_.ui.screenshotDirectory = options.screenshotDirectory;
    state_.ui.itemProbe = options.itemProbe;
    if (const auto& view = document.view()) {
        state_.view.camera = render::Camera::fromView(*view);
        state_.view.fitRequested = false;
    }
    state_.placement.medium = firstDropletMedium(document);
    state_.ui.status.say(options.scenePath.empty()
                             ? "the bundled default scene (File > Save as keeps your changes) - F1 for help"
                             : "opened " + options.scenePath.string() + " - F1 for help");
}

App::~App() {
    state_.traces.job.cancel();
    imguiRenderer_.reset();
    scene_.reset();
    ImGui::DestroyContext(context_);
}

void App::buildUi() {
    handleShortcuts(state_);
    drawMainMenu(state_);
    drawScenePanel(state_);
    drawMediaPanel(state_.scene.document(), state_.ui);
    drawPlacementPanel(state_.placement, state_.view.slice, state_.scene.document());
    drawFirePanel(state_);
    drawDetectorsPanel(state_);
    drawOctreePanel(state_);
    drawPathPanel(state_.view.layers, state_.traces, state_.ui.itemProbe);
    drawResultsPanel(state_.traces, state_.ui);
    drawDetectorWindows(state_.traces, state_.ui.itemProbe);
    drawFilePrompts(state_);
    drawHelpWindow(state_.ui);
    drawStatusBar(state_);
    controls_.handle(state_, scene_->sceneBounds());
}

void App::frame(const InputFrame& input) {
    ImGui::SetCurrentContext(context_);
    applyInput(ImGui::GetIO(), input);
    ImGui::NewFrame();
    updateTraces(state_);
    buildUi();
    ImGui::Render();

    const int width = std::max(input.framebufferWidth, 1);
    const int height = std::max(input.framebufferHeight, 1);
    panelsLastOnProcessor_ = scene_->draw(state_, width, height, panelsOverlay(width, height));
    if (!panelsLastOnProcessor_) imguiRenderer_->render(ImGui::GetDrawData());
    if (state_.ui.screenshot && state_.ui.screenshot->delayFrames-- <= 0) takeScreenshot(width, height);
}

render::Renderer::RasterOverlay App::panelsOverlay(int framebufferWidth, int framebufferHeight) {
    const ImDrawData* data = ImGui::GetDrawData();
    if (!state_.ui.panelsOnProcessor || !data || !rasterisable(*data, imguiRenderer_->fontTexture()) ||
        static_cast<int>(data->DisplaySize.x * data->FramebufferScale.x) != framebufferWidth ||
        static_cast<int>(data->DisplaySize.y * data->FramebufferScale.y) != framebufferHeight) {
        return {};
    }
    AtlasPixels atlas;
    unsigned char* pixels = nullptr;
    ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &atlas.width, &atlas.height);
    atlas.rgba = pixels;
    if (!state_.ui.keepPanels) {
        return
            [data, atlas](render::RasterImage& image) { rasteriseImGui(*data, atlas, image, render::rasterThreads()); };
    }
    return [this, data, atlas](render::RasterImage& image) {
        keptPanels_->drawOver(*data, atlas, image, render::rasterThreads());
    };
}

// A trace or a ray tree running, a screenshot due, or a text field being edited (its cursor blinks).
bool App::busy() const {
    ImGui::SetCurrentContext(context_);
    return state_.traces.job.running() || state_.traces.rayTreeJob.running() || state_.ui.screenshot.has_value() ||
           ImGui::GetIO().WantTextInput;
}

void App::takeScreenshot(int framebufferWidth, int framebufferHeight) {
    const ScreenshotRequest request = *state_.ui.screenshot;
    state_.ui.screenshot.reset();
    state_.ui.status.attempt("screenshot not saved", [&] {
        snapshot::Image image;
        if (request.panels) {
            image = readFramebuffer(gl_, framebufferWidth, framebufferHeight);
        } else {
            const int width = request.width > 0 ? request.width : framebufferWidth;
            const int height = request.height > 0 ? request.height : framebufferHeight;
            image = renderViewport(gl_, *scene_, state_, width, height);
        }
        writePng(image, request.file);
        state_.ui.lastScreenshot = request.file;
        state_.ui.status.say("screenshot saved: " +
                             std::filesystem::absolute(request.file).lexically_normal().string());
    });
}

}  // namespace dropscope::gui
