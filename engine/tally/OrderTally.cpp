#include "tally/OrderTally.hpp"

#include "tally/AngularTally.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace dropscope {

void RayOrder::add(const Event& event) {
    const bool diffract = event.type == EventType::Diffract;
    if (!diffract && event.type != EventType::Reflect && event.type != EventType::Refract &&
        event.type != EventType::Tir)
        return;
    if (firstShape_ == RayHit::kNone) firstShape_ = event.shape;
    if (event.shape != firstShape_) severalShapes_ = true;
    if (diffract) {
        diffracted_ = true;
    } else {
        ++eventsAtShape_;
    }
}

int RayOrder::order() const {
    if (firstShape_ == RayHit::kNone) return kUnscattered;
    if (severalShapes_) return kMultipleShapes;
    // A droplet that diffracts a photon is passed as if it were not there: nothing else happens at it.
    if (diffracted_) return kDiffracted;
    return std::min(eventsAtShape_ - 1, kMaxOrder);
}

OrderTally::OrderTally(int bins, bool withDiffraction) : withDiffraction_(withDiffraction) {
    if (bins < 1) throw std::invalid_argument("the number of angular bins must be at least 1");
    const auto count = static_cast<std::size_t>(bins);
    for (auto& column : orders_) column.assign(count, 0);
    multiple_.assign(count, 0);
    diffracted_.assign(count, 0);
}

void OrderTally::score(const Event& event, const TallyContext& photon) {
    if (event.type == EventType::Emit) {
        ++photons_;
        current_ = {};
        return;
    }
    current_.add(event);
    if (event.type != EventType::Escape) return;
    const int order = current_.order();
    if (order == RayOrder::kUnscattered) return;
    // The same bins as AngularTally: theta from the photon's axis.
    const std::size_t bin = angularBinOf(event.direction, photon.state.axis, multiple_.size());
    if (order == RayOrder::kMultipleShapes) {
        ++multiple_[bin];
    } else if (order == RayOrder::kDiffracted) {
        ++diffracted_[bin];
    } else {
        ++orders_[static_cast<std::size_t>(order)][bin];
    }
}

void OrderTally::merge(const Tally& other) {
    const OrderTally& more = sameTally(*this, other);
    if (more.bins() != bins() || more.withDiffraction_ != withDiffraction_)
        throw std::logic_error("merging order tallies of different bins or diffraction");
    photons_ += more.photons_;
    for (std::size_t p = 0; p < kOrderColumns; ++p) {
        for (std::size_t b = 0; b < multiple_.size(); ++b) orders_[p][b] += more.orders_[p][b];
    }
    for (std::size_t b = 0; b < multiple_.size(); ++b) {
        multiple_[b] += more.multiple_[b];
        diffracted_[b] += more.diffracted_[b];
    }
}

void OrderTally::writeScores(ScoreWriter& out) const {
    out.word(photons_);
    for (const std::vector<std::uint64_t>& column : orders_) out.words(column);
    out.words(multiple_);
    out.words(diffracted_);
}

void OrderTally::readScores(ScoreReader& in) {
    photons_ = in.word();
    for (std::vector<std::uint64_t>& column : orders_) in.words(column);
    in.words(multiple_);
    in.words(diffracted_);
}

std::uint64_t OrderTally::singleTotal() const {
    std::uint64_t total = 0;
    for (const auto& column : orders_) {
        for (std::uint64_t count : column) total += count;
    }
    for (std::uint64_t count : diffracted_) total += count;
    return total;
}

std::uint64_t OrderTally::multipleTotal() const {
    std::uint64_t total = 0;
    for (std::uint64_t count : multiple_) total += count;
    return total;
}

void OrderTally::report(ResultReport& report) const {
    const auto share = [&](std::uint64_t count) {
        return photons_ > 0 ? static_cast<double>(count) / static_cast<double>(photons_) : std::nan("");
    };
    report.set({"single_scattering"}, share(singleTotal()));
    report.set({"multiple_scattering"}, share(multipleTotal()));
    std::vector<double> lower, upper;
    for (int bin = 0; bin < bins(); ++bin) {
        lower.push_back(angularEdgeDeg(bin, bins()));
        upper.push_back(angularEdgeDeg(bin + 1, bins()));
    }
    ResultTable table{"angular_orders", {}};
    table.columns.push_back({"theta_lo_deg", std::move(lower), "deg"});
    table.columns.push_back({"theta_hi_deg", std::move(upper), "deg"});
    const auto shares = [&](const std::vector<std::uint64_t>& counts) {
        std::vector<double> column;
        for (std::uint64_t count : counts) column.push_back(share(count));
        return column;
    };
    static const std::array<std::string, kOrderColumns> kNames{"p0", "p1", "p2", "p3", "p4", "p5_plus"};
    for (std::size_t p = 0; p < kOrderColumns; ++p) table.columns.push_back({kNames[p], shares(orders_[p])});
    table.columns.push_back({"multiple", shares(multiple_)});
    if (withDiffraction_) table.columns.push_back({"diffraction", shares(diffracted_)});
    report.addTable(std::move(table));
}

}  // namespace dropscope
