#pragma once

#include "edit/SceneDocument.hpp"
#include "gui/ItemProbe.hpp"
#include "gui/PanelState.hpp"
#include "gui/StatusLine.hpp"

#include <string>

namespace dropscope::gui {

// How the medium's n and absorption are given, for its row in the Media panel: "n 1.3337", "n water 20 C,
// kappa water", "n Cauchy, sigma table".
std::string dispersionSummary(const Medium& medium);

// The Media panel's Dispersion window, while fields.dispersionOpen, for medium fields.dispersionOf: the form
// of its n (number, table, Cauchy, Sellmeier, builtin) and of its kappa or sigma, each form's numbers, and
// a plot of n against the wavelength. Every edit goes to the document (setMedium), which refuses, in
// `status`, a model that is not valid or not defined at a wavelength a source emits. Tells the probe where
// it drew "n form", "kappa form" (or "sigma form"), the rows ("n rows 0", ...) and "n plot range" (its text).
void drawDispersionWindow(SceneDocument& document, MediaPanelFields& fields, StatusLine& status,
                          const ItemProbe& probe);

}  // namespace dropscope::gui
