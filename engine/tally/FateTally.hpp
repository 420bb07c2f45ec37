#pragma once

#include "tally/Tally.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace dropscope {

// The lost photon of lowest index: where and why. The same for any thread or rank count, since the merge
// keeps the lower index.
struct FirstLost {
    std::uint64_t photon = 0;
    LostReason reason = LostReason::EventCap;
    ShapeId shape = RayHit::kNone;  // the surface it was at, if any
    Point position = Point::Zero();
    friend bool operator==(const FirstLost&, const FirstLost&) = default;
};

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
    // Set when a photon was lost.
    const std::optional<FirstLost>& firstLost() const { return firstLost_; }
    // The reason most photons were lost for (the first in LostReason order on a tie); EventCap when none was.
    LostReason mainLostReason() const;
    // One line for stderr, summary.json's "lost_warning" and the app's status bar when a photon was lost:
    // "lost 0.3 % of the photons (3 of 1000), mostly at box edges or vertices (undefined_normal: 3); the first,
    // photon 17, at shape 0 (1, 0, -0.5)"; nothing when none was. With nameShapes, "... photon 17, on
    // shapes[0]: box \"b\" at (1, 0, -0.5)".
    std::optional<std::string> lossWarning() const;
    // How the warning and summary.json's first_lost.shape_label name a shape, where the scene is known (the
    // CLI, Python): `shapes[3]: sphere "d1"`, `generators[0]: droplet 17`. Not part of the scores.
    void nameShapes(std::function<std::string(ShapeId)> label) { shapeLabel_ = std::move(label); }

    friend bool operator==(const FateTally& a, const FateTally& b) {
        return a.photons_ == b.photons_ && a.escaped_ == b.escaped_ && a.absorbed_ == b.absorbed_ &&
               a.lost_ == b.lost_ && a.detected_ == b.detected_ && a.unscattered_ == b.unscattered_ &&
               a.lostReasons_ == b.lostReasons_ && a.events_ == b.events_ && a.firstLost_ == b.firstLost_;
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
    std::optional<FirstLost> firstLost_;
    std::function<std::string(ShapeId)> shapeLabel_;
};

}  // namespace dropscope
