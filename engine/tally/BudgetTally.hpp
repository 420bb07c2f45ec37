#pragma once

#include "scene/Detector.hpp"
#include "tally/Tally.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace dropscope {

// Where every photon of a run went (summary.json "budget", docs/detectors.md, "Energy budget"): escaped (into
// each far-field detector, the first in scene order that sees it, or elsewhere), absorbed (by medium),
// detected (by absorbing detector) or lost (by reason). Each count has its share of the photons; the four
// totals add up to every photon exactly, as does each breakdown to its total.
class BudgetTally final : public Tally {
public:
    // `detectors` are the scene's (far-field and absorbing plane ones are used), `media` its media's names.
    BudgetTally(const std::vector<Detector>& detectors, std::vector<std::string> media);
    std::string_view name() const override { return "budget"; }
    std::unique_ptr<Tally> emptyCopy() const override;
    std::unique_ptr<Tally> clone() const override { return std::make_unique<BudgetTally>(*this); }
    void score(const Event& event, const TallyContext& photon) override;
    void merge(const Tally& other) override;
    void writeScores(ScoreWriter& out) const override;
    void readScores(ScoreReader& in) override;
    void report(ResultReport& report) const override;

    std::uint64_t photons() const { return photons_; }
    std::uint64_t escapedElsewhere() const { return escapedElsewhere_; }
    const std::vector<std::uint64_t>& escapedInto() const { return escapedInto_; }  // per far-field detector
    const std::vector<std::uint64_t>& absorbedBy() const { return absorbedBy_; }    // per medium
    const std::vector<std::uint64_t>& detectedBy() const { return detectedBy_; }    // per scene detector
    const std::array<std::uint64_t, kLostReasonCount>& lostBy() const { return lostBy_; }

private:
    std::vector<Detector> detectors_;
    std::vector<std::string> media_;
    std::vector<FarFieldCamera> cameras_;
    std::vector<std::size_t> cameraDetectors_;  // the scene index of each camera
    std::uint64_t photons_ = 0;
    std::uint64_t escapedElsewhere_ = 0;
    std::vector<std::uint64_t> escapedInto_, absorbedBy_, detectedBy_;
    std::array<std::uint64_t, kLostReasonCount> lostBy_{};
};

}  // namespace dropscope
