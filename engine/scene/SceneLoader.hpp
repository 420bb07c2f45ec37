#pragma once

#include "scene/Scene.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace dropscope {

// A bad scene: what() is one line "FILE: JSON.PATH: message", e.g.
// "scene.json: shapes[3].radius: must be > 0".
class SceneError : public std::runtime_error {
public:
    SceneError(const std::string& origin, const std::string& jsonPath, const std::string& message);
    const std::string& jsonPath() const { return jsonPath_; }
    const std::string& detail() const { return detail_; }

private:
    std::string jsonPath_;
    std::string detail_;
};

// Reads and validates a scene file (format version 1). Throws SceneError.
Scene loadScene(const std::filesystem::path& file);
// Same from text already in memory; `origin` names it in messages.
Scene parseScene(std::string_view jsonText, const std::string& origin);

}  // namespace dropscope
