#pragma once

#include <exception>
#include <string>
#include <string_view>
#include <utility>

namespace dropscope::gui {

// The line at the bottom of the window: what the last action did, or why it was refused.
class StatusLine {
public:
    void say(std::string text) { set(std::move(text), false); }
    void refuse(std::string text) { set(std::move(text), true); }

    // Runs `action` (which says what it did, if anything). When it throws instead (an edit the document
    // refuses, a file that cannot be written), refuses with "failure: the reason". Returns whether the
    // action ran to its end.
    template <class Action>
    bool attempt(std::string_view failure, Action&& action) {
        try {
            std::forward<Action>(action)();
            return true;
        } catch (const std::exception& error) {
            refuse(std::string(failure) + ": " + error.what());
            return false;
        }
    }

    const std::string& text() const { return text_; }
    bool error() const { return error_; }

private:
    void set(std::string text, bool error) {
        text_ = std::move(text);
        error_ = error;
    }

    std::string text_;
    bool error_ = false;
};

}  // namespace dropscope::gui
