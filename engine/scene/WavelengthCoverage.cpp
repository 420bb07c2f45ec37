#include "scene/WavelengthCoverage.hpp"

#include <stdexcept>

namespace dropscope {

namespace {

// Why `model` fails somewhere on `spectrum`, or an empty string.
std::string problemOn(const SpectralFunction& model, OpticalQuantity quantity, const Spectrum& spectrum) {
    std::vector<double> wavelengths;
    if (spectrum.kind() == Spectrum::Kind::Lines) {
        for (const auto& line : spectrum.pointsNm()) wavelengths.push_back(line.first);
    } else {
        const auto [lo, hi] = spectrum.rangeNm();
        if (const auto domain = model.domainNm(); domain && (lo < domain->first || hi > domain->second)) {
            return "the spectrum's " + formatWavelength(lo) + " to " + formatWavelength(hi) + " is not within " +
                   formatWavelength(domain->first) + " to " + formatWavelength(domain->second) +
                   ", where it is defined";
        }
        for (int i = 0; i <= kCoverageSamplesPerSpectrum; ++i) {
            wavelengths.push_back(i == kCoverageSamplesPerSpectrum ? hi
                                                                   : lo + (hi - lo) * i / kCoverageSamplesPerSpectrum);
        }
    }
    for (const double wavelength : wavelengths) {
        try {
            checkedSpectralValue(model, quantity, wavelength);
        } catch (const std::logic_error& error) {
            return error.what();
        }
    }
    return {};
}

}  // namespace

std::optional<WavelengthCoverageProblem> findWavelengthCoverageProblem(const std::vector<Medium>& media,
                                                                       const std::vector<Source>& sources,
                                                                       double sceneWavelengthNm) {
    for (std::size_t m = 0; m < media.size(); ++m) {
        const Medium& medium = media[m];
        const std::pair<const std::optional<SpectralFunction>*, OpticalQuantity> models[] = {
            {&medium.nModel, OpticalQuantity::N},
            {&medium.kappaModel, OpticalQuantity::Kappa},
            {&medium.sigmaModel, OpticalQuantity::Sigma}};
        for (const auto& [model, quantity] : models) {
            if (!*model) continue;
            for (std::size_t s = 0; s < sources.size(); ++s) {
                std::string message = problemOn(**model, quantity, sourceSpectrum(sources[s], sceneWavelengthNm));
                if (!message.empty()) return WavelengthCoverageProblem{m, quantity, s, std::move(message)};
            }
        }
    }
    return std::nullopt;
}

}  // namespace dropscope
