#pragma once

#include "gui/AppState.hpp"
#include "render/Renderer.hpp"

namespace dropscope::gui {

// The 3D view behind the panels: turns the app state into the renderer's shapes and line layers
// (rebuilt only when something drawn changed) and draws them with the state's camera.
class ViewportScene {
public:
    explicit ViewportScene(const render::GlFunctions& gl) : renderer_(gl) {}

    // Rebuilds what changed, fits or clips the camera, and draws into the bound framebuffer.
    void draw(AppState& state, int width, int height);

    // What the last rebuild handed to the renderer, for the UI tests.
    const render::SceneLayers& layers() const { return layers_; }
    std::uint64_t rebuilds() const { return rebuilds_; }

private:
    void rebuild(AppState& state);

    render::Renderer renderer_;
    render::SceneLayers layers_{render::LineBatch(render::Anchor{}), {}};
    Eigen::AlignedBox3d bounds_;
    std::uint64_t rebuilds_ = 0;
};

// The box the camera keeps between its near and far planes: the shapes, the sources, and room for the
// escaping ends of paths.
Eigen::AlignedBox3d viewBounds(const AppState& state, const Eigen::AlignedBox3d& shapes);

}  // namespace dropscope::gui
