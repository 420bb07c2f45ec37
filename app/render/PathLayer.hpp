#pragma once

#include "render/Chords.hpp"
#include "render/DrawData.hpp"
#include "run/TraceRun.hpp"
#include "transport/RayTree.hpp"

#include <vector>

namespace dropscope::render {

// How photon path segments are coloured.
enum class PathColouring {
    Weight,      // along viridis by the weight the segment starts with (an analog photon's is 1: the top)
    Event,       // by the type of the event the segment starts at (eventColour): how the light got there
    Dolp,        // along viridis by the degree of linear polarisation the segment starts with; grey when the
                 // photons carry no polarisation (traced with PolarisationModel::None)
    Wavelength,  // the colour of the photon's wavelength (displayColourOfWavelength, docs/spectra.md "Colour")
};

// Photon paths as polylines; an escape goes on for `escapeLength` along its direction. With `chords`, the
// segments that are chords of a sphere or ellipsoid (isChord) go to its batch instead.
void addPhotonPaths(LineBatch& lines, const std::vector<PhotonPath>& paths, double escapeLength,
                    PathColouring colouring = PathColouring::Weight, const ChordSplit* chords = nullptr);

// One small sphere of `radius` at every event of the paths, coloured by event type (eventColour).
void addEventMarkers(std::vector<ShapeInstance>& markers, const std::vector<PhotonPath>& paths, double radius,
                     const Anchor& anchor);
// The same at every node of a ray tree.
void addEventMarkers(std::vector<ShapeInstance>& markers, const RayTree& tree, double radius, const Anchor& anchor);

}  // namespace dropscope::render
