#pragma once

#include "gui/platform/ImGuiRasteriser.hpp"

#include <imgui.h>

#include <cstddef>
#include <vector>

namespace dropscope::gui {

// ImGui's panels drawn over the 3D view's picture on the processor as rasteriseImGui draws them, with what stays
// from frame to frame drawn once: the draw lists equal to the last frame's are drawn into a kept layer over
// transparent black (each pixel their colour times their coverage, and the coverage), which later frames blend over
// the view in one pass while those lists stay; the lists that changed are drawn over it as before, when no kept list
// lies over them. A pixel one blend makes comes out as drawn directly; where several blend over the view, they are
// combined first, which may round a channel 1 or 2 another way. docs/gui.md, "The panels kept while they stay".
class KeptPanels {
public:
    // How the last drawOver drew the panels.
    enum class Drawn {
        directly,    // every list by rasteriseImGui
        layerDrawn,  // the lists equal to the last frame's drawn into the layer, then as fromLayer
        fromLayer,   // the kept layer blended, the other lists drawn over it
    };

    // `data` drawn over `image` (see rasteriseImGui).
    void drawOver(const ImDrawData& data, const AtlasPixels& atlas, render::RasterImage& image, unsigned threads);
    Drawn lastDrawn() const { return lastDrawn_; }

private:
    // What a list draws, as bytes compared from frame to frame: its vertices, indices and commands.
    using ListBytes = std::vector<std::byte>;
    // What every list's pixels depend on besides its own bytes: the picture's size and layout, the display, the atlas.
    struct Frame {
        int width = 0, height = 0;
        render::PixelLayout layout;
        float displayX = 0, displayY = 0, displayWidth = 0, displayHeight = 0, scaleX = 0, scaleY = 0;
        const unsigned char* atlas = nullptr;
        int atlasWidth = 0, atlasHeight = 0;
        bool operator==(const Frame&) const = default;
    };
    struct Span {  // a run of a row's pixels the layer covers
        int y, begin, end;
    };

    // The lists `kept` says drawn into the layer, over transparent black, and the spans it covers found.
    void drawLayer(const ImDrawData& data, const AtlasPixels& atlas, const std::vector<bool>& kept,
                   const render::RasterImage& image, unsigned threads);

    Frame frame_;
    std::vector<ListBytes> lastLists_;   // the last frame's lists
    std::vector<ListBytes> layerLists_;  // the lists in the layer, by their index then
    std::vector<bool> layerHas_;         // which of those indices the layer holds
    bool layerReady_ = false;
    render::RasterImage layer_;
    std::vector<Span> spans_;
    Drawn lastDrawn_ = Drawn::directly;
};

}  // namespace dropscope::gui
