#include "gui/platform/KeptPanels.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace dropscope::gui {

namespace {

// What a list draws, part by part, as `visit(bytes, size)`: its vertices, its indices and each command's clip
// rectangle, texture and ranges (rasterisable: no callbacks).
template <typename Visit>
void eachPart(const ImDrawList& list, Visit&& visit) {
    visit(&list.VtxBuffer.Size, sizeof list.VtxBuffer.Size);  // the counts first: the parts' bytes alone could be
    visit(&list.IdxBuffer.Size, sizeof list.IdxBuffer.Size);  // cut into vertices and indices more than one way
    visit(&list.CmdBuffer.Size, sizeof list.CmdBuffer.Size);
    visit(list.VtxBuffer.Data, static_cast<std::size_t>(list.VtxBuffer.size_in_bytes()));
    visit(list.IdxBuffer.Data, static_cast<std::size_t>(list.IdxBuffer.size_in_bytes()));
    for (const ImDrawCmd& command : list.CmdBuffer) {
        visit(&command.ClipRect, sizeof command.ClipRect);
        visit(&command.TextureId, sizeof command.TextureId);
        visit(&command.VtxOffset, sizeof command.VtxOffset);
        visit(&command.IdxOffset, sizeof command.IdxOffset);
        visit(&command.ElemCount, sizeof command.ElemCount);
    }
}

void record(const ImDrawList& list, std::vector<std::byte>& bytes) {
    bytes.clear();
    eachPart(list, [&](const void* part, std::size_t size) {
        const auto* first = static_cast<const std::byte*>(part);
        bytes.insert(bytes.end(), first, first + size);
    });
}

bool matches(const ImDrawList& list, const std::vector<std::byte>& bytes) {
    std::size_t at = 0;
    bool same = true;
    eachPart(list, [&](const void* part, std::size_t size) {
        same = same && at + size <= bytes.size() && (size == 0 || std::memcmp(bytes.data() + at, part, size) == 0);
        at += size;
    });
    return same && at == bytes.size();
}

// A rectangle of the display's coordinates.
struct Box {
    float left = 0, top = 0, right = 0, bottom = 0;
    bool meets(const Box& other) const {
        return left < other.right && other.left < right && top < other.bottom && other.top < bottom;
    }
};

// The pixels a list can draw: within its vertices' bounding box (a window's first commands clip to the whole
// display), a pixel to spare each side. A list without vertices meets nothing; one with a NaN position, everything.
Box listBox(const ImDrawList& list) {
    constexpr float kFar = std::numeric_limits<float>::infinity();
    Box box{kFar, kFar, -kFar, -kFar};
    for (const ImDrawVert& vertex : list.VtxBuffer) {
        if (std::isnan(vertex.pos.x) || std::isnan(vertex.pos.y)) return {-kFar, -kFar, kFar, kFar};
        box.left = std::min(box.left, vertex.pos.x);
        box.top = std::min(box.top, vertex.pos.y);
        box.right = std::max(box.right, vertex.pos.x);
        box.bottom = std::max(box.bottom, vertex.pos.y);
    }
    return {box.left - 1.0f, box.top - 1.0f, box.right + 1.0f, box.bottom + 1.0f};
}

// `data` with only the lists `chosen` says.
struct ChosenLists {
    ChosenLists(const ImDrawData& all, const std::vector<bool>& chosen) : data(all) {
        for (int n = 0; n < all.CmdListsCount; ++n) {
            if (!chosen[static_cast<std::size_t>(n)]) continue;
            lists.push_back(all.CmdLists[n]);
        }
        data.CmdLists = lists.data();
        data.CmdListsCount = static_cast<int>(lists.size());
        data.TotalVtxCount = data.TotalIdxCount = 0;
        for (const ImDrawList* list : lists) {
            data.TotalVtxCount += list->VtxBuffer.Size;
            data.TotalIdxCount += list->IdxBuffer.Size;
        }
    }
    std::vector<ImDrawList*> lists;
    ImDrawData data;
};

// Gaps shorter than this between a row's covered pixels are blended too (they leave the pixels as they are), so a
// row of a panel is one span.
constexpr int kSpanGap = 16;
// Only lists whose boxes cover at least this share of the picture go into the layer: a panel (a tenth of the
// picture or more), not a tooltip or the menu and status bars (2-3 %), which may change from frame to frame and are
// cheap to draw over the layer, where one that changed in the layer would have it drawn anew.
constexpr double kKeptShare = 1.0 / 32.0;

}  // namespace

void KeptPanels::drawOver(const ImDrawData& data, const AtlasPixels& atlas, render::RasterImage& image,
                          unsigned threads) {
    const Frame frame{image.width(),           image.height(),     image.layout(),     data.DisplayPos.x,
                      data.DisplayPos.y,       data.DisplaySize.x, data.DisplaySize.y, data.FramebufferScale.x,
                      data.FramebufferScale.y, atlas.rgba,         atlas.width,        atlas.height};
    const auto count = static_cast<std::size_t>(std::max(data.CmdListsCount, 0));
    if (!(frame == frame_)) {
        layerReady_ = false;
        lastLists_.clear();
    }
    std::vector<Box> boxes(count);
    std::vector<bool> stable(count);
    for (std::size_t n = 0; n < count; ++n) {
        boxes[n] = listBox(*data.CmdLists[n]);
        stable[n] = n < lastLists_.size() && matches(*data.CmdLists[n], lastLists_[n]);
    }
    // The lists in `inLayer` blended first and the others drawn over them give each pixel's blends in the lists'
    // order when no list drawn over the layer lies under a later one in it.
    const auto orderKept = [&](const std::vector<bool>& inLayer) {
        for (std::size_t drawnOver = 0; drawnOver < count; ++drawnOver) {
            if (inLayer[drawnOver]) continue;
            for (std::size_t later = drawnOver + 1; later < count; ++later) {
                if (inLayer[later] && boxes[drawnOver].meets(boxes[later])) return false;
            }
        }
        return true;
    };
    std::vector<bool> inLayer(count);
    bool usable = layerReady_ && layerLists_.size() <= count;
    for (std::size_t n = 0; usable && n < layerLists_.size(); ++n) {
        inLayer[n] = layerHas_[n];
        usable = !layerHas_[n] || matches(*data.CmdLists[n], layerLists_[n]);
    }
    usable = usable && orderKept(inLayer);
    // The lists worth keeping: those that stayed and cover enough of the picture to be worth a layer drawn anew, and
    // those that stayed under them.
    const double area = static_cast<double>(frame.displayWidth) * static_cast<double>(frame.displayHeight);
    std::vector<bool> wanted(count);
    for (std::size_t n = count; n-- > 0;) {
        const double covered = static_cast<double>(std::max(boxes[n].right - boxes[n].left, 0.0f)) *
                               static_cast<double>(std::max(boxes[n].bottom - boxes[n].top, 0.0f));
        bool under = false;
        for (std::size_t later = n + 1; later < count && !under; ++later) {
            under = wanted[later] && boxes[n].meets(boxes[later]);
        }
        wanted[n] = stable[n] && (covered >= kKeptShare * area || under);
    }
    bool anyWanted = false;
    bool wantedOutside = false;
    for (std::size_t n = 0; n < count; ++n) {
        anyWanted = anyWanted || wanted[n];
        wantedOutside = wantedOutside || (wanted[n] && !inLayer[n]);
    }
    lastDrawn_ = usable ? Drawn::fromLayer : Drawn::directly;
    if ((!usable || wantedOutside) && anyWanted && orderKept(wanted)) {
        drawLayer(data, atlas, wanted, image, threads);
        inLayer = wanted;
        usable = true;
        lastDrawn_ = Drawn::layerDrawn;
    }
    if (usable) {
        std::vector<bool> onTop(count);
        for (std::size_t n = 0; n < count; ++n) onTop[n] = !inLayer[n];
        render::drawInBands(image.height(), threads, [&](int rowBegin, int rowEnd) {
            auto span =
                std::lower_bound(spans_.begin(), spans_.end(), rowBegin, [](const Span& s, int y) { return s.y < y; });
            for (; span != spans_.end() && span->y < rowEnd; ++span) {
                blendCovered(layer_.colourRow(span->y) + span->begin, image.colourRow(span->y) + span->begin,
                             span->end - span->begin);
            }
        });
        const ChosenLists others(data, onTop);
        if (others.data.CmdListsCount > 0) rasteriseImGui(others.data, atlas, image, threads);
    } else {
        layerReady_ = false;
        rasteriseImGui(data, atlas, image, threads);
    }
    lastLists_.resize(count);
    for (std::size_t n = 0; n < count; ++n) {
        if (!stable[n]) record(*data.CmdLists[n], lastLists_[n]);
    }
    frame_ = frame;
}

void KeptPanels::drawLayer(const ImDrawData& data, const AtlasPixels& atlas, const std::vector<bool>& kept,
                           const render::RasterImage& image, unsigned threads) {
    layer_.setLayout(image.layout());
    layer_.resize(image.width(), image.height());
    std::fill_n(layer_.colourData(), static_cast<std::size_t>(layer_.stride()) * layer_.height(), 0u);
    rasteriseImGui(ChosenLists(data, kept).data, atlas, layer_, threads);
    spans_.clear();
    for (int y = 0; y < layer_.height(); ++y) {
        const std::uint32_t* row = layer_.colourRow(y);
        for (int x = 0; x < layer_.width();) {
            if (row[x] == 0) {
                ++x;
                continue;
            }
            int end = x + 1;
            for (int gap = 0; end + gap < layer_.width() && gap < kSpanGap;) {
                if (row[end + gap] != 0) {
                    end += gap + 1;
                    gap = 0;
                } else {
                    ++gap;
                }
            }
            spans_.push_back({y, x, end});
            x = end;
        }
    }
    layerLists_.resize(kept.size());
    layerHas_ = kept;
    for (std::size_t n = 0; n < kept.size(); ++n) {
        if (kept[n]) record(*data.CmdLists[n], layerLists_[n]);
    }
    layerReady_ = true;
}

}  // namespace dropscope::gui
