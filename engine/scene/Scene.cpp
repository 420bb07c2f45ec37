#include "scene/Scene.hpp"

namespace dropscope {

std::optional<MediumId> Scene::findMedium(const std::string& name) const {
    for (std::size_t i = 0; i < media.size(); ++i) {
        if (media[i].name == name) return static_cast<MediumId>(i);
    }
    return std::nullopt;
}

}  // namespace dropscope
