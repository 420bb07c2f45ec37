#include "results/NumberText.hpp"

#include <charconv>

namespace dropscope {

std::string shortestText(double value) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return {text, end};
}

}  // namespace dropscope
