#pragma once

#include "gui/ItemProbe.hpp"
#include "tally/BudgetTally.hpp"

namespace dropscope::gui {

// The energy budget (summary.json's "budget") drawn for the Results panel: where the photons went.

// One bar `width` wide, split into the shares escaped, absorbed, detected and lost (a tooltip names them).
// Tells the probe where it is, as "budget bar".
void drawBudgetBar(const BudgetTally& budget, float width, const ItemProbe& probe);
// The "Energy budget" window while `open` (its close button clears it): the bar, and a table of each end's
// photons and share with its breakdown (far-field camera or elsewhere, medium, detector, reason). Tells the
// probe where each end's row is, as "budget escaped", ...
void drawBudgetWindow(const BudgetTally& budget, bool& open, const ItemProbe& probe);

}  // namespace dropscope::gui
