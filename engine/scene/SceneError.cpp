#include "scene/SceneLoader.hpp"

namespace dropscope {

namespace {

std::string oneLine(const std::string& origin, const std::string& jsonPath, const std::string& message) {
    std::string line = origin + ": ";
    if (!jsonPath.empty()) line += jsonPath + ": ";
    return line + message;
}

}  // namespace

SceneError::SceneError(const std::string& origin, const std::string& jsonPath, const std::string& message)
    : std::runtime_error(oneLine(origin, jsonPath, message)), jsonPath_(jsonPath), detail_(message) {}

}  // namespace dropscope
