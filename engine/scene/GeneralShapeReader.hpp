#pragma once

#include "geometry/Shape.hpp"
#include "scene/JsonReader.hpp"

#include <map>
#include <memory>
#include <string>
#include <string_view>

namespace dropscope {

class ImplicitFunction;
class ParametricSurface;

// The bases read so far, by preset and parameters: shapes with equal presets share one base
// (std::shared_ptr, seed 000 1.4), so its mesh, cover and integrals are computed once.
class BaseCache {
public:
    std::shared_ptr<const void> find(const std::string& key) const;
    void add(const std::string& key, std::shared_ptr<const void> base);

private:
    std::map<std::string, std::shared_ptr<const void>> bases_;
};

// Loading an implicit shape integrates its volume and area along lines through it once per distinct base
// (preset and parameters; shapes that differ only in transform, medium or name share one), measured at about
// 0.13 s for a superellipsoid or a blob of 4 spheres (Release, one core). A blob evaluates every sphere at
// every point, and a line crosses more of them the more there are, so its cost grows with the square of
// their number: 0.59 s for 16 spheres, 3.1 s for 64, 39 s for 256. The limits keep a scene's load under
// three minutes (docs/limits.md).
inline constexpr std::size_t kMaxBlobSpheres = 64;
inline constexpr double kMaxImplicitLoadSeconds = 150.0;

// The estimated seconds to load one implicit base (Release, one core): 0.13 s for a superellipsoid, and for a
// blob a fit to the measured times.
double implicitLoadSeconds(const ImplicitFunction& function);

// Refuses `shapes` (the scene's "shapes" array) when its distinct implicit bases would take more than
// kMaxImplicitLoadSeconds to load, naming the shape that crosses the limit, before any is built.
void checkImplicitLoadTime(const JsonReader& shapes);

// {"type": "parametric", "preset": "sphere" | "ellipsoid" | "torus" | "bezier", its parameters, "transform"}
// and {"type": "implicit", "preset": "superellipsoid" | "blob", ...}, without the medium (the caller sets
// it). A bezier's "patches" may name a JSON file {"patches": [...]}, relative to the scene file.
std::unique_ptr<Shape> readParametricShape(const JsonReader& json, BaseCache& cache);
std::unique_ptr<Shape> readImplicitShape(const JsonReader& json, BaseCache& cache);

// The surface of a patches file's text, {"patches": [...]} (the file a bezier's "patches" names); `origin`
// names it in messages. Throws SceneError.
std::shared_ptr<const ParametricSurface> parseBezierPatchesFile(std::string_view text, const std::string& origin);

}  // namespace dropscope
