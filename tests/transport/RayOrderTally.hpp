#pragma once

#include "tally/FixedPointSum.hpp"
#include "tally/Tally.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace dropscope::test {

// For a lone sphere under a beam: the escapes by ray order (a photon's interface events less one: order 0
// is the outer reflection, order p >= 1 enters, reflects p - 1 times and leaves), the orders from
// `lastOrder` on counted together; the mean cosine of the scattering angle (g) of the escapes with its
// standard error; the escapes beyond 90 degrees. A test's tally: the detectors of the app will have their
// own ray orders.
class RayOrderTally final : public Tally {
public:
    explicit RayOrderTally(int lastOrder) : orders_(static_cast<std::size_t>(lastOrder) + 1, 0) {}

    std::string_view name() const override { return "ray_orders"; }
    std::unique_ptr<Tally> emptyCopy() const override {
        return std::make_unique<RayOrderTally>(static_cast<int>(orders_.size()) - 1);
    }
    std::unique_ptr<Tally> clone() const override { return std::make_unique<RayOrderTally>(*this); }
    void score(const Event& event, const TallyContext& photon) override {
        if (event.type != EventType::Escape) return;
        const auto order = static_cast<std::size_t>(photon.state.interfaceEvents) - 1;
        ++orders_[std::min(order, orders_.size() - 1)];
        ++escaped_;
        const double cosine = event.direction.dot(photon.state.emitted.direction);
        cosines_.add(cosine);
        squares_.add(cosine * cosine);
        if (cosine < 0.0) ++backscattered_;
    }
    void merge(const Tally& other) override {
        const RayOrderTally& more = sameTally(*this, other);
        for (std::size_t k = 0; k < orders_.size(); ++k) orders_[k] += more.orders_[k];
        escaped_ += more.escaped_;
        cosines_ += more.cosines_;
        squares_ += more.squares_;
        backscattered_ += more.backscattered_;
    }
    void writeScores(ScoreWriter& out) const override {
        out.words(orders_);
        out.word(escaped_);
        out.sum(cosines_);
        out.sum(squares_);
        out.word(backscattered_);
    }
    void readScores(ScoreReader& in) override {
        in.words(orders_);
        escaped_ = in.word();
        cosines_ = in.sum();
        squares_ = in.sum();
        backscattered_ = in.word();
    }
    void report(ResultReport&) const override {}

    const std::vector<std::uint64_t>& orders() const { return orders_; }
    std::uint64_t backscattered() const { return backscattered_; }
    double asymmetry() const { return cosines_.value() / static_cast<double>(escaped_); }
    double asymmetrySigma() const {
        const double n = static_cast<double>(escaped_);
        const double g = asymmetry();
        return std::sqrt((squares_.value() / n - g * g) / n);
    }

private:
    std::vector<std::uint64_t> orders_;
    std::uint64_t escaped_ = 0;
    FixedPointSum cosines_, squares_;
    std::uint64_t backscattered_ = 0;
};

}  // namespace dropscope::test
