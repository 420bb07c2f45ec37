#pragma once

#include "tally/DetectorTallies.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace dropscope::gui {

// A plane or far-field detector's image as its window shows it, taken from the tally's report (the numbers of
// the files `dropscope trace` writes). Per pixel, numbered iy * nx + ix (row 0 at the bottom).
struct DetectorImage {
    Detector detector;
    std::vector<double> fraction;              // of the emitted photons
    std::vector<double> density;               // irradiance (plane, 1/scene unit^2) or radiance (far field, 1/sr)
    std::vector<std::array<double, 2>> where;  // the pixel centre's u, v (plane) or theta, azimuth in deg (far field)
    std::vector<std::uint8_t> sky;             // far field: the true-colour sRGB image, 3 bytes a pixel; else empty
    double maxDensity = 0.0;                   // over the pixels with a finite density
    std::uint64_t photons = 0;                 // traced
    std::uint64_t hits = 0;                    // counted by the detector
};

// The image of a PlaneDetectorTally or FarFieldTally; none for any other tally.
std::optional<DetectorImage> detectorImage(const DetectorTally& tally);
// "irradiance" or "radiance", and its unit.
const char* densityName(const Detector& detector);
const char* densityUnit(const Detector& detector);

}  // namespace dropscope::gui
