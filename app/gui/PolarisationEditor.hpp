#pragma once

#include "gui/PanelWidgets.hpp"

#include <string>

namespace dropscope::gui {

// The polarisation of the Fire panel's selected source: its kind (unpolarised, linear, Stokes vector), the
// linear angle or the Stokes vector, the reference axis and a button that sets a perpendicular one; a point
// source is shown as unpolarised. Edits `source` only (the panel applies it to the document, which refuses
// a state checkPolarisation refuses), tracking each field in `edits`; `note` gets what was changed besides
// the field edited (a reference made perpendicular), for the status line.
void polarisationEditor(Source& source, FieldEdits& edits, std::string& note, const ItemProbe& probe);

}  // namespace dropscope::gui
