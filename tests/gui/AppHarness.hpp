#pragma once

#include "gui/App.hpp"
#include "scene/SceneLoader.hpp"
#include "snapshot/OsmesaContext.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <thread>

namespace dropscope::gui::testing {

// The real app, headless: an OSMesa buffer instead of a window, driven by the same InputFrame the GLFW
// window fills, one frame per call.
class AppHarness {
public:
    AppHarness(std::string_view sceneJson, int width = 1280, int height = 800, AppOptions options = {})
        : context_(width, height) {
        input_.windowWidth = input_.framebufferWidth = width;
        input_.windowHeight = input_.framebufferHeight = height;
        options.itemProbe = [this](std::string_view name, const ItemRect& rect) {
            itemRects_[std::string(name)] = rect;
        };
        app_ = std::make_unique<App>(context_.gl(), parseScene(sceneJson, "test.json"), options);
        frames(2);  // ImGui lays windows out on their first frame and shows them on the second
    }
    // The app's item probe points at this harness.
    AppHarness(const AppHarness&) = delete;
    AppHarness& operator=(const AppHarness&) = delete;

    App& app() { return *app_; }
    AppState& state() { return app_->state(); }
    InputFrame& input() { return input_; }
    // Where the named fields were drawn in the last frame (ItemProbe), by name.
    const std::map<std::string, ItemRect>& itemRects() const { return itemRects_; }

    void frame() {
        itemRects_.clear();
        app_->frame(input_);
        input_.wheelY = 0.0f;
        input_.characters.clear();
    }
    void frames(int count) {
        for (int k = 0; k < count; ++k) frame();
    }
    void moveMouse(float x, float y) {
        input_.mouseInside = true;
        input_.mouseX = x;
        input_.mouseY = y;
        frame();
    }
    void click(float x, float y, int button = 0) {
        moveMouse(x, y);
        input_.mouseDown[static_cast<std::size_t>(button)] = true;
        frame();
        input_.mouseDown[static_cast<std::size_t>(button)] = false;
        frame();
    }
    // Press at `from`, move in `steps` frames to `to`, release there.
    void drag(float fromX, float fromY, float toX, float toY, int steps = 8, int button = 0) {
        moveMouse(fromX, fromY);
        input_.mouseDown[static_cast<std::size_t>(button)] = true;
        frame();
        for (int k = 1; k <= steps; ++k) {
            const float t = static_cast<float>(k) / static_cast<float>(steps);
            moveMouse(fromX + t * (toX - fromX), fromY + t * (toY - fromY));
        }
        input_.mouseDown[static_cast<std::size_t>(button)] = false;
        frame();
    }
    void press(int key, bool ctrl = false, bool shift = false) {
        input_.ctrl = ctrl;
        input_.shift = shift;
        input_.keysDown.set(static_cast<std::size_t>(key));
        frame();
        input_.keysDown.reset(static_cast<std::size_t>(key));
        input_.ctrl = input_.shift = false;
        frame();
    }
    // Where the named field was drawn in the last frame; a failure and nothing when it was not.
    std::optional<ItemRect> item(const std::string& name) {
        const auto found = itemRects_.find(name);
        EXPECT_NE(found, itemRects_.end()) << "'" << name << "' was not drawn";
        if (found == itemRects_.end()) return std::nullopt;
        return found->second;
    }
    // Clicks the named field, `dx` pixels into it (its middle when negative), halfway down.
    bool clickItem(const std::string& name, float dx = -1.0f) {
        const auto rect = item(name);
        if (!rect) return false;
        click(dx < 0.0f ? 0.5f * (rect->minX + rect->maxX) : rect->minX + dx, 0.5f * (rect->minY + rect->maxY));
        return true;
    }
    // Picks "combo: choice" in the named combo box, as a user does: a click opens it, a click chooses.
    bool choose(const std::string& combo, const std::string& choice) {
        if (!clickItem(combo)) return false;
        frames(2);  // the popup is laid out in its first frame and shown in the second
        return clickItem(combo + ": " + choice);
    }
    // Types `text` into the named field, `dx` pixels into it (the first of several numbers), replacing what
    // it held, and leaves it with Enter.
    bool typeInto(const std::string& name, const std::string& text, float dx = 8.0f) {
        if (!clickItem(name, dx)) return false;
        EXPECT_TRUE(ImGui::GetIO().WantTextInput) << "the click did not reach " << name;
        press('A', true);  // select the whole number
        for (const char c : text) {
            input_.characters.push_back(static_cast<unsigned>(c));
            frame();
        }
        press(kKeyEnter);
        return true;
    }
    // Frames until the background trace has delivered (a generous bound: a hang check, not a timing).
    bool waitForTrace(std::chrono::seconds limit = std::chrono::seconds(60)) {
        const auto end = std::chrono::steady_clock::now() + limit;
        do {
            frame();
            if (!state().traces.job.running() && state().traces.trace) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        } while (std::chrono::steady_clock::now() < end);
        return false;
    }
    // Frames until a trace started since the results numbered `shownBefore` (TraceState::shownId) were
    // shown has delivered and is shown: a live trace, or one fired while another was shown.
    bool waitForNewTrace(std::uint64_t shownBefore, std::chrono::seconds limit = std::chrono::seconds(60)) {
        const auto end = std::chrono::steady_clock::now() + limit;
        do {
            frame();
            if (!state().traces.job.running()) {
                frame();  // takes the result, should the run have ended after this frame took none
                if (state().traces.shownId != shownBefore) return true;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        } while (std::chrono::steady_clock::now() < end);
        return false;
    }
    snapshot::Image image() const { return context_.read(); }
    const render::GlFunctions& gl() const { return context_.gl(); }

private:
    snapshot::OsmesaContext context_;  // first: the app's GL objects live in this context
    InputFrame input_;
    std::map<std::string, ItemRect> itemRects_;
    std::unique_ptr<App> app_;
};

// The scene's first source, as the document holds it.
inline const Source& firstSource(AppHarness& harness) { return harness.state().scene.document().sources().front(); }

// Fires `photons` (keeping `paths` of them) with Space and waits until their results are shown.
inline void fire(AppHarness& harness, std::uint64_t photons = 200, std::uint64_t paths = 10) {
    harness.state().traces.fire.photons = photons;
    harness.state().traces.fire.paths = paths;
    const std::uint64_t shown = harness.state().traces.shownId;
    harness.press(kKeySpace);
    ASSERT_TRUE(harness.waitForNewTrace(shown));
}

// The run whose results the app shows.
inline const TraceResult& shownTrace(AppHarness& harness) { return harness.state().traces.trace->outcome.result; }

}  // namespace dropscope::gui::testing
