#pragma once

#include "tally/AngularTally.hpp"

#include <utility>
#include <vector>

namespace dropscope {

// Equal wavelength bins over [loNm, hiNm], both ends included: bin k holds lo + (hi - lo) [k/K, (k+1)/K),
// the last also hi. With lo == hi (one line) there is one bin.
struct WavelengthBins {
    int count = 1;
    double loNm = 0.0;
    double hiNm = 0.0;

    // Throws std::invalid_argument for count < 1, a range that is not finite and positive or has lo > hi,
    // and count > 1 on a single wavelength.
    void check() const;
    double edgeNm(int k) const;            // lo + (hi - lo) k / K, exactly hi at k = K
    int binOf(double wavelengthNm) const;  // clamped to [0, K)
};

// The angular distribution per wavelength band: the table "angular_spectral" (angular_spectral.csv,
// docs/cli.md), one AngularTally per band. Every band counts every photon emitted, so a row's fraction is
// a share of all the power emitted, and the bands of one angle sum to angular.csv's row.
class SpectralAngularTally final : public Tally {
public:
    SpectralAngularTally(int angularBins, WavelengthBins wavelengths, bool stokes);

    std::string_view name() const override { return "angular_spectral"; }
    std::unique_ptr<Tally> emptyCopy() const override;
    std::unique_ptr<Tally> clone() const override { return std::make_unique<SpectralAngularTally>(*this); }
    void score(const Event& event, const TallyContext& photon) override;
    void merge(const Tally& other) override;
    void writeScores(ScoreWriter& out) const override;
    void readScores(ScoreReader& in) override;
    // Summary "wavelength_bins"; table "angular_spectral": wavelength_lo_nm, wavelength_hi_nm, then the columns
    // of AngularTally's table, band after band.
    void report(ResultReport& report) const override;

    const WavelengthBins& wavelengths() const { return wavelengths_; }
    const std::vector<AngularTally>& bands() const { return bands_; }

private:
    WavelengthBins wavelengths_;
    std::vector<AngularTally> bands_;
};

}  // namespace dropscope
