#pragma once

#include "cli/SceneSummary.hpp"
#include "scene/Scene.hpp"

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace dropscope {

// The human-readable report of `dropscope inspect`: aligned tables, numbers to 6 significant digits.
void writeInspectTables(const Scene& scene, const SceneSummary& summary, std::ostream& out);

// The wavelengths at which inspect shows dispersive media: every line of the sources' line spectra, or
// kInspectWavelengthsNm when no source has lines.
std::vector<double> inspectWavelengthsNm(const Scene& scene);
inline constexpr double kInspectWavelengthsNm[] = {400.0, 550.0, 700.0};

// A medium at each of inspectWavelengthsNm: its n and absorption, or nothing outside a model's range.
struct DispersionSample {
    double wavelengthNm;
    std::optional<MediumOptics> optics;
};
std::vector<DispersionSample> dispersionSamples(const Scene& scene, const Medium& medium);

// "sellmeier", "builtin water (20 C)", "table (4 points)": how a medium's quantity varies; "-" for a number.
std::string spectralModelText(const std::optional<SpectralFunction>& model);
// "scene line", "lines 486.1-656.3 nm (3)", "sun 380-780 nm", plus ", divergence 0.266 deg".
std::string spectrumText(const Source& source);

// The same as one JSON document (`inspect --json`, keys in docs/scene-format.md); numbers are
// written with every digit needed to read them back exactly.
void writeInspectJson(const Scene& scene, const SceneSummary& summary, std::ostream& out);

}  // namespace dropscope
