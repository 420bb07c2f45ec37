#pragma once

#include "gui/plot/PlotData.hpp"

#include <cstddef>
#include <filesystem>
#include <string>

// A figure's data as CSV, every sample of every curve (not only the zoomed part).
namespace dropscope::gui::plot {

// Whether every curve of the figure has the same x values (then one x column serves them all).
bool sharesX(const Figure& figure);

// When the curves share x: a header "<x label>,<curve>,<curve>,..." and one row per x. Otherwise the
// long form: "curve,x,y" and one row per sample. Numbers in their shortest round-trip form; a curve
// name used twice in the figure becomes "<y label>: <name>"; fields with a comma, quote or line break
// quoted (RFC 4180). Lines end in "\n".
std::string plotCsv(const Figure& figure);
// The rows below the header plotCsv writes.
std::size_t plotCsvRows(const Figure& figure);
// Writes plotCsv whole or not at all (writeFileAtomically); throws std::runtime_error naming the file
// when it cannot.
void writePlotCsv(const Figure& figure, const std::filesystem::path& file);

}  // namespace dropscope::gui::plot
