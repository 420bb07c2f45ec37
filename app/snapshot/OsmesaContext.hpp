#pragma once

#include "render/GlFunctions.hpp"
#include "snapshot/Image.hpp"

#include <memory>
#include <vector>

namespace dropscope::snapshot {

// A headless OpenGL 3.3 core context (OSMesa, llvmpipe) rendering into memory: no display, no X server.
// Its GL functions come from OSMesaGetProcAddress into render::GlFunctions.
class OsmesaContext {
public:
    OsmesaContext(int width, int height);  // throws render::RenderError when OSMesa cannot make one
    ~OsmesaContext();
    OsmesaContext(const OsmesaContext&) = delete;
    OsmesaContext& operator=(const OsmesaContext&) = delete;

    const render::GlFunctions& gl() const { return gl_; }
    // For tests: what the renderers on this context take its framebuffer's layout to be (GlFunctions::windowLayout).
    void setWindowLayout(render::PixelLayout layout) { gl_.windowLayout = layout; }
    int width() const { return width_; }
    int height() const { return height_; }
    // The finished frame, top row first.
    Image read() const;

private:
    struct Handle;
    int width_;
    int height_;
    std::vector<std::uint8_t> buffer_;  // OSMesa's colour buffer, bottom row first
    std::unique_ptr<Handle> handle_;
    render::GlFunctions gl_;
};

}  // namespace dropscope::snapshot
