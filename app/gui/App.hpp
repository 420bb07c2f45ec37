#pragma once

#include "gui/AppState.hpp"
#include "gui/FrameClient.hpp"
#include "gui/ItemProbe.hpp"
#include "gui/ViewportControls.hpp"
#include "gui/ViewportScene.hpp"
#include "render/GlFunctions.hpp"
#include "scene/Scene.hpp"

#include <filesystem>
#include <memory>
#include <string>

struct ImGuiContext;

namespace dropscope::gui {

class ImGuiRenderer;
class KeptPanels;

struct AppOptions {
    std::filesystem::path scenePath;                  // where the scene came from (Save writes there); may be empty
    std::filesystem::path iniFile;                    // ImGui's panel layout, remembered between runs; empty: not kept
    std::filesystem::path screenshotDirectory = ".";  // where F12 puts its timestamped PNGs
    ItemProbe itemProbe;                              // the UI tests' (ItemProbe.hpp); none in the app
};

// The interactive app: the 3D view with its mouse controls, the panels, the shortcuts, screenshots.
// Everything but the window: the GLFW window drives it in dropscope, an OSMesa buffer in the UI tests,
// with the same InputFrame either way. Owns the ImGui context; one App at a time.
class App : public FrameClient {
public:
    App(const render::GlFunctions& gl, Scene scene, const AppOptions& options);
    ~App() override;
    App(const App&) = delete;
    App& operator=(const App&) = delete;

    void frame(const InputFrame& input) override;
    bool quitRequested() const override { return state_.ui.quit; }
    bool busy() const override;

    AppState& state() { return state_; }
    const AppState& state() const { return state_; }
    const ViewportScene& viewport() const { return *scene_; }

    // Whether the last frame's panels were drawn on the processor, into its 3D view's picture (panelsOverlay).
    bool panelsLastOnProcessor() const { return panelsLastOnProcessor_; }

private:
    void buildUi();
    void takeScreenshot(int framebufferWidth, int framebufferHeight);
    // The last ImGui frame's panels drawn on the processor (UiState::panelsOnProcessor), for the 3D view to draw over
    // its picture when it is drawn there; none when they show an OpenGL texture or the frame is not the display's.
    render::Renderer::RasterOverlay panelsOverlay(int framebufferWidth, int framebufferHeight);

    const render::GlFunctions& gl_;
    AppOptions options_;
    std::string iniFile_;  // ImGui keeps a pointer to this
    ImGuiContext* context_ = nullptr;
    std::unique_ptr<ImGuiRenderer> imguiRenderer_;
    std::unique_ptr<KeptPanels> keptPanels_;  // for panelsOverlay (UiState::keepPanels)
    std::unique_ptr<ViewportScene> scene_;
    ViewportControls controls_;
    AppState state_;
    bool panelsLastOnProcessor_ = false;
};

}  // namespace dropscope::gui
