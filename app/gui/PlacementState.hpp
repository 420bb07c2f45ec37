#pragma once

#include "geometry/Shape.hpp"

namespace dropscope::gui {

// Where a click in placement mode drops a droplet when no surface is under the cursor: the plane
// normal to `axis` at `offset` along it (default: the horizontal plane through the scene's centre).
struct PlacementPlane {
    int axis = 1;  // 0 x, 1 y, 2 z
    double offset = 0.0;
};

// Placement mode (P, the Place panel): a click in the view drops a droplet of this radius and medium.
struct PlacementState {
    bool active = false;
    double radius = 0.25;
    MediumId medium = 0;
    // Also the plane a dragged droplet or source handle slides parallel to.
    PlacementPlane plane;
};

}  // namespace dropscope::gui
