// The plot window on its own, in an ImGui context without GL (ImGui frames without drawing): two stacked
// sub-plots over one x axis, the readout, zoom by wheel, drag and double-click, and drawing data a log
// axis cannot show.
#include "gui/PlotWindow.hpp"
#include "gui/platform/ImGuiInput.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace dropscope::gui {
namespace {

using plot::AxisRange;
using plot::Scale;

// x computed from a mouse pixel by the window and here: a few double roundings of values up to 100.
constexpr double kPixelRounding = 1e-12;

// 101 samples on [0, 100]: a decaying intensity with a zero and a negative value (top, log) and a
// ratio in [-1, 1] (bottom, fixed axis).
plot::Figure twoSubPlots() {
    plot::Curve intensity{"intensity"};
    plot::Curve background{"background"};
    plot::Curve ratio{"ratio"};
    for (int i = 0; i <= 100; ++i) {
        const double x = i;
        intensity.x.push_back(x);
        intensity.y.push_back(i == 30 ? 0.0 : i == 31 ? -1.0 : std::exp(-x / 10.0));
        background.x.push_back(x);
        background.y.push_back(1e-3);
        ratio.x.push_back(x);
        ratio.y.push_back(std::cos(x / 10.0));
    }
    plot::SubPlot top{"I", {intensity, background}, Scale::Log};
    plot::SubPlot bottom{"P", {ratio}, Scale::Linear, AxisRange{-1.0, 1.0}};
    return {"Test plot", "x (mm)", AxisRange{0.0, 100.0}, {top, bottom}};
}

class PlotWindowTest : public ::testing::Test {
protected:
    PlotWindowTest() {
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        configureImGuiIo(io);
        io.Fonts->Build();
        state_.open = true;
        input_.mouseInside = true;
        frames(2);  // the window appears on the first frame, laid out, and is shown on the second
    }
    ~PlotWindowTest() override { ImGui::DestroyContext(context_); }

    void frame() {
        rects_.clear();
        applyInput(ImGui::GetIO(), input_);
        ImGui::NewFrame();
        drawPlotWindow(figure_, state_, status_,
                       [&](std::string_view name, const ItemRect& rect) { rects_[std::string(name)] = rect; });
        ImGui::Render();
        input_.wheelY = 0.0f;
    }
    void frames(int count) {
        for (int k = 0; k < count; ++k) frame();
    }
    void moveTo(float x, float y) {
        input_.mouseX = x;
        input_.mouseY = y;
        frame();
    }
    void setButton(bool down) {
        input_.mouseDown[0] = down;
        frame();
    }
    ItemRect frameRect(int index) {
        const auto found = rects_.find("Test plot frame " + std::to_string(index));
        EXPECT_NE(found, rects_.end()) << "sub-plot " << index << " not drawn";
        return found == rects_.end() ? ItemRect{} : found->second;
    }
    // The pixel of x over a frame (its x axis spans the figure's 0..100 unless zoomed), and the x at a
    // pixel as the window computes it. ImGui floors the mouse position: the mouse at pixelOf(x) reads
    // xAt(floor(pixelOf(x))), up to one pixel (0.2 in x) below x.
    static float pixelOf(const ItemRect& rect, double x, AxisRange view = {0.0, 100.0}) {
        return rect.minX + static_cast<float>((x - view.lo) / view.span()) * (rect.maxX - rect.minX);
    }
    static double xAt(const ItemRect& rect, float pixel, AxisRange view = {0.0, 100.0}) {
        return view.lo + (std::floor(static_cast<double>(pixel)) - rect.minX) / (rect.maxX - rect.minX) * view.span();
    }
    static float middleY(const ItemRect& rect) { return 0.5f * (rect.minY + rect.maxY); }

    ImGuiContext* context_ = ImGui::CreateContext();
    plot::Figure figure_ = twoSubPlots();
    plot::PlotWindowState state_;
    StatusLine status_;
    InputFrame input_;
    std::map<std::string, ItemRect> rects_;
};

TEST_F(PlotWindowTest, SubPlotsAreStackedOverOneXAxisEachWithItsOwnScale) {
    const ItemRect top = frameRect(0);
    const ItemRect bottom = frameRect(1);
    EXPECT_GT(bottom.minY, top.maxY);
    EXPECT_EQ(top.minX, bottom.minX) << "the frames line up";
    EXPECT_EQ(top.maxX, bottom.maxX);
    EXPECT_GT(top.maxY - top.minY, 60.0f);
    EXPECT_EQ(state_.scales, (std::vector<Scale>{Scale::Log, Scale::Linear}));
}

TEST_F(PlotWindowTest, TheReadoutGivesEachCurvesNearestSampleOfTheSubPlotUnderTheMouse) {
    const ItemRect top = frameRect(0);
    moveTo(pixelOf(top, 40.3), middleY(top));
    ASSERT_TRUE(state_.hovered);
    EXPECT_EQ(state_.hovered->subPlot, 0u);
    EXPECT_NEAR(state_.hovered->cursorX, xAt(top, pixelOf(top, 40.3)), kPixelRounding);
    ASSERT_EQ(state_.hovered->samples.size(), 2u);
    EXPECT_EQ(state_.hovered->samples[0].x, 40.0);
    EXPECT_EQ(state_.hovered->samples[0].y, std::exp(-4.0));
    EXPECT_EQ(state_.hovered->samples[1].y, 1e-3);

    const ItemRect bottom = frameRect(1);
    moveTo(pixelOf(bottom, 71.8), middleY(bottom));
    ASSERT_TRUE(state_.hovered);
    EXPECT_EQ(state_.hovered->subPlot, 1u);
    ASSERT_EQ(state_.hovered->samples.size(), 1u);
    EXPECT_EQ(state_.hovered->samples[0].curve, 0u);
    EXPECT_EQ(state_.hovered->samples[0].x, 72.0);
    EXPECT_EQ(state_.hovered->samples[0].y, std::cos(7.2));

    moveTo(5.0f, 5.0f);  // off the window
    EXPECT_FALSE(state_.hovered);
}

TEST_F(PlotWindowTest, TheWheelZoomsAboutTheMouseAndADoubleClickShowsTheWholeAxis) {
    const ItemRect top = frameRect(0);
    moveTo(pixelOf(top, 25.0), middleY(top));
    input_.wheelY = 1.0f;
    frame();
    ASSERT_TRUE(state_.xView);
    const double anchor = xAt(top, pixelOf(top, 25.0));
    EXPECT_NEAR(state_.xView->lo, anchor - 0.8 * anchor, kPixelRounding);
    EXPECT_NEAR(state_.xView->hi, anchor + 0.8 * (100.0 - anchor), kPixelRounding);
    frame();
    setButton(true);
    setButton(false);
    setButton(true);  // the second press within the double-click time
    EXPECT_FALSE(state_.xView);
    setButton(false);
    EXPECT_FALSE(state_.xView) << "the double-click's presses are clicks, not drags";
}

TEST_F(PlotWindowTest, DraggingOverASubPlotZoomsToTheXRangeDraggedOver) {
    const ItemRect bottom = frameRect(1);
    moveTo(pixelOf(bottom, 60.0), middleY(bottom));
    setButton(true);
    for (double x : {50.0, 40.0, 30.0, 20.0}) moveTo(pixelOf(bottom, x), middleY(bottom));  // right to left
    EXPECT_FALSE(state_.xView) << "zoomed before the release";
    setButton(false);
    ASSERT_TRUE(state_.xView);
    EXPECT_NEAR(state_.xView->lo, xAt(bottom, pixelOf(bottom, 20.0)), kPixelRounding);
    EXPECT_NEAR(state_.xView->hi, xAt(bottom, pixelOf(bottom, 60.0)), kPixelRounding);

    // The readout follows the zoomed axis.
    frame();
    moveTo(pixelOf(frameRect(1), 33.3, *state_.xView), middleY(bottom));
    ASSERT_TRUE(state_.hovered);
    EXPECT_EQ(state_.hovered->samples[0].x, 33.0);
}

TEST_F(PlotWindowTest, DataALogAxisCannotShowNeverReachesTheDrawingAsNaNOrInfinity) {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    constexpr double kInf = std::numeric_limits<double>::infinity();
    figure_.subPlots[0].curves.push_back({"nothing positive", {0.0, 50.0, 100.0}, {0.0, -2.0, kNaN}});
    figure_.subPlots[0].curves.push_back({"extremes", {0.0, 10.0, 20.0, 30.0}, {1e300, kInf, 1e-300, -kInf}});
    figure_.subPlots[1].curves.push_back({"one sample", {50.0}, {0.5}});
    const ItemRect top = frameRect(0);
    for (const Scale scale : {Scale::Log, Scale::Linear}) {
        state_.scales[0] = scale;
        moveTo(pixelOf(top, 10.0), middleY(top));  // with the readout's marks
        const ImDrawData* data = ImGui::GetDrawData();
        ASSERT_NE(data, nullptr);
        int vertices = 0;
        for (int list = 0; list < data->CmdListsCount; ++list) {
            for (const ImDrawVert& vertex : data->CmdLists[list]->VtxBuffer) {
                ASSERT_TRUE(std::isfinite(vertex.pos.x) && std::isfinite(vertex.pos.y))
                    << "a vertex at (" << vertex.pos.x << ", " << vertex.pos.y << ")";
                ++vertices;
            }
        }
        EXPECT_GT(vertices, 1000) << "the plot was drawn";
    }
}

TEST_F(PlotWindowTest, AClosedWindowDrawsNothing) {
    state_.open = false;
    frame();
    EXPECT_EQ(rects_.count("Test plot frame 0"), 0u);
    EXPECT_FALSE(state_.hovered);
}

}  // namespace
}  // namespace dropscope::gui
