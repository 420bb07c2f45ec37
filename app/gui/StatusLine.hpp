#pragma once

#include <string>
#include <utility>

namespace dropscope::gui {

// The line at the bottom of the window: what the last action did, or why it was refused.
class StatusLine {
public:
    void say(std::string text) { set(std::move(text), false); }
    void refuse(std::string text) { set(std::move(text), true); }

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
