#include "results/ImagePng.hpp"

#include <stb/stb_image_write.h>

#include <ostream>
#include <stdexcept>
#include <string>

namespace dropscope {

void writeImagePng(const ResultImage& image, std::ostream& out) {
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::ostream*>(context)->write(static_cast<const char*>(data), size);
    };
    if (!stbi_write_png_to_func(append, &out, image.width, image.height, 3, image.rgb.data(), 3 * image.width)) {
        throw std::runtime_error("cannot encode image " + image.name + " as PNG");
    }
}

}  // namespace dropscope
