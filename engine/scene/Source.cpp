#include "scene/Source.hpp"

namespace dropscope {

std::string_view sourceTypeName(SourceType type) {
    switch (type) {
    case SourceType::Beam: return "beam";
    case SourceType::Ray: return "ray";
    case SourceType::PointSource: return "point";
    }
    return "unknown";
}

}  // namespace dropscope
