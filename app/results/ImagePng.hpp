#pragma once

#include "tally/ResultReport.hpp"

#include <iosfwd>

namespace dropscope {

// A result image as an 8-bit RGB PNG file (stb_image_write). Throws std::runtime_error if it cannot be encoded.
void writeImagePng(const ResultImage& image, std::ostream& out);

}  // namespace dropscope
