// libFuzzer target: the Bezier patches file a scene's bezier shape names (parseBezierPatchesFile) on any text. A
// bad file must be refused with a SceneError; any other exception, a crash, a sanitizer report, a leak or a hang
// is a finding (docs/fuzzing.md).
#include "scene/GeneralShapeReader.hpp"
#include "scene/SceneLoader.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        dropscope::parseBezierPatchesFile(text, "patches.json");
    } catch (const dropscope::SceneError&) {
        // refused, as it should be
    }
    return 0;
}
