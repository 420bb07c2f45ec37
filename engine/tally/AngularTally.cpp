#include "tally/AngularTally.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dropscope {

namespace {

double radians(double degrees) { return degrees * (std::numbers::pi / 180.0); }

}  // namespace

AngularTally::AngularTally(int bins) {
    if (bins < 1) throw std::invalid_argument("the number of angular bins must be at least 1");
    escapes_.assign(static_cast<std::size_t>(bins), 0);
}

void AngularTally::score(const Event& event, const TallyContext& photon) {
    if (event.type == EventType::Emit) ++photons_;
    if (event.type != EventType::Escape) return;
    const double cosine = std::clamp(event.direction.dot(photon.state.emitted.direction), -1.0, 1.0);
    const double fraction = std::acos(cosine) / std::numbers::pi;
    const auto bins = escapes_.size();
    ++escapes_[std::min(static_cast<std::size_t>(fraction * static_cast<double>(bins)), bins - 1)];
}

void AngularTally::merge(const Tally& other) {
    const AngularTally& more = sameTally(*this, other);
    if (more.escapes_.size() != escapes_.size()) throw std::logic_error("merging angular tallies of different bins");
    photons_ += more.photons_;
    for (std::size_t bin = 0; bin < escapes_.size(); ++bin) escapes_[bin] += more.escapes_[bin];
}

double AngularTally::lowerEdgeDeg(int bin) const {
    // 180 * bin / bins: the edge correctly rounded, so whole degrees come out whole
    return 180.0 * static_cast<double>(bin) / static_cast<double>(bins());
}

AngularTally::Columns AngularTally::columns() const {
    Columns columns;
    for (int bin = 0; bin < bins(); ++bin) {
        const double lo = lowerEdgeDeg(bin);
        const double hi = lowerEdgeDeg(bin + 1);
        const double share =
            photons_ > 0 ? static_cast<double>(escapes_[static_cast<std::size_t>(bin)]) / static_cast<double>(photons_)
                         : std::nan("");
        const double solidAngle = 2.0 * std::numbers::pi * (std::cos(radians(lo)) - std::cos(radians(hi)));
        columns.lower.push_back(lo);
        columns.upper.push_back(hi);
        columns.fraction.push_back(share);
        columns.perSteradian.push_back(share / solidAngle);
    }
    return columns;
}

void AngularTally::report(ResultReport& report) const {
    report.set({"bins"}, static_cast<std::uint64_t>(escapes_.size()));
    Columns c = columns();
    report.addTable({"angular",
                     {{"theta_lo_deg", std::move(c.lower)},
                      {"theta_hi_deg", std::move(c.upper)},
                      {"fraction", std::move(c.fraction)},
                      {"fraction_per_sr", std::move(c.perSteradian)}}});
}

std::vector<double> AngularTally::fractionPerSteradian() const { return columns().perSteradian; }

}  // namespace dropscope
