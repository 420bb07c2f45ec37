#pragma once

#include <imgui.h>

#include <algorithm>

namespace dropscope::gui {

// The scissor box ImGuiRenderer gives OpenGL for an ImGui command's clip rectangle, in framebuffer pixels with rows
// counted from the bottom: the clip rectangle cut to the framebuffer, and the integer parts of its lower-left corner,
// width and height. ImGuiRasteriser cuts the same box.
struct ScissorBox {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
    bool empty() const { return width <= 0 || height <= 0; }
};

inline ScissorBox scissorBox(const ImDrawData& data, const ImVec4& clip, int framebufferWidth, int framebufferHeight) {
    const ImVec2 origin = data.DisplayPos;
    const ImVec2 scale = data.FramebufferScale;
    const float minX = std::max((clip.x - origin.x) * scale.x, 0.0f);
    const float minY = std::max((clip.y - origin.y) * scale.y, 0.0f);
    const float maxX = std::min((clip.z - origin.x) * scale.x, static_cast<float>(framebufferWidth));
    const float maxY = std::min((clip.w - origin.y) * scale.y, static_cast<float>(framebufferHeight));
    if (!(maxX > minX) || !(maxY > minY)) return {};  // empty, or not a number
    return {static_cast<int>(minX), static_cast<int>(static_cast<float>(framebufferHeight) - maxY),
            static_cast<int>(maxX - minX), static_cast<int>(maxY - minY)};
}

}  // namespace dropscope::gui
