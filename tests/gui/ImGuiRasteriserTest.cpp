// ImGui's panels drawn on the processor (gui/platform/ImGuiRasteriser): the picture ImGuiRenderer draws with OpenGL
// (llvmpipe) of the app's own draw data, every panel open, over the same background.
#include "AppHarness.hpp"
#include "UiTestScenes.hpp"

#include "gui/platform/ImGuiRasteriser.hpp"
#include "gui/platform/ImGuiRenderer.hpp"
#include "gui/platform/KeptPanels.hpp"
#include "render/LayoutComparison.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <random>

namespace dropscope::gui::testing {
namespace {

constexpr int kWidth = 1280;
constexpr int kHeight = 800;
// OpenGL's blending and filtering round in their own ways (llvmpipe blends bytes in fixed point, filters with
// 8-bit weights): a pixel may differ from the processor's by this much in a channel.
constexpr int kRoundingTolerance = 2;
// Pixels whose centres lie within rounding of a triangle's edge may go either way: at most this share differ by
// more (20 pixels of the 1,024,000; 3 do here).
constexpr double kEdgeShare = 2e-5;

class ImGuiRasteriser : public ::testing::Test {
protected:
    ImGuiRasteriser() {
        ImGuiIO& io = ImGui::GetIO();
        fontTexture_ = io.Fonts->TexID;
        unsigned char* pixels = nullptr;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &atlas_.width, &atlas_.height);
        atlas_.rgba = pixels;
    }

    // `data` (the last frame's panels unless given) drawn on the processor over `background` (RGBA8 in the
    // layout's byte order) with `threads` bands, into a picture of `layout` (OpenGL's own unless given).
    render::RasterImage drawnOnProcessor(std::uint32_t background, unsigned threads,
                                         const ImDrawData& data = *ImGui::GetDrawData(),
                                         render::PixelLayout layout = {}) const {
        render::RasterImage image;
        image.setLayout(layout);
        image.resize(kWidth, kHeight);
        for (int y = 0; y < kHeight; ++y) std::fill_n(image.colourRow(y), image.stride(), background);
        rasteriseImGui(data, atlas_, image, threads);
        return image;
    }
    // `data` drawn by ImGuiRenderer over the window cleared to `background`, read back.
    snapshot::Image drawnByOpenGL(const ImDrawData& data, std::uint32_t background) {
        const render::GlFunctions& gl = harness_.gl();
        const auto channel = [&](int k) { return static_cast<float>(background >> (8 * k) & 0xFFu) / 255.0f; };
        gl.ClearColor(channel(0), channel(1), channel(2), channel(3));
        gl.Clear(GL_COLOR_BUFFER_BIT);
        {
            ImGuiRenderer renderer(gl);  // the app's font texture stays: the draw data names it
            renderer.render(&data);
        }
        ImGui::GetIO().Fonts->SetTexID(fontTexture_);
        return harness_.image();
    }
    // A draw list of this test's own, for oneList; the font atlas bound, the whole window its clip rectangle.
    ImDrawList& freshList(bool antiAliased = true) {
        list_._ResetForNewFrame();
        if (!antiAliased) list_.Flags &= ~(ImDrawListFlags_AntiAliasedFill | ImDrawListFlags_AntiAliasedLines);
        list_.PushClipRectFullScreen();
        list_.PushTextureID(fontTexture_);
        return list_;
    }
    // freshList's draws as the frame's draw data, over the whole window.
    ImDrawData oneList() {
        lists_[0] = &list_;
        ImDrawData data;
        data.Valid = true;
        data.CmdLists = lists_;
        data.CmdListsCount = 1;
        data.TotalVtxCount = list_.VtxBuffer.Size;
        data.TotalIdxCount = list_.IdxBuffer.Size;
        data.DisplaySize = {kWidth, kHeight};
        data.FramebufferScale = {1.0f, 1.0f};
        return data;
    }

    AppHarness harness_{kCloudScene, kWidth, kHeight};
    ImTextureID fontTexture_ = nullptr;
    AtlasPixels atlas_;
    ImDrawList list_{ImGui::GetDrawListSharedData()};
    ImDrawList* lists_[1] = {nullptr};
};

// The pixels of the window (read from the top down) and of the processor's picture that differ by more than
// `tolerance` in some channel, and those of the picture other than `background`.
struct Comparison {
    int differing = 0;
    int drawn = 0;
};

Comparison compare(const snapshot::Image& window, const render::RasterImage& picture, std::uint32_t background,
                   int tolerance) {
    Comparison result;
    for (int row = 0; row < kHeight; ++row) {
        for (int x = 0; x < kWidth; ++x) {
            const std::uint8_t* expected = &window.rgba[4 * (static_cast<std::size_t>(row) * kWidth + x)];
            const std::uint32_t pixel = picture.colourAt(x, kHeight - 1 - row);
            bool differs = false;
            for (int k = 0; k < 4; ++k) {
                differs = differs || std::abs(static_cast<int>(pixel >> (8 * k) & 0xFFu) -
                                              static_cast<int>(expected[k])) > tolerance;
            }
            result.differing += differs ? 1 : 0;
            result.drawn += pixel != background ? 1 : 0;
        }
    }
    return result;
}

TEST_F(ImGuiRasteriser, DrawsThePanelsOpenGLDraws) {
    const ImDrawData& data = *ImGui::GetDrawData();
    ASSERT_TRUE(rasterisable(data, fontTexture_));
    ASSERT_GT(data.TotalVtxCount, 1000) << "every panel open";
    for (const std::uint32_t background : {0xFF1C1714u, 0x00000000u, 0xFFFFFFFFu}) {
        SCOPED_TRACE(background);
        const Comparison comparison =
            compare(drawnByOpenGL(data, background), drawnOnProcessor(background, 2), background, kRoundingTolerance);
        EXPECT_GT(comparison.drawn, kWidth * kHeight / 3) << "the panels cover a good part of the window";
        EXPECT_LE(comparison.differing, static_cast<int>(kEdgeShare * kWidth * kHeight))
            << comparison.differing << " of " << kWidth * kHeight << " pixels differ";
    }
}

TEST_F(ImGuiRasteriser, AnyNumberOfBandsDrawsTheSamePicture) {
    const render::RasterImage one = drawnOnProcessor(0xFF1C1714u, 1);
    for (const unsigned threads : {2u, 3u, 7u}) {
        EXPECT_EQ(drawnOnProcessor(0xFF1C1714u, threads).colour(), one.colour()) << threads << " bands";
    }
}

// The panels drawn into a picture of each layout a window may have (the top row or the bottom one first, RGBA or
// BGRA) are the same picture: only the rows' order and the bytes' order in memory differ. So are shapes and text
// in colours whose red and blue differ (the panels' text is grey, so its glyphs alone would not show bytes left
// unswapped): a blended rectangle, an anti-aliased triangle, a line of text (ImGui puts it at whole pixels, so its
// glyphs are copied texel for texel), the font atlas drawn larger than it is (sampled), and a red top row, so that
// rows in the wrong order show.
TEST_F(ImGuiRasteriser, EveryLayoutHoldsTheSamePicture) {
    constexpr std::uint32_t kBackground = 0xFF1C1714u;
    ImDrawList& list = freshList();
    list.AddRectFilled({10.0f, 10.0f}, {300.0f, 200.0f}, IM_COL32(230, 90, 20, 160));
    list.AddTriangleFilled({40.3f, 250.2f}, {300.7f, 260.1f}, {120.4f, 420.9f}, IM_COL32(20, 200, 240, 255));
    list.AddText({20.0f, 450.0f}, IM_COL32(250, 120, 10, 255), "Red and blue differ: 0123456789");
    // The atlas's top left 256 x 128 texels over 384 x 192 pixels: sampled between texels.
    list.AddImage(fontTexture_, {400.0f, 300.0f}, {784.0f, 492.0f}, {0.0f, 0.0f},
                  {256.0f / static_cast<float>(atlas_.width), 128.0f / static_cast<float>(atlas_.height)},
                  IM_COL32(10, 120, 250, 255));
    list.AddRectFilled({0.0f, 0.0f}, {kWidth, 1.0f}, IM_COL32(255, 0, 0, 255));  // the top row unlike the bottom
    const ImDrawData coloured = oneList();
    for (const ImDrawData* data : {static_cast<const ImDrawData*>(ImGui::GetDrawData()), &coloured}) {
        const render::RasterImage opengl = drawnOnProcessor(kBackground, 2, *data);
        int drawn = 0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) drawn += opengl.colourAt(x, y) != kBackground ? 1 : 0;
        }
        EXPECT_GT(drawn, 50000);
        if (data == &coloured) {
            EXPECT_NE(opengl.colourAt(0, 0), opengl.colourAt(0, kHeight - 1));
        }
        for (const render::PixelLayout layout : test::kEveryLayout) {
            SCOPED_TRACE((data == &coloured ? "shapes and text, " : "panels, ") + test::layoutName(layout));
            const render::RasterImage image =
                drawnOnProcessor(render::inByteOrder(kBackground, layout), 2, *data, layout);
            // Read from memory row by row: each layout's rows and bytes are OpenGL's layout's in its own order.
            EXPECT_EQ(test::differingInMemory(image, opengl, false), 0);
        }
    }
}

// The pixels of two frames of the window that differ by more than kRoundingTolerance in some channel.
int differingPixels(const snapshot::Image& a, const snapshot::Image& b) {
    int differing = 0;
    for (std::size_t pixel = 0; pixel + 3 < a.rgba.size(); pixel += 4) {
        bool differs = false;
        for (std::size_t k = 0; k < 4; ++k) {
            differs = differs || std::abs(static_cast<int>(a.rgba[pixel + k]) - static_cast<int>(b.rgba[pixel + k])) >
                                     kRoundingTolerance;
        }
        differing += differs ? 1 : 0;
    }
    return differing;
}

// The app over a software OpenGL draws its panels into the 3D view's picture on the processor: the window is the one
// OpenGL's panels make, when the view is drawn afresh (orbiting) and when its kept picture is copied.
TEST_F(ImGuiRasteriser, TheAppsWindowIsTheOneWithOpenGLsPanels) {
    const int most = static_cast<int>(kEdgeShare * kWidth * kHeight);
    for (const bool orbiting : {true, false}) {
        SCOPED_TRACE(orbiting ? "orbiting" : "the kept view copied");
        const auto frame = [&](bool panelsOnProcessor) {
            harness_.state().ui.panelsOnProcessor = panelsOnProcessor;
            if (orbiting) harness_.state().view.camera.orbit(0.01, 0.0);
            const std::uint64_t copied = harness_.app().viewport().copiedFrames();
            harness_.frames(orbiting ? 1 : 3);
            EXPECT_EQ(harness_.app().viewport().copiedFrames(), copied + (orbiting ? 0u : 3u));
            EXPECT_EQ(harness_.app().panelsLastOnProcessor(), panelsOnProcessor);
            return harness_.image();
        };
        const snapshot::Image byOpenGL = frame(false);
        if (orbiting) harness_.state().view.camera.orbit(-0.01, 0.0);  // the same view again
        const snapshot::Image onProcessor = frame(true);
        EXPECT_LE(differingPixels(onProcessor, byOpenGL), most);
    }
}

// A frame whose panels show an OpenGL texture (a plot, a detector's image) leaves them to OpenGL.
TEST_F(ImGuiRasteriser, PanelsShowingAnotherTextureAreLeftToOpenGL) {
    ImDrawList& list = freshList();
    list.AddRectFilled({10.0f, 10.0f}, {50.0f, 30.0f}, IM_COL32(200, 100, 50, 255));
    ImDrawData data = oneList();
    EXPECT_TRUE(rasterisable(data, fontTexture_));
    const auto otherTexture = reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(12345));
    list.AddImage(otherTexture, {60.0f, 10.0f}, {90.0f, 40.0f});
    EXPECT_FALSE(rasterisable(data, fontTexture_));
}

// Shapes whose edges run through pixel centres, level, upright and sloped, without ImGui's anti-aliased fringes: a
// centre on an edge goes to the same side as in llvmpipe's window framebuffer, pixel for pixel.
TEST_F(ImGuiRasteriser, AnEdgeThroughPixelCentresGoesWhereOpenGLPutsIt) {
    ImDrawList& list = freshList(false);
    list.AddRectFilled({10.5f, 10.5f}, {20.5f, 20.5f}, IM_COL32(255, 0, 0, 255));
    list.AddTriangleFilled({40.5f, 10.5f}, {60.5f, 10.5f}, {50.5f, 30.5f}, IM_COL32(0, 255, 0, 255));
    list.AddTriangleFilled({70.5f, 30.5f}, {90.5f, 30.5f}, {80.5f, 10.5f}, IM_COL32(0, 0, 255, 255));
    list.AddTriangleFilled({100.5f, 10.5f}, {120.5f, 20.5f}, {100.5f, 30.5f}, IM_COL32(255, 255, 0, 255));
    list.AddRectFilled({130.0f, 10.5f}, {140.0f, 20.0f}, IM_COL32(0, 255, 255, 255));  // edges between centres too
    const ImDrawData data = oneList();
    constexpr std::uint32_t kBlack = 0xFF000000u;
    const Comparison comparison = compare(drawnByOpenGL(data, kBlack), drawnOnProcessor(kBlack, 1, data), kBlack, 0);
    EXPECT_GT(comparison.drawn, 700) << "the five shapes, about 800 pixels";
    EXPECT_EQ(comparison.differing, 0);
}

// The panels kept while they stay (KeptPanels): the lists equal to the last frame's drawn once into a layer, blended
// over each new view.
class KeptPanelsTest : public ImGuiRasteriser {
protected:
    // A 3D view that changes from frame to frame: pixels of any colour and alpha, drawn from `seed`.
    static render::RasterImage view(unsigned seed, render::PixelLayout layout = {}, int width = kWidth,
                                    int height = kHeight) {
        render::RasterImage image;
        image.setLayout(layout);
        image.resize(width, height);
        std::mt19937 random(seed);
        for (int y = 0; y < height; ++y) {
            std::uint32_t* row = image.colourRow(y);
            for (int x = 0; x < image.stride(); ++x) row[x] = static_cast<std::uint32_t>(random());
        }
        return image;
    }
    // `data` drawn by `kept` over view(seed), and directly over the same view.
    struct Both {
        render::RasterImage kept;
        render::RasterImage direct;
    };
    Both drawnBoth(KeptPanels& kept, const ImDrawData& data, unsigned seed, render::PixelLayout layout = {},
                   int width = kWidth, int height = kHeight) const {
        Both both{view(seed, layout, width, height), view(seed, layout, width, height)};
        kept.drawOver(data, atlas_, both.kept, 2);
        rasteriseImGui(data, atlas_, both.direct, 2);
        return both;
    }
    // Lists of this test's own, each over the whole window, the font atlas bound.
    ImDrawList& ownList(std::size_t n) {
        ImDrawList& list = *own_[n];
        list._ResetForNewFrame();
        list.PushClipRectFullScreen();
        list.PushTextureID(fontTexture_);
        return list;
    }
    ImDrawData ownLists(int count) {
        ImDrawData data;
        data.Valid = true;
        for (int n = 0; n < count; ++n) ownPointers_[n] = own_[static_cast<std::size_t>(n)].get();
        data.CmdLists = ownPointers_;
        data.CmdListsCount = count;
        data.DisplaySize = {kWidth, kHeight};
        data.FramebufferScale = {1.0f, 1.0f};
        return data;
    }

    std::array<std::unique_ptr<ImDrawList>, 3> own_{std::make_unique<ImDrawList>(ImGui::GetDrawListSharedData()),
                                                    std::make_unique<ImDrawList>(ImGui::GetDrawListSharedData()),
                                                    std::make_unique<ImDrawList>(ImGui::GetDrawListSharedData())};
    ImDrawList* ownPointers_[3] = {nullptr, nullptr, nullptr};
};

// Where several of the panels' blends meet the view, the layer combines them before the view's pixel is known, which
// may round a channel another way: at most this share of the pixels differ from the panels drawn directly, by 1 (about
// 60,000 of the 1,024,000 over a view of random pixels, 6-8 of them by 2).
constexpr double kCombinedShare = 0.1;

// The pixels of two pictures that differ at all, by more than 1, and by more than kRoundingTolerance, in some channel.
struct Differences {
    int any = 0;
    int beyondOne = 0;
    int beyondRounding = 0;
};

Differences differences(const render::RasterImage& a, const render::RasterImage& b) {
    Differences result;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            int most = 0;
            for (int k = 0; k < 4; ++k) {
                most = std::max(most, std::abs(static_cast<int>(a.colourAt(x, y) >> (8 * k) & 0xFFu) -
                                               static_cast<int>(b.colourAt(x, y) >> (8 * k) & 0xFFu)));
            }
            result.any += most > 0 ? 1 : 0;
            result.beyondOne += most > 1 ? 1 : 0;
            result.beyondRounding += most > kRoundingTolerance ? 1 : 0;
        }
    }
    return result;
}

// A layer's pixel (colour times coverage in each channel, coverage in alpha) over a pixel: each channel the layer's
// plus the pixel's times one minus the coverage, rounded to nearest, computed here in integers of its own.
TEST(BlendCovered, IsTheLayerPlusWhatItsCoverageLeavesOfEachPixel) {
    std::mt19937 random(7);
    for (const int count : {1, 3, 4, 5, 8, 11, 333}) {
        std::vector<std::uint32_t> layer(static_cast<std::size_t>(count));
        std::vector<std::uint32_t> pixels(layer.size());
        for (std::size_t x = 0; x < layer.size(); ++x) {
            const auto coverage = static_cast<std::uint32_t>(random() % 256u);
            std::uint32_t value = coverage << 24;
            for (int k = 0; k < 3; ++k) {
                value |= static_cast<std::uint32_t>(random() % (coverage + 1u)) << (8 * k);  // at most the coverage
            }
            layer[x] = value;
            pixels[x] = static_cast<std::uint32_t>(random());
        }
        std::vector<std::uint32_t> blended = pixels;
        blendCovered(layer.data(), blended.data(), count);
        for (std::size_t x = 0; x < layer.size(); ++x) {
            const std::uint32_t rest = 255u - (layer[x] >> 24);
            for (int k = 0; k < 4; ++k) {
                const std::uint32_t under = pixels[x] >> (8 * k) & 0xFFu;
                const std::uint32_t expected = (layer[x] >> (8 * k) & 0xFFu) + (2u * under * rest + 255u) / 510u;
                ASSERT_EQ(blended[x] >> (8 * k) & 0xFFu, expected)
                    << "pixel " << x << " of " << count << ", byte " << k;
            }
        }
    }
}

// The app's panels, every one open, over views that change from frame to frame: the first frame draws them, the
// second draws the layer, the later ones blend it; each picture is the panels drawn directly over that view.
TEST_F(KeptPanelsTest, TheAppsPanelsFromTheLayerAreThePanelsDrawnOverEachView) {
    const ImDrawData& data = *ImGui::GetDrawData();
    ASSERT_GT(data.TotalVtxCount, 1000) << "every panel open";
    for (const render::PixelLayout layout : test::kEveryLayout) {
        SCOPED_TRACE(test::layoutName(layout));
        KeptPanels kept;
        for (unsigned frame = 0; frame < 4; ++frame) {
            SCOPED_TRACE(frame);
            const Both both = drawnBoth(kept, data, frame, layout);
            EXPECT_EQ(kept.lastDrawn(), frame == 0   ? KeptPanels::Drawn::directly
                                        : frame == 1 ? KeptPanels::Drawn::layerDrawn
                                                     : KeptPanels::Drawn::fromLayer);
            const Differences differing = differences(both.kept, both.direct);
            EXPECT_EQ(differing.beyondRounding, 0);
            EXPECT_LE(differing.beyondOne, static_cast<int>(kEdgeShare * kWidth * kHeight));
            EXPECT_LE(differing.any, static_cast<int>(kCombinedShare * kWidth * kHeight))
                << differing.any << " pixels differ";
            if (frame == 0) {
                EXPECT_EQ(differing.any, 0);
            }
        }
    }
}

TEST_F(KeptPanelsTest, AListThatChangedIsDrawnAsItIsNow) {
    ImDrawList& panel = ownList(0);
    panel.AddRectFilled({100.0f, 100.0f}, {500.0f, 500.0f}, IM_COL32(40, 60, 80, 240));
    panel.AddText({120.0f, 120.0f}, IM_COL32(230, 230, 230, 255), "A panel's text");
    const ImDrawData data = ownLists(1);
    KeptPanels kept;
    drawnBoth(kept, data, 1);
    drawnBoth(kept, data, 2);
    ASSERT_EQ(kept.lastDrawn(), KeptPanels::Drawn::layerDrawn);
    // The same list, another colour: not the layer's.
    ImDrawList& changed = ownList(0);
    changed.AddRectFilled({100.0f, 100.0f}, {500.0f, 500.0f}, IM_COL32(200, 30, 20, 240));
    changed.AddText({120.0f, 120.0f}, IM_COL32(230, 230, 230, 255), "A panel's text");
    for (unsigned frame = 3; frame < 6; ++frame) {
        const Both both = drawnBoth(kept, data, frame);
        EXPECT_EQ(differences(both.kept, both.direct).beyondRounding, 0) << "frame " << frame;
        const std::uint32_t inside = both.kept.colourAt(300, kHeight - 1 - 300);
        EXPECT_GT(inside & 0xFFu, 150u) << "the new red, frame " << frame;
    }
}

// A list that changed under one kept in the layer is not drawn over it, nor is the layer of another picture size or
// layout used.
TEST_F(KeptPanelsTest, TheLayerIsNotUsedWhereItWouldPutAListOverOneLaterOrFitAnotherPicture) {
    const auto lists = [&](ImU32 underColour) {
        ownList(0).AddRectFilled({100.0f, 100.0f}, {500.0f, 500.0f}, underColour);
        ownList(1).AddRectFilled({300.0f, 300.0f}, {700.0f, 700.0f}, IM_COL32(20, 200, 40, 180));  // over list 0
        return ownLists(2);
    };
    ImDrawData data = lists(IM_COL32(40, 60, 80, 255));
    KeptPanels kept;
    drawnBoth(kept, data, 1);
    drawnBoth(kept, data, 2);
    ASSERT_EQ(kept.lastDrawn(), KeptPanels::Drawn::layerDrawn);
    data = lists(IM_COL32(200, 30, 20, 255));
    const Both both = drawnBoth(kept, data, 3);
    EXPECT_EQ(kept.lastDrawn(), KeptPanels::Drawn::directly);
    EXPECT_EQ(differences(both.kept, both.direct).any, 0);
    const std::uint32_t overlap = both.kept.colourAt(400, kHeight - 1 - 400);
    EXPECT_GT(overlap >> 8 & 0xFFu, overlap & 0xFFu) << "list 1's green over list 0's red";

    drawnBoth(kept, data, 4);
    ASSERT_EQ(kept.lastDrawn(), KeptPanels::Drawn::layerDrawn);
    for (const render::PixelLayout layout : test::kEveryLayout) {
        if (layout == render::PixelLayout{}) continue;  // the layer's
        const Both other = drawnBoth(kept, data, 5, layout);
        EXPECT_NE(kept.lastDrawn(), KeptPanels::Drawn::fromLayer) << test::layoutName(layout);
        EXPECT_EQ(differences(other.kept, other.direct).beyondRounding, 0) << test::layoutName(layout);
    }
    drawnBoth(kept, data, 6);
    drawnBoth(kept, data, 7);
    ASSERT_EQ(kept.lastDrawn(), KeptPanels::Drawn::layerDrawn);
    const Both smaller = drawnBoth(kept, data, 8, {}, kWidth - 200, kHeight - 100);
    EXPECT_NE(kept.lastDrawn(), KeptPanels::Drawn::fromLayer) << "a picture of another size";
    EXPECT_EQ(differences(smaller.kept, smaller.direct).beyondRounding, 0);
}

// A list drawn over the layer (it changed) that has moved under a later list kept in the layer: the layer, though
// every list in it stayed, is not used, since the moved list would come out over the later one.
TEST_F(KeptPanelsTest, AListMovedUnderALaterOneInTheLayerIsNotDrawnOverIt) {
    const auto lists = [&](float smallX) {
        ownList(0).AddRectFilled({smallX, 300.0f}, {smallX + 60.0f, 330.0f}, IM_COL32(230, 20, 20, 255));
        ownList(1).AddRectFilled({100.0f, 100.0f}, {500.0f, 500.0f}, IM_COL32(20, 200, 40, 180));
        return ownLists(2);
    };
    KeptPanels kept;
    drawnBoth(kept, lists(700.0f), 1);
    drawnBoth(kept, lists(700.0f), 2);
    ASSERT_EQ(kept.lastDrawn(), KeptPanels::Drawn::layerDrawn) << "the large list kept, the small one drawn over it";
    const Both both = drawnBoth(kept, lists(300.0f), 3);
    EXPECT_EQ(kept.lastDrawn(), KeptPanels::Drawn::directly);
    EXPECT_EQ(differences(both.kept, both.direct).any, 0);
    const std::uint32_t under = both.kept.colourAt(320, kHeight - 1 - 315);
    EXPECT_GT(under >> 8 & 0xFFu, under & 0xFFu) << "list 1's green over list 0's red";
}

// A small list that changes every frame over kept ones (a tooltip) is drawn over the layer, which stays.
TEST_F(KeptPanelsTest, ASmallListChangingEveryFrameOverTheLayerLeavesItKept) {
    ownList(0).AddRectFilled({100.0f, 100.0f}, {500.0f, 500.0f}, IM_COL32(40, 60, 80, 240));
    KeptPanels kept;
    for (unsigned frame = 0; frame < 6; ++frame) {
        ImDrawList& tooltip = ownList(1);
        const float x = 200.0f + 10.0f * static_cast<float>(frame);
        tooltip.AddRectFilled({x, 200.0f}, {x + 80.0f, 230.0f}, IM_COL32(10, 10, 10, 230));
        tooltip.AddText({x + 4.0f, 204.0f}, IM_COL32(250, 250, 250, 255), "droplet 12");
        const Both both = drawnBoth(kept, ownLists(2), frame);
        if (frame >= 2) {
            EXPECT_EQ(kept.lastDrawn(), KeptPanels::Drawn::fromLayer) << "frame " << frame;
        }
        EXPECT_EQ(differences(both.kept, both.direct).beyondRounding, 0) << "frame " << frame;
    }
}

}  // namespace
}  // namespace dropscope::gui::testing
