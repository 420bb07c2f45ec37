#pragma once

#include "tally/Tally.hpp"

#include <array>
#include <cstdint>

namespace dropscope {

// How the photons of a run ended (escaped, absorbed, lost and why, detected by an absorbing detector;
// unscattered: escaped without meeting any surface) and their interface and absorption events: summary.json's
// fractions, counts, lost_reasons and events (docs/cli.md).
class FateTally final : public Tally {
public:
    std::string_view name() const override { return "fates"; }
    std::unique_ptr<Tally> emptyCopy() const override { return std::make_unique<FateTally>(); }
    std::unique_ptr<Tally> clone() const override { return std::make_unique<FateTally>(*this); }
    void score(const Event& event, const TallyContext& photon) override;
    void merge(const Tally& other) override;
    void writeScores(ScoreWriter& out) const override;
    void readScores(ScoreReader& in) override;
    void report(ResultReport& report) const override;

    std::uint64_t photons() const { return photons_; }  // emitted
    std::uint64_t escaped() const { return escaped_; }
    std::uint64_t absorbed() const { return absorbed_; }
    std::uint64_t lost() const { return lost_; }
    std::uint64_t detected() const { return detected_; }
    std::uint64_t unscattered() const { return unscattered_; }
    std::uint64_t lost(LostReason reason) const { return lostReasons_[static_cast<std::size_t>(reason)]; }
    const EventCounts& events() const { return events_; }

    friend bool operator==(const FateTally& a, const FateTally& b) {
        return a.photons_ == b.photons_ && a.escaped_ == b.escaped_ && a.absorbed_ == b.absorbed_ &&
               a.lost_ == b.lost_ && a.detected_ == b.detected_ && a.unscattered_ == b.unscattered_ &&
               a.lostReasons_ == b.lostReasons_ && a.events_ == b.events_;
    }

private:
    std::uint64_t photons_ = 0;
    std::uint64_t escaped_ = 0;
    std::uint64_t absorbed_ = 0;
    std::uint64_t lost_ = 0;
    std::uint64_t detected_ = 0;
    std::uint64_t unscattered_ = 0;
    std::array<std::uint64_t, kLostReasonCount> lostReasons_{};
    EventCounts events_;
};

}  // namespace dropscope
