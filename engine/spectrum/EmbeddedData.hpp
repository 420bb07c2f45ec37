#pragma once

#include <string_view>
#include <vector>

namespace dropscope {

// Tables of published data shipped under assets/data/ and compiled into the engine (engine/CMakeLists.txt,
// dropscope_embed_text), so that no program needs to find the assets at run time. Each file starts with
// '#' lines naming its source, then a header line, then rows of comma-separated numbers.
namespace embedded {
extern const std::string_view kCie1931Cmf;  // assets/data/cie1931_2deg_cmf.csv
extern const std::string_view kWaterKappa;  // assets/data/water_kappa_hale_querry_1973.csv
}  // namespace embedded

// The rows of numbers of such a file (comments and the header line skipped), each with `columns` numbers.
// Throws std::runtime_error naming `name` and the line for a row that does not parse.
std::vector<std::vector<double>> parseNumberTable(std::string_view text, std::size_t columns, std::string_view name);

}  // namespace dropscope
