#include "gui/Screenshot.hpp"

#include "render/OffscreenImage.hpp"
#include "render/RenderError.hpp"
#include "results/AtomicFile.hpp"

#include <algorithm>
#include <ostream>
#include <string>

namespace dropscope::gui {

snapshot::Image readFramebuffer(const render::GlFunctions& gl, int width, int height) {
    snapshot::Image image{width, height, std::vector<std::uint8_t>(4 * static_cast<std::size_t>(width) * height)};
    std::vector<std::uint8_t> bottomUp(image.rgba.size());
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    const std::size_t row = 4 * static_cast<std::size_t>(width);
    for (int y = 0; y < height; ++y) {
        const auto source =
            bottomUp.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(height - 1 - y));
        std::copy(source, source + static_cast<std::ptrdiff_t>(row),
                  image.rgba.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y)));
    }
    for (std::size_t k = 3; k < image.rgba.size(); k += 4) image.rgba[k] = 255;  // a PNG of the view is opaque
    return image;
}

snapshot::Image renderViewport(const render::GlFunctions& gl, ViewportScene& scene, AppState& state, int width,
                               int height) {
    if (width < 1 || height < 1 || width > kMaxScreenshotSide || height > kMaxScreenshotSide) {
        throw render::RenderError("screenshot size " + std::to_string(width) + "x" + std::to_string(height) +
                                  " is outside 1.." + std::to_string(kMaxScreenshotSide));
    }
    render::OffscreenImage target(gl);
    if (!target.bindForDrawing(width, height)) {
        throw render::RenderError("the driver cannot render a " + std::to_string(width) + "x" + std::to_string(height) +
                                  " screenshot");
    }
    scene.draw(state, width, height);
    snapshot::Image image = readFramebuffer(gl, width, height);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    return image;
}

void writePng(const snapshot::Image& image, const std::filesystem::path& file) {
    const std::string bytes = snapshot::encodePng(image);
    writeFileAtomically(
        file, [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
}

}  // namespace dropscope::gui
