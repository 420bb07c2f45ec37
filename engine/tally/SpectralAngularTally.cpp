#include "tally/SpectralAngularTally.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dropscope {

void WavelengthBins::check() const {
    if (count < 1) throw std::invalid_argument("the number of wavelength bins must be at least 1");
    if (!(std::isfinite(loNm) && std::isfinite(hiNm) && loNm > 0.0 && loNm <= hiNm)) {
        throw std::invalid_argument("wavelength bins need a finite range lo <= hi of positive wavelengths");
    }
    if (count > 1 && loNm == hiNm) {
        throw std::invalid_argument("the light has one wavelength: more than one wavelength bin needs a spectrum");
    }
}

double WavelengthBins::edgeNm(int k) const {
    if (k >= count) return hiNm;
    return loNm + (hiNm - loNm) * static_cast<double>(k) / static_cast<double>(count);
}

int WavelengthBins::binOf(double wavelengthNm) const {
    if (hiNm == loNm) return 0;
    const double position = (wavelengthNm - loNm) / (hiNm - loNm) * static_cast<double>(count);
    if (!(position > 0.0)) return 0;
    return std::min(static_cast<int>(position), count - 1);
}

SpectralAngularTally::SpectralAngularTally(int angularBins, WavelengthBins wavelengths, bool stokes)
    : wavelengths_(wavelengths) {
    wavelengths_.check();
    bands_.assign(static_cast<std::size_t>(wavelengths_.count), AngularTally(angularBins, stokes));
}

std::unique_ptr<Tally> SpectralAngularTally::emptyCopy() const {
    return std::make_unique<SpectralAngularTally>(bands_.front().bins(), wavelengths_, bands_.front().stokes());
}

void SpectralAngularTally::score(const Event& event, const TallyContext& photon) {
    if (event.type == EventType::Emit) {
        for (AngularTally& band : bands_) band.score(event, photon);
    } else if (event.type == EventType::Escape) {
        bands_[static_cast<std::size_t>(wavelengths_.binOf(photon.state.wavelengthNm))].score(event, photon);
    }
}

void SpectralAngularTally::merge(const Tally& other) {
    const SpectralAngularTally& more = sameTally(*this, other);
    if (more.bands_.size() != bands_.size() || more.wavelengths_.loNm != wavelengths_.loNm ||
        more.wavelengths_.hiNm != wavelengths_.hiNm) {
        throw std::logic_error("merging spectral angular tallies of different wavelength bins");
    }
    for (std::size_t k = 0; k < bands_.size(); ++k) bands_[k].merge(more.bands_[k]);
}

void SpectralAngularTally::writeScores(ScoreWriter& out) const {
    for (const AngularTally& band : bands_) band.writeScores(out);
}

void SpectralAngularTally::readScores(ScoreReader& in) {
    for (AngularTally& band : bands_) band.readScores(in);
}

void SpectralAngularTally::report(ResultReport& report) const {
    report.set({"wavelength_bins"}, static_cast<std::uint64_t>(bands_.size()));
    std::vector<double> lo, hi;
    AngularTally::Columns all;
    const auto append = [](std::vector<double>& to, const std::vector<double>& from) {
        to.insert(to.end(), from.begin(), from.end());
    };
    for (std::size_t k = 0; k < bands_.size(); ++k) {
        const AngularTally::Columns c = bands_[k].columns();
        lo.insert(lo.end(), c.lower.size(), wavelengths_.edgeNm(static_cast<int>(k)));
        hi.insert(hi.end(), c.lower.size(), wavelengths_.edgeNm(static_cast<int>(k) + 1));
        append(all.lower, c.lower);
        append(all.upper, c.upper);
        append(all.fraction, c.fraction);
        append(all.perSteradian, c.perSteradian);
        append(all.stokesQ, c.stokesQ);
        append(all.stokesU, c.stokesU);
        append(all.stokesV, c.stokesV);
        append(all.dolp, c.dolp);
    }
    ResultTable table{"angular_spectral",
                      {{"wavelength_lo_nm", std::move(lo), "nm"}, {"wavelength_hi_nm", std::move(hi), "nm"}}};
    AngularTally::appendColumns(table, std::move(all), bands_.front().stokes());
    report.addTable(std::move(table));
}

}  // namespace dropscope
