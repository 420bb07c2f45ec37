// libFuzzer target: the rays CSV reader of `dropscope query` (parseRayCsv) on any text. A bad file must be
// refused with a RayCsvError; any other exception, a crash, a sanitizer report, a leak or a hang is a finding, and
// so is a ray read with an origin that is not finite or a direction that is not a unit vector (docs/fuzzing.md).
#include "cli/RayCsv.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        for (const dropscope::CsvRay& ray : dropscope::parseRayCsv(text, "rays.csv")) {
            if (!ray.origin.allFinite() || !ray.direction || std::abs(ray.direction.vector().norm() - 1.0) > 1e-12) {
                __builtin_trap();
            }
        }
    } catch (const dropscope::RayCsvError&) {
        // refused, as it should be
    }
    return 0;
}
