#pragma once

#include "tally/FixedPointSum.hpp"
#include "tally/Tally.hpp"

#include <cstdint>
#include <vector>

namespace dropscope {

// Of `bins` equal bins of theta over 0-180 degrees: the one a direction at angle acos(direction . axis) from
// `axis` falls in (180 degrees in the last), and edge k, 180 k / bins degrees, correctly rounded (so whole degrees
// come out whole). AngularTally, SpectralAngularTally and OrderTally share them.
std::size_t angularBinOf(const Direction& direction, const Direction& axis, std::size_t bins);
double angularEdgeDeg(int k, int bins);
// The solid angle of bin k of `bins` equal bins of theta over 0-180 degrees: 2 pi (cos lo - cos hi), in sr.
double angularBinSolidAngle(int k, int bins);

// Escapes per equal bin of theta, the angle between a photon's escape direction and its emission
// direction (0 straight on, 180 degrees straight back): the table "angular" (angular.csv, docs/cli.md).
// With `stokes`, also the Stokes parameters Q, U, V of the escaping light in each photon's scattering-plane
// frame (docs/transport.md, "Polarised tallies"), summed exactly (FixedPointSum).
class AngularTally final : public Tally {
public:
    // Throws std::invalid_argument when bins < 1.
    explicit AngularTally(int bins, bool stokes = false);

    std::string_view name() const override { return "angular"; }
    std::unique_ptr<Tally> emptyCopy() const override { return std::make_unique<AngularTally>(bins(), stokes()); }
    std::unique_ptr<Tally> clone() const override { return std::make_unique<AngularTally>(*this); }
    void score(const Event& event, const TallyContext& photon) override;
    void merge(const Tally& other) override;
    void writeScores(ScoreWriter& out) const override;
    void readScores(ScoreReader& in) override;
    // Summary "bins"; table "angular": theta_lo_deg, theta_hi_deg, fraction (of the photons traced),
    // fraction_per_sr (over the bin's solid angle 2 pi (cos lo - cos hi)); NaN when no photon was traced.
    // With stokes: stokes_q, stokes_u, stokes_v (sums over the bin as shares of the emitted power, like
    // fraction) and dolp = sqrt(Q^2 + U^2) / I of the bin (0 for an empty bin).
    void report(ResultReport& report) const override;

    int bins() const { return static_cast<int>(escapes_.size()); }
    bool stokes() const { return !stokesQ_.empty(); }
    std::uint64_t photons() const { return photons_; }
    const std::vector<std::uint64_t>& escapes() const { return escapes_; }
    // Bin b's lower and upper edges in degrees: 180 b / bins, correctly rounded.
    double lowerEdgeDeg(int bin) const;

    // The report's table, column by column (the Stokes columns empty without stokes).
    struct Columns {
        std::vector<double> lower, upper, fraction, perSteradian;
        std::vector<double> stokesQ, stokesU, stokesV, dolp;
    };
    Columns columns() const;
    // Appends the table's columns (theta_lo_deg, theta_hi_deg, fraction, fraction_per_sr, and with Stokes
    // columns stokes_q, stokes_u, stokes_v, dolp) to `table`: angular.csv's, and angular_spectral.csv's after
    // its wavelength columns.
    static void appendColumns(ResultTable& table, Columns columns, bool stokes);

    friend bool operator==(const AngularTally& a, const AngularTally& b) {
        return a.photons_ == b.photons_ && a.escapes_ == b.escapes_ && a.stokesQ_ == b.stokesQ_ &&
               a.stokesU_ == b.stokesU_ && a.stokesV_ == b.stokesV_;
    }

private:
    std::uint64_t photons_ = 0;
    std::vector<std::uint64_t> escapes_;
    std::vector<FixedPointSum> stokesQ_, stokesU_, stokesV_;  // empty without stokes
};

}  // namespace dropscope
