#pragma once

#include "geometry/Shape.hpp"
#include "scene/Detector.hpp"
#include "scene/Medium.hpp"
#include "scene/RadiusDistribution.hpp"
#include "scene/SceneView.hpp"
#include "scene/Source.hpp"
#include "tree/OctreeTypes.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace dropscope {

// What one entry of "generators" made: its droplets are shapes[firstShape, firstShape + count), all of `medium`,
// their radii drawn from `radius` (dropscope mie --generator averages over it).
struct GeneratedCloud {
    RadiusDistribution radius;
    MediumId medium = 0;
    std::size_t firstShape = 0;
    std::size_t count = 0;
};

// Everything a scene file describes (docs/scene-format.md). Shape ids are indices into `shapes`:
// the explicit shapes of "shapes" first, then those of "generators", in generator order.
struct Scene {
    std::string origin;  // file the scene was read from, for messages
    int formatVersion = 1;
    std::string unit = "mm";
    double unitInMetres = 1e-3;
    double wavelengthNm = 532.0;
    MediumId ambient = 0;  // index into media
    std::vector<Medium> media;
    std::vector<std::unique_ptr<Shape>> shapes;
    std::vector<std::string> shapeNames;     // parallel to shapes; empty when unnamed (always for generated)
    std::size_t explicitShapeCount = 0;      // shapes[0, explicitShapeCount) come from "shapes"
    std::vector<GeneratedCloud> generators;  // in file order
    std::vector<Source> sources;
    std::vector<Detector> detectors;  // scene key "detectors" (docs/detectors.md)
    OctreeSettings octree;            // scene key "octree"
    std::optional<SceneView> view;    // scene key "view": the renderer's starting camera

    const Medium& mediumOf(const Shape& shape) const { return media.at(shape.mediumId()); }
    std::optional<MediumId> findMedium(const std::string& name) const;
    // The wavelength expressed in the scene's length unit.
    double wavelengthInSceneUnits() const { return wavelengthNm * 1e-9 / unitInMetres; }
};

}  // namespace dropscope
