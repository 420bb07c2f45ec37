#pragma once

#include "render/DrawData.hpp"
#include "scene/Detector.hpp"
#include "tally/ResultReport.hpp"

#include <string>
#include <vector>

namespace dropscope::render {

inline constexpr Colour kDetectorColour{0.45f, 0.85f, 0.95f, 1.0f};  // pale cyan: what looks at the light
inline constexpr Colour kDetectorAxisU{0.95f, 0.45f, 0.45f, 1.0f};   // u red, v green, as the axes' x and y
inline constexpr Colour kDetectorAxisV{0.45f, 0.90f, 0.45f, 1.0f};
inline constexpr Colour kAbsorbingFill{0.10f, 0.10f, 0.12f, 1.0f};  // an absorbing plane without its image
// An image is drawn with at most this many cells a side: a larger grid is summed in blocks.
inline constexpr int kMaxDrawnImageSide = 256;
// A far-field camera's frustum is drawn at most this wide (a fisheye's 360 degrees would fold it back).
inline constexpr double kMaxDrawnFovDeg = 140.0;

// A plane detector's image: a value per pixel in its PixelGrid's order (iy outer, ix inner), drawn through
// viridis normalised to the image's maximum.
struct DetectorImage {
    std::string name;  // the detector's
    PixelGrid pixels;
    std::vector<double> values;
};

// The images of `detectors`' planes in a run's report: table "detector-NAME"'s fraction column (of the emitted
// power, PlaneDetectorTally), for each plane whose table is there with its grid.
std::vector<DetectorImage> planeDetectorImages(const ResultReport& report, const std::vector<Detector>& detectors);

// How long a plane's arrow is: the glyph length `size`, or a quarter of its shorter side when that is longer
// (so a large screen's arrow shows beside it).
double planeArrowLength(const Detector& plane, double size);

// Where a far-field camera's glyph has its eye: outside `bounds` (the shapes'), on the side it looks from,
// `size` (the glyph's length) beyond the sphere around them.
Point farFieldGlyphEye(const Detector& camera, const Eigen::AlignedBox3d& bounds, double size);

// `box` grown to hold the detectors' glyphs (the planes' corners, the far-field frusta's eyes), so a camera fitted
// or clipped to it shows them.
Eigen::AlignedBox3d withDetectorGlyphs(Eigen::AlignedBox3d box, const std::vector<Detector>& detectors,
                                       const Eigen::AlignedBox3d& bounds, double size);

// Detectors as glyphs of scale `size`, sized for `bounds`:
//  plane: its rectangle's outline, its u (red) and v (green) half-axes from the centre, and an arrow
//    (planeArrowLength) along the normal towards the side it counts (both: one each way); an absorbing plane hatched
//    and, without an image, filled dark; with an image of its name and grid in `images`, the image on it.
//  far_field: a frustum from farFieldGlyphEye along `look`, as wide as its fov (at most kMaxDrawnFovDeg) and
//    as high as its pixels' aspect, with a tick on the side of its up.
//  shape_absorption: nothing.
void addDetectorGlyphs(LineBatch& lines, TriangleBatch& surfaces, const std::vector<Detector>& detectors,
                       const std::vector<DetectorImage>& images, const Eigen::AlignedBox3d& bounds, double size);

}  // namespace dropscope::render
