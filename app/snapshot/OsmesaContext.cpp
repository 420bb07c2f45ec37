#include "snapshot/OsmesaContext.hpp"

#include "render/RenderError.hpp"

#include <GL/osmesa.h>

#include <algorithm>
#include <string>

namespace dropscope::snapshot {

struct OsmesaContext::Handle {
    OSMesaContext context = nullptr;
};

namespace {

void* procAddress(const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }

}  // namespace

OsmesaContext::OsmesaContext(int width, int height)
    : width_(width),
      height_(height),
      buffer_(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height)),
      handle_(std::make_unique<Handle>()) {
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    handle_->context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!handle_->context) throw render::RenderError("OSMesa cannot create an OpenGL 3.3 core context");
    if (!OSMesaMakeCurrent(handle_->context, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
        OSMesaDestroyContext(handle_->context);
        throw render::RenderError("OSMesa cannot make its context current at " + std::to_string(width) + "x" +
                                  std::to_string(height));
    }
    try {
        gl_ = render::GlFunctions::load(procAddress);
        gl_.windowLayout = {.topRowFirst = true, .bgra = false};  // OSMESA_RGBA
    } catch (...) {
        OSMesaDestroyContext(handle_->context);
        throw;
    }
}

OsmesaContext::~OsmesaContext() { OSMesaDestroyContext(handle_->context); }

Image OsmesaContext::read() const {
    gl_.Finish();
    Image image{width_, height_, std::vector<std::uint8_t>(buffer_.size())};
    const std::size_t row = 4 * static_cast<std::size_t>(width_);
    for (int y = 0; y < height_; ++y) {
        const auto source =
            buffer_.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(height_ - 1 - y));
        std::copy(source, source + static_cast<std::ptrdiff_t>(row),
                  image.rgba.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y)));
    }
    return image;
}

}  // namespace dropscope::snapshot
