#pragma once

#include "geometry/Vector.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
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
// but must be finite and non-zero). Blank lines are skipped; CRLF, a last line without a newline, and spaces
// or tabs around a field are accepted. The file is read through a reused block of a megabyte and scanned in
// place (std::from_chars, no copy of a line), each block in parts on OpenMP's threads (OMP_NUM_THREADS): millions
// of rays a second, docs/performance.md ("Query I/O"). Errors are those of reading line by line: the first bad
// line in the file, with its number.
std::vector<CsvRay> readRayCsv(const std::filesystem::path& file);
std::vector<CsvRay> parseRayCsv(std::string_view text, const std::string& origin);

}  // namespace dropscope
