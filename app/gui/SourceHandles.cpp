#include "gui/SourceHandles.hpp"

#include <algorithm>
#include <limits>

namespace dropscope::gui {

double distanceToRay(const Ray& ray, const Point& point) {
    const Eigen::Vector3d offset = point - ray.origin;
    const double along = offset.dot(ray.direction.vector());
    if (along <= 0.0) return std::numeric_limits<double>::infinity();
    return (offset - along * ray.direction.vector()).norm();
}

std::optional<SourceHandlePlaces> sourceHandles(const AppState& state, const Eigen::AlignedBox3d& sceneBounds) {
    const auto& sources = state.scene.document().sources();
    if (!state.view.layers.sources || sources.empty() || sceneBounds.isEmpty()) return std::nullopt;
    if (state.view.layers.detectors && state.scene.selectedDetector()) return std::nullopt;
    const Source& source = sources[state.scene.selectedSource()];
    const double diagonal = sceneBounds.diagonal().norm();
    const double arrow = render::kSourceGlyph * diagonal;
    const Eigen::Vector3d direction = source.direction ? source.direction.vector() : Eigen::Vector3d::UnitZ();
    return SourceHandlePlaces{source.origin, source.origin + arrow * direction,
                              kHandleMarkerScale * render::kMarkerRadius * diagonal};
}

SourceHandle handleUnder(const AppState& state, const Eigen::AlignedBox3d& sceneBounds, const Ray& ray) {
    const auto handles = sourceHandles(state, sceneBounds);
    if (!handles) return SourceHandle::None;
    const double origin = distanceToRay(ray, handles->origin);
    const auto& sources = state.scene.document().sources();
    const double aim = sources[state.scene.selectedSource()].type == SourceType::PointSource
                           ? std::numeric_limits<double>::infinity()
                           : distanceToRay(ray, handles->aim);
    const double reach = kGrabScale * handles->radius;
    if (std::min(origin, aim) > reach) return SourceHandle::None;
    return origin <= aim ? SourceHandle::Origin : SourceHandle::Aim;
}

}  // namespace dropscope::gui
