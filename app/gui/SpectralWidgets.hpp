#pragma once

#include "gui/ItemProbe.hpp"
#include "spectrum/Spectrum.hpp"

#include <array>
#include <vector>

namespace dropscope::gui {

// Widgets of the wavelength editors (Media panel's Dispersion window, Fire panel) and legends (Paths panel).

// The visible range the legends and plots span when nothing else gives one.
inline constexpr std::array<double, 2> kVisibleRangeNm{380.0, 780.0};

// Rows of one or two numbers (`columns`), each applied on Enter, a remove button ("x") per row and an
// "Add row" button that appends `newRow` (or, with `step` > 0 and rows to copy, the last one with its
// first number moved by `step`: a table's next wavelength). True when a row was edited, added or removed. Tells the
// probe where it drew
// "<label> <i>" (row i's fields) and "<label> add".
bool editRows(const char* label, std::vector<std::array<double, 2>>& rows, int columns, std::array<double, 2> newRow,
              double step, const ItemProbe& probe);
// A bar of `width` showing the colour of each wavelength from lo to hi (displayColourOfWavelength).
void wavelengthBar(double loNm, double hiNm, float width, float height);
// The spectrum as a bar chart over the visible range (or its own range, where that is wider): each
// column as high as its share of the photons and in its wavelength's colour; beside it the range emitted.
void spectrumPreview(const Spectrum& spectrum, float width, float height);

}  // namespace dropscope::gui
