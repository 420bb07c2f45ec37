#include "snapshot/Image.hpp"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <memory>
#include <stdexcept>

namespace dropscope::snapshot {

std::string encodePng(const Image& image) {
    std::string bytes;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
    };
    if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.rgba.data(), 4 * image.width)) {
        throw std::runtime_error("cannot encode a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                 " PNG");
    }
    return bytes;
}

Image readPng(const std::filesystem::path& file) {
    int width = 0;
    int height = 0;
    int channels = 0;
    const std::unique_ptr<stbi_uc, void (*)(void*)> data(stbi_load(file.c_str(), &width, &height, &channels, 4),
                                                         stbi_image_free);
    if (!data) throw std::runtime_error(file.string() + ": cannot read as PNG: " + stbi_failure_reason());
    Image image{width, height, {}};
    image.rgba.assign(data.get(), data.get() + 4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    return image;
}

}  // namespace dropscope::snapshot
