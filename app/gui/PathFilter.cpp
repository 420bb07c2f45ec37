#include "gui/PathFilter.hpp"

#include <algorithm>
#include <limits>

namespace dropscope::gui {

int rayOrder(const PhotonPath& path) {
    RayOrder order;
    for (const Event& event : path.events) order.add(event);
    return order.order();
}

// Choices 1.. of kOrderChoices are unscattered, p0 .. p5+, multiple, diffraction: the orders -1 .. 7.
const char* orderName(int order) {
    const int known = std::clamp(order, RayOrder::kUnscattered, RayOrder::kDiffracted);
    return kOrderChoices[static_cast<std::size_t>(known - RayOrder::kUnscattered + 1)];
}

bool hasOrderChoice(const PhotonPath& path, int choice) {
    if (choice <= 0) return true;
    return rayOrder(path) == choice - 1 + RayOrder::kUnscattered;
}

bool hitsDetector(const PhotonPath& path, const Detector& detector, std::size_t index) {
    const auto& events = path.events;
    if (events.empty()) return false;
    const Event& last = events.back();
    if (detector.type == DetectorType::FarField) {
        // A photon escaping along d is seen from -d (Detector.hpp).
        return last.type == EventType::Escape && FarFieldCamera(detector).pixelOf(-last.direction).has_value();
    }
    if (detector.type != DetectorType::Plane) return false;
    if (last.type == EventType::Detect && last.detector == index) return true;
    const PlaneFrame frame = planeFrame(detector);
    for (std::size_t k = 0; k + 1 < events.size(); ++k) {
        const Point& from = events[k].position;
        const double length = (events[k + 1].position - from).norm();
        if (crossPlane(detector, frame, from, events[k].direction, length)) return true;
    }
    return last.type == EventType::Escape &&
           crossPlane(detector, frame, last.position, last.direction, std::numeric_limits<double>::infinity());
}

std::vector<int> filterPaths(const std::vector<PhotonPath>& paths, const std::vector<Detector>& detectors,
                             const PathFilter& filter) {
    std::vector<int> kept;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        if (!hasOrderChoice(paths[i], filter.order)) continue;
        if (filter.detector && (*filter.detector >= detectors.size() ||
                                !hitsDetector(paths[i], detectors[*filter.detector], *filter.detector))) {
            continue;
        }
        kept.push_back(static_cast<int>(i));
    }
    return kept;
}

}  // namespace dropscope::gui
