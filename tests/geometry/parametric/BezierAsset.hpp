#pragma once

// Reading Bezier patch nets from the assets' JSON ({"patches": rows of 4 x 4 control-point nets}), for the
// Bezier surface and shape tests.
#include "geometry/parametric/ParametricPresets.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace dropscope::testing {

using Patches = std::vector<std::vector<BezierNet>>;

inline Patches readPatches(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    const nlohmann::json json = nlohmann::json::parse(in);
    Patches patches;
    for (const auto& jsonRow : json.at("patches")) {
        std::vector<BezierNet> row;
        for (const auto& jsonNet : jsonRow) {
            BezierNet net;
            for (std::size_t i = 0; i < 4; ++i)
                for (std::size_t j = 0; j < 4; ++j) {
                    const auto& p = jsonNet.at(i).at(j);
                    net[i][j] = Point(p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>());
                }
            row.push_back(net);
        }
        patches.push_back(row);
    }
    return patches;
}

// The flattened droplet asset: 2 x 4 bicubic patches, rows from the north pole (z = 1) to the south pole
// (z = -0.6), domain [0, 2] x [0, 4].
inline Patches flattenedDropletPatches() {
    return readPatches(DROPSCOPE_SOURCE_DIR "/assets/shapes/flattened_droplet.json");
}

}  // namespace dropscope::testing
