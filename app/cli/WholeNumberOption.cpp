#include "cli/WholeNumberOption.hpp"

#include "cli/WholeNumber.hpp"

#include <optional>
#include <string>

namespace dropscope {

CLI::Validator wholeNumberIn(std::uint64_t minimum, std::uint64_t maximum) {
    const std::string range = maximum == kNoUpperBound
                                  ? ">= " + std::to_string(minimum)
                                  : "from " + std::to_string(minimum) + " to " + std::to_string(maximum);
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            const std::optional<std::uint64_t> value = parseWholeNumber(text);
            if (!value || *value < minimum || *value > maximum) {
                return "must be a whole number " + range + ", got \"" + text + "\"";
            }
            text = std::to_string(*value);
            return {};
        },
        "");
}

}  // namespace dropscope
