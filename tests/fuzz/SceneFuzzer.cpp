// libFuzzer target: the scene loader (parseScene) on any text. A bad scene must be refused with a SceneError;
// any other exception, a crash, a sanitizer report, a leak or a hang is a finding (docs/fuzzing.md).
#include "InputBudget.hpp"

#include "scene/SceneLoader.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

// Files a scene names (a bezier's "patches") resolve beside this path, so the seeds' "../shapes/..." is found.
const std::string kOrigin = DROPSCOPE_FUZZ_SCENE_ORIGIN;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    if (!dropscope::fuzz::withinInputBudget(text)) return -1;  // slow by design: not kept in the corpus
    try {
        dropscope::parseScene(text, kOrigin);
    } catch (const dropscope::SceneError&) {
        // refused, as it should be
    }
    return 0;
}
