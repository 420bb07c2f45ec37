#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace dropscope::snapshot {

// 8-bit RGBA pixels, top row first.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;

    const std::uint8_t* pixel(int x, int y) const {
        return rgba.data() + 4 * (static_cast<std::size_t>(y) * width + x);
    }
};

// The PNG file's bytes (stb_image_write).
std::string encodePng(const Image& image);
// Reads a PNG as RGBA; throws std::runtime_error naming the file when it cannot.
Image readPng(const std::filesystem::path& file);

}  // namespace dropscope::snapshot
