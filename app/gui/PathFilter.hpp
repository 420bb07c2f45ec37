#pragma once

#include "run/TraceRun.hpp"
#include "scene/Detector.hpp"
#include "tally/OrderTally.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace dropscope::gui {

// The Paths panel's filters: which recorded photons its list shows.
//  order: a choice of kOrderChoices (0: any);
//  detector: a plane detector the path crossed or ended on, or a far-field camera it escaped into (an index
//    into the traced scene's detectors), or none: any path.
struct PathFilter {
    int order = 0;
    std::optional<std::size_t> detector;
    bool operator==(const PathFilter&) const = default;
};

inline constexpr std::array<const char*, 10> kOrderChoices{"any", "unscattered", "p0",  "p1",       "p2",
                                                           "p3",  "p4",          "p5+", "multiple", "diffraction"};

// A path's ray order as OrderTally counts it (RayOrder of its events). Unlike OrderTally, which counts escapes
// only, any fate has an order.
int rayOrder(const PhotonPath& path);
// "unscattered", "p0" .. "p5+", "multiple": a rayOrder's name.
const char* orderName(int order);
// Whether `path` has the order of kOrderChoices[choice] (choice 0: any order).
bool hasOrderChoice(const PhotonPath& path, int choice);

// Whether `path` crossed plane detector `detector` (crossPlane on each segment between consecutive events, the
// escape's ray to infinity included) or ended on it (a Detect event), or, for a far-field camera, escaped in a
// direction it sees. Shape-absorption detectors see no path.
bool hitsDetector(const PhotonPath& path, const Detector& detector, std::size_t index);

// The indices into `paths` of those the filter keeps, in order; `detectors` are the traced scene's.
std::vector<int> filterPaths(const std::vector<PhotonPath>& paths, const std::vector<Detector>& detectors,
                             const PathFilter& filter);

}  // namespace dropscope::gui
