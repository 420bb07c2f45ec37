#pragma once

#include "gui/PanelWidgets.hpp"

#include <string>

namespace dropscope::gui {

// The spectrum and the divergence of the Fire panel's selected source: the spectrum's form (the scene's
// line, lines, uniform, table, blackbody, sun) and its numbers, a preview of it, and the divergence of a
// beam or a ray. Edits `source` only (the panel applies it to the document, which refuses what
// checkDivergence refuses and media not defined at a wavelength emitted), tracking each field in `edits`.
// Numbers that make no spectrum (a table whose wavelengths do not ascend, lo >= hi) leave the spectrum
// as it was and put the reason in `refusal`.
void spectrumEditor(Source& source, double sceneWavelengthNm, FieldEdits& edits, std::string& refusal,
                    const ItemProbe& probe);

}  // namespace dropscope::gui
