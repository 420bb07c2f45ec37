#pragma once

#include "gui/AppState.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace dropscope::gui {

// Widgets more than one panel uses.

// Three doubles in one row (a point, a direction, semi-axes); true when edited this frame. `flags` are
// ImGuiInputTextFlags (EnterReturnsTrue: applied on Enter only).
bool inputVector3(const char* label, Eigen::Vector3d& v, const char* format = "%.6g", int flags = 0);
// A choice among the document's media; true when another one was chosen.
bool mediumCombo(const char* label, const SceneDocument& document, MediumId& medium);
// One of `choices` in a combo box, with `help` as the box's tooltip; true when another one was chosen.
// Tells the probe, if there is one, where the box is, under `label`, and while it is open where each
// choice is, under "label: choice".
bool choiceCombo(const char* label, int& chosen, std::span<const char* const> choices, const ItemProbe& probe,
                 const char* help = nullptr);
// Tells the probe, if there is one, where the last widget was drawn, under `name`.
void reportItemRect(const ItemProbe& probe, std::string_view name);
// Draws `text` (wrapped at the window's edge with `wrap`) and tells the probe, if there is one, what it
// says and where, under `name`.
void probedText(const ItemProbe& probe, std::string_view name, const std::string& text, bool wrap = false);

// Which field of a form was edited this frame, so that one activation of one field (typing a number,
// dragging a value) is one undo step. `editing` (kept in PanelState) is the field of the last edit
// applied, 0 when none is being edited.
class FieldEdits {
public:
    explicit FieldEdits(std::uint32_t& editing) : editing_(editing) {}
    // Returns `edited`; when it is true, `label`'s field (its id in the current window) is the one edited.
    bool track(bool edited, const char* label);
    bool changed() const { return edited_ != 0; }
    // The edit continues the last one applied (the same field, still active): merge their undo steps.
    bool continuesLast() const { return edited_ == editing_; }
    // The edit was applied: the next one of the same field continues it.
    void applied() { editing_ = edited_; }
    // At the end of the form: with no field active, the next edit starts a new undo step.
    void finish();

private:
    std::uint32_t& editing_;
    std::uint32_t edited_ = 0;
};
// The running trace's progress bar (or "building the octree") with its Cancel button, on one line.
void drawTraceProgress(AppState& state, float barWidth);

}  // namespace dropscope::gui
