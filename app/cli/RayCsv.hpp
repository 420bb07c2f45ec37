#pragma once

#include "geometry/Vector.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace dropscope {

struct CsvRay {
    Point origin;
    Direction direction;
};

// A bad rays file: what() is one line "FILE:LINE: message" (or "FILE: message").
class RayCsvError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Reads `ox,oy,oz,dx,dy,dz` (that header, then one ray a line; directions need not be normalised,
// but must be finite and non-zero). Blank lines are skipped; CRLF is accepted.
std::vector<CsvRay> readRayCsv(const std::filesystem::path& file);
std::vector<CsvRay> parseRayCsv(const std::string& text, const std::string& origin);

}  // namespace dropscope
