#pragma once

#include "gui/AppState.hpp"
#include "gui/ViewportScene.hpp"
#include "render/GlFunctions.hpp"
#include "snapshot/Image.hpp"

#include <filesystem>

namespace dropscope::gui {

// Largest screenshot side accepted (llvmpipe's renderbuffers go to 16384; 8192 keeps a frame under
// 256 MB of RGBA).
inline constexpr int kMaxScreenshotSide = 8192;

// The window's framebuffer as it is now (everything drawn this frame, panels included), top row first.
snapshot::Image readFramebuffer(const render::GlFunctions& gl, int width, int height);

// The 3D view alone at width x height, drawn into an offscreen framebuffer object with the state's
// camera; the window's own framebuffer is bound again afterwards. Throws render::RenderError when the
// driver refuses the size.
snapshot::Image renderViewport(const render::GlFunctions& gl, ViewportScene& scene, AppState& state, int width,
                               int height);

// The PNG, whole or not at all (writeFileAtomically).
void writePng(const snapshot::Image& image, const std::filesystem::path& file);

}  // namespace dropscope::gui
