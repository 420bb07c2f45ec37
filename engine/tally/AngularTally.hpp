#pragma once

#include "tally/Tally.hpp"

#include <cstdint>
#include <vector>

namespace dropscope {

// Escapes per equal bin of theta, the angle between a photon's escape direction and its emission
// direction (0 straight on, 180 degrees straight back): the table "angular" (angular.csv, docs/cli.md).
class AngularTally final : public Tally {
public:
    // Throws std::invalid_argument when bins < 1.
    explicit AngularTally(int bins);

    std::string_view name() const override { return "angular"; }
    std::unique_ptr<Tally> emptyCopy() const override { return std::make_unique<AngularTally>(bins()); }
    std::unique_ptr<Tally> clone() const override { return std::make_unique<AngularTally>(*this); }
    void score(const Event& event, const TallyContext& photon) override;
    void merge(const Tally& other) override;
    // Summary "bins"; table "angular": theta_lo_deg, theta_hi_deg, fraction (of the photons traced),
    // fraction_per_sr (over the bin's solid angle 2 pi (cos lo - cos hi)); NaN when no photon was traced.
    void report(ResultReport& report) const override;

    int bins() const { return static_cast<int>(escapes_.size()); }
    std::uint64_t photons() const { return photons_; }
    const std::vector<std::uint64_t>& escapes() const { return escapes_; }
    // Bin b's lower and upper edges in degrees: 180 b / bins, correctly rounded.
    double lowerEdgeDeg(int bin) const;
    // The report's fraction_per_sr column.
    std::vector<double> fractionPerSteradian() const;

    friend bool operator==(const AngularTally& a, const AngularTally& b) {
        return a.photons_ == b.photons_ && a.escapes_ == b.escapes_;
    }

private:
    struct Columns {
        std::vector<double> lower, upper, fraction, perSteradian;
    };
    Columns columns() const;  // the report's table

    std::uint64_t photons_ = 0;
    std::vector<std::uint64_t> escapes_;
};

}  // namespace dropscope
