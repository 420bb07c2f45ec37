#pragma once

#include "geometry/Shape.hpp"
#include "scene/JsonReader.hpp"

#include <map>
#include <memory>
#include <string>
#include <string_view>

namespace dropscope {

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

// {"type": "parametric", "preset": "sphere" | "ellipsoid" | "torus" | "bezier", its parameters, "transform"}
// and {"type": "implicit", "preset": "superellipsoid" | "blob", ...}, without the medium (the caller sets
// it). A bezier's "patches" may name a JSON file {"patches": [...]}, relative to the scene file.
std::unique_ptr<Shape> readParametricShape(const JsonReader& json, BaseCache& cache);
std::unique_ptr<Shape> readImplicitShape(const JsonReader& json, BaseCache& cache);

// The surface of a patches file's text, {"patches": [...]} (the file a bezier's "patches" names); `origin`
// names it in messages. Throws SceneError.
std::shared_ptr<const ParametricSurface> parseBezierPatchesFile(std::string_view text, const std::string& origin);

}  // namespace dropscope
