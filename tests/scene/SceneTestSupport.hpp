#pragma once

#include "scene/SceneLoader.hpp"

#include <string>
#include <string_view>

namespace dropscope::test {

// The SceneError message parseScene gives for `text` read as "scene.json", or "no error".
inline std::string sceneErrorOf(std::string_view text) {
    try {
        parseScene(text, "scene.json");
    } catch (const SceneError& error) {
        return error.what();
    }
    return "no error";
}

// A version-1 scene with one medium "water" and the given "shapes" array body.
inline std::string sceneWithShapes(const std::string& shapes) {
    return R"({"dropscope": 1, "media": {"water": {"n": 1.333}}, "shapes": [)" + shapes + "]}";
}

}  // namespace dropscope::test
