#pragma once

#include "geometry/Shape.hpp"
#include "scene/Detector.hpp"
#include "scene/Source.hpp"

#include <limits>
#include <optional>
#include <string>

namespace dropscope {

struct Scene;

// Limits on a scene's geometry, in its own length unit (docs/limits.md explains each).
// Every coordinate of a shape's bounds, a source (a beam with its radius) or a plane detector lies within
// +-kMaxCoordinate: the geometry multiplies up to three lengths (volumes, quadratic coefficients), and
// 1e100 cubed is still far from the double range.
inline constexpr double kMaxCoordinate = 1e100;
// Whether every coordinate of `point` lies within +-kMaxCoordinate.
inline bool withinCoordinateLimit(const Point& point) { return !(point.cwiseAbs().maxCoeff() > kMaxCoordinate); }
// How every refusal of kMaxCoordinate ends: "beyond the limit 1e+100 on any coordinate (docs/limits.md)".
std::string beyondCoordinateLimit();

// A shape's smallest feature (smallestFeature) is at least this, for the same reason at the other end.
inline constexpr double kMinFeature = 1e-100;
// The scene's reach (the largest coordinate of anything in it) over its smallest feature. A point at
// coordinate L carries rounding of about L * 2^-52 and the surface bands widen by 64 ulps of the coordinate
// (tolerance::kCoordinateRelative = 1.4e-14); at 1e12 that band is 1.4 % of the smallest feature, the most
// that still lets a photon tell the surface of the smallest shape from its inside.
inline constexpr double kMaxScaleRatio = 1e12;

// 3 V / A: a sphere's radius, half a cube's edge, 1.5 times a thin plate's thickness, 1.5 times a thin
// needle's radius. It shrinks with the thinnest direction of a shape, whatever its orientation.
double smallestFeature(const Shape& shape);

// What makes one shape unusable (bounds, volume or area not finite, positive and within the limits above),
// as the end of a sentence about it ("its volume is not finite (inf)"), or nothing.
std::optional<std::string> shapeLimitProblem(const Shape& shape);

// What the scale limit compares: the largest coordinate of anything in a scene (its reach) and the
// smallest feature of its shapes.
struct ScaleExtremes {
    double reach = 0.0;
    double feature = std::numeric_limits<double>::infinity();
    void add(const Shape& shape);
    void add(const Source& source);      // its origin, and a beam's radius around it
    void add(const Detector& detector);  // a plane's centre and half its diagonal; far-field cameras have none
    bool withinLimit() const { return !(reach > kMaxScaleRatio * feature); }
};
// "its smallest feature (3 volume / area) F UNIT is R times smaller than the scene's reach L UNIT (WHERE);
// the limit is ..." for a shape whose feature breaks the limit against `reach`.
std::string scaleLimitMessage(double feature, double reach, const std::string& unit, const std::string& where);

// A source or a plane detector that reaches beyond kMaxCoordinate, as the end of a sentence about it.
std::optional<std::string> sourceLimitProblem(const Source& source);
std::optional<std::string> detectorLimitProblem(const Detector& detector);

// Where shape `id` (its index in scene.shapes, and its octree id) is in the scene file and what it is, as
// messages name it: `shapes[3]: sphere "d1"`, `generators[0]: droplet 17`.
std::string shapeLabel(const Scene& scene, std::size_t id);

// The scene's reach against its smallest feature (kMaxScaleRatio), and the sources and plane detectors
// against kMaxCoordinate. Throws SceneError naming the shape, source or detector, e.g.
// `scene.json: shapes[2]: sphere "d": its smallest feature 0.001 mm is 1e+15 times smaller than the
// scene's reach 1e+12 mm (sources[0]); the limit is 1e+12 (docs/limits.md)`.
void checkSceneScale(const Scene& scene);
// Sources and detectors alone (their JSON paths), before the shapes' pairwise checks.
void checkSourceAndDetectorLimits(const Scene& scene);

}  // namespace dropscope
