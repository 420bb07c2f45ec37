#include "gui/FrameClient.hpp"
#include "gui/window/GlfwWindow.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <sstream>

namespace dropscope::gui {
namespace {

// Quits after its second frame; notes whether its window was on the screen when it was destroyed.
class QuittingClient : public FrameClient {
public:
    explicit QuittingClient(int& visibleWhenDestroyed) : visibleWhenDestroyed_(visibleWhenDestroyed) {}
    ~QuittingClient() override { visibleWhenDestroyed_ = glfwGetWindowAttrib(glfwGetCurrentContext(), GLFW_VISIBLE); }
    void frame(const InputFrame&) override { ++frames_; }
    bool quitRequested() const override { return frames_ >= 2; }

private:
    int& visibleWhenDestroyed_;
    int frames_ = 0;
};

// Opens a real window: CTest runs it as gui_window_xvfb, under xvfb-run with DROPSCOPE_WINDOW_TEST set (and
// LeakSanitizer off, which would report Mesa's driver); everywhere else, a desktop's gui_tests included, it is
// skipped.
TEST(GlfwWindow, TheWindowLeavesTheScreenBeforeTheAppWaitsForItsJobs) {
    if (std::getenv("DROPSCOPE_WINDOW_TEST") == nullptr) {
        GTEST_SKIP() << "opens a window: run by gui_window_xvfb under xvfb-run";
    }
    int visible = -1;
    std::ostringstream err;
    const int code = runWindow(
        WindowOptions{}, [&](const render::GlFunctions&) { return std::make_unique<QuittingClient>(visible); }, err);
    ASSERT_EQ(code, 0) << err.str();
    EXPECT_EQ(visible, GLFW_FALSE) << "the window was still shown while the app was being closed";
}

}  // namespace
}  // namespace dropscope::gui
