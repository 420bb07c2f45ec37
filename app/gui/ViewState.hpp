#pragma once

#include "render/Camera.hpp"
#include "render/SceneLayers.hpp"

namespace dropscope::gui {

// The slice plane: everything on the far side of the plane normal to `axis` at `offset` is hidden
// (render::SlicePlane); `flip` keeps the other side.
struct SliceSettings {
    bool enabled = false;
    int axis = 2;
    double offset = 0.0;
    bool flip = false;

    bool operator==(const SliceSettings&) const = default;
};

// How the 3D view looks at the scene and what it draws: the camera (moved by ViewportControls, fitted
// by ViewportScene), the layer switches (menus, panels, shortcuts) and the slice plane.
struct ViewState {
    render::Camera camera;
    bool fitRequested = true;  // fit the camera to the scene in the next frame
    render::LayerOptions layers = interactiveLayers();
    SliceSettings slice;

    // Small droplets as points (render::kInteractivePointPixels): a frame a user orbits in, not a snapshot.
    static render::LayerOptions interactiveLayers() {
        render::LayerOptions layers;
        layers.render.pointPixels = render::kInteractivePointPixels;
        return layers;
    }
};

}  // namespace dropscope::gui
