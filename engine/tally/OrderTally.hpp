#pragma once

#include "tally/Tally.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace dropscope {

// A photon's ray order (docs/detectors.md, "Ray orders"), told its events one by one from the emission: the
// photon meets a shape when it reflects off it or enters it (a reflect, refract or tir event at it). One that met
// exactly one shape has order p = (its interface events) - 1, kMaxOrder for five or more; kMultipleShapes when it
// met two shapes or more; kUnscattered when it met none. A photon diffracted by a droplet (a Diffract event) met
// it; one whose only meeting was that diffraction is kDiffracted. OrderTally counts escapes by it; the app's path
// filter gives each recorded path its order.
class RayOrder {
public:
    static constexpr int kUnscattered = -1;
    static constexpr int kMaxOrder = 5;
    static constexpr int kMultipleShapes = 6;
    static constexpr int kDiffracted = 7;

    void add(const Event& event);
    int order() const;

private:
    ShapeId firstShape_ = RayHit::kNone;
    bool severalShapes_ = false;
    bool diffracted_ = false;
    int eventsAtShape_ = 0;
};

// Ray orders (`dropscope trace --orders`, docs/detectors.md, "Ray orders"). An escaping photon that met exactly
// one shape (reflected off it or entered it) has ray order p = (its interface events at that shape) - 1: p0
// reflected outside, p1 straight through, p2 one internal reflection (the primary bow), ...; one that met two
// shapes or more is "multiple". Table "angular_orders": theta_lo_deg, theta_hi_deg, p0, p1, p2, p3, p4, p5_plus,
// multiple (shares of the emitted photons escaping into the bin, angles as in angular.csv); summary
// "single_scattering" and "multiple_scattering" (the columns' totals). Built `withDiffraction` (a run with
// --diffraction fraunhofer), the table ends with a column "diffraction": photons diffracted by one droplet and
// met by nothing else, part of the single scattering.
class OrderTally final : public Tally {
public:
    static constexpr std::size_t kOrderColumns = RayOrder::kMaxOrder + 1;  // p0 .. p4, p5_plus

    explicit OrderTally(int bins, bool withDiffraction = false);
    std::string_view name() const override { return "angular_orders"; }
    std::unique_ptr<Tally> emptyCopy() const override { return std::make_unique<OrderTally>(bins(), withDiffraction_); }
    std::unique_ptr<Tally> clone() const override { return std::make_unique<OrderTally>(*this); }
    void score(const Event& event, const TallyContext& photon) override;
    void merge(const Tally& other) override;
    void writeScores(ScoreWriter& out) const override;
    void readScores(ScoreReader& in) override;
    void report(ResultReport& report) const override;

    int bins() const { return static_cast<int>(multiple_.size()); }
    std::uint64_t photons() const { return photons_; }
    // Escapes of order p (p = 5: five or more) in each bin, and of photons that met several shapes.
    const std::vector<std::uint64_t>& order(std::size_t p) const { return orders_[p]; }
    const std::vector<std::uint64_t>& multiple() const { return multiple_; }
    const std::vector<std::uint64_t>& diffracted() const { return diffracted_; }
    bool withDiffraction() const { return withDiffraction_; }
    std::uint64_t singleTotal() const;
    std::uint64_t multipleTotal() const;

private:
    std::uint64_t photons_ = 0;
    std::array<std::vector<std::uint64_t>, kOrderColumns> orders_;
    std::vector<std::uint64_t> multiple_;
    bool withDiffraction_ = false;
    std::vector<std::uint64_t> diffracted_;
    RayOrder current_;  // of the photon being scored
};

}  // namespace dropscope
