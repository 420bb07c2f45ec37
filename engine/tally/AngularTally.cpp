#include "tally/AngularTally.hpp"

#include "optics/OpticsTolerance.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dropscope {

namespace {

double radians(double degrees) { return degrees * (std::numbers::pi / 180.0); }

// The escaping light's Stokes vector in the scattering-plane frame: the parallel axis in the plane of the
// emission direction k0 and the escape direction k (Bohren and Huffman's e_par,s, up to a sign that
// changes no Stokes parameter). Straight on or straight back the plane is undefined and the photon's own
// frame is kept (tolerance::kScatteringPlaneSine).
StokesVector scatteringPlaneStokes(const Polarisation& light, const Direction& k, const Direction& k0) {
    const Eigen::Vector3d inPlane = k0.vector() - k0.dot(k.vector()) * k.vector();
    const double sine = inPlane.norm();
    if (sine < tolerance::kScatteringPlaneSine) return light.stokes;
    return stokesInFrame(light, k, inPlane / sine);
}

}  // namespace

std::size_t angularBinOf(const Direction& direction, const Direction& axis, std::size_t bins) {
    const double cosine = std::clamp(direction.dot(axis), -1.0, 1.0);
    const double fraction = std::acos(cosine) / std::numbers::pi;
    return std::min(static_cast<std::size_t>(fraction * static_cast<double>(bins)), bins - 1);
}

double angularEdgeDeg(int k, int bins) { return 180.0 * static_cast<double>(k) / static_cast<double>(bins); }

double angularBinSolidAngle(int k, int bins) {
    return 2.0 * std::numbers::pi *
           (std::cos(radians(angularEdgeDeg(k, bins))) - std::cos(radians(angularEdgeDeg(k + 1, bins))));
}

AngularTally::AngularTally(int bins, bool stokes) {
    if (bins < 1) throw std::invalid_argument("the number of angular bins must be at least 1");
    const auto count = static_cast<std::size_t>(bins);
    escapes_.assign(count, 0);
    if (stokes) stokesQ_ = stokesU_ = stokesV_ = std::vector<FixedPointSum>(count);
}

void AngularTally::score(const Event& event, const TallyContext& photon) {
    if (event.type == EventType::Emit) ++photons_;
    if (event.type != EventType::Escape) return;
    const Direction& emitted = photon.state.axis;
    const std::size_t bin = angularBinOf(event.direction, emitted, escapes_.size());
    ++escapes_[bin];
    if (!stokes()) return;
    if (!event.polarisation) throw std::logic_error("a Stokes angular tally was given an unpolarised photon");
    const StokesVector s = scatteringPlaneStokes(*event.polarisation, event.direction, emitted);
    stokesQ_[bin].add(s[1]);
    stokesU_[bin].add(s[2]);
    stokesV_[bin].add(s[3]);
}

void AngularTally::merge(const Tally& other) {
    const AngularTally& more = sameTally(*this, other);
    if (more.escapes_.size() != escapes_.size() || more.stokes() != stokes()) {
        throw std::logic_error("merging angular tallies of different bins or columns");
    }
    photons_ += more.photons_;
    for (std::size_t bin = 0; bin < escapes_.size(); ++bin) escapes_[bin] += more.escapes_[bin];
    for (std::size_t bin = 0; bin < stokesQ_.size(); ++bin) {
        stokesQ_[bin] += more.stokesQ_[bin];
        stokesU_[bin] += more.stokesU_[bin];
        stokesV_[bin] += more.stokesV_[bin];
    }
}

void AngularTally::writeScores(ScoreWriter& out) const {
    out.word(photons_);
    out.words(escapes_);
    for (const auto* column : {&stokesQ_, &stokesU_, &stokesV_}) out.sums(*column);
}

void AngularTally::readScores(ScoreReader& in) {
    photons_ = in.word();
    in.words(escapes_);
    for (auto* column : {&stokesQ_, &stokesU_, &stokesV_}) in.sums(*column);
}

double AngularTally::lowerEdgeDeg(int bin) const { return angularEdgeDeg(bin, bins()); }

AngularTally::Columns AngularTally::columns() const {
    Columns columns;
    const auto share = [&](double sum) { return photons_ > 0 ? sum / static_cast<double>(photons_) : std::nan(""); };
    for (int bin = 0; bin < bins(); ++bin) {
        const auto b = static_cast<std::size_t>(bin);
        const double lo = lowerEdgeDeg(bin);
        const double hi = lowerEdgeDeg(bin + 1);
        const double fraction = share(static_cast<double>(escapes_[b]));
        const double solidAngle = angularBinSolidAngle(bin, bins());
        columns.lower.push_back(lo);
        columns.upper.push_back(hi);
        columns.fraction.push_back(fraction);
        columns.perSteradian.push_back(fraction / solidAngle);
        if (!stokes()) continue;
        const double q = share(stokesQ_[b].value());
        const double u = share(stokesU_[b].value());
        columns.stokesQ.push_back(q);
        columns.stokesU.push_back(u);
        columns.stokesV.push_back(share(stokesV_[b].value()));
        columns.dolp.push_back(escapes_[b] > 0 ? std::hypot(q, u) / fraction : (photons_ > 0 ? 0.0 : std::nan("")));
    }
    return columns;
}

void AngularTally::appendColumns(ResultTable& table, Columns c, bool stokes) {
    table.columns.push_back({"theta_lo_deg", std::move(c.lower), "deg"});
    table.columns.push_back({"theta_hi_deg", std::move(c.upper), "deg"});
    table.columns.push_back({"fraction", std::move(c.fraction)});
    table.columns.push_back({"fraction_per_sr", std::move(c.perSteradian), "1/sr"});
    if (!stokes) return;
    table.columns.push_back({"stokes_q", std::move(c.stokesQ)});
    table.columns.push_back({"stokes_u", std::move(c.stokesU)});
    table.columns.push_back({"stokes_v", std::move(c.stokesV)});
    table.columns.push_back({"dolp", std::move(c.dolp)});
}

void AngularTally::report(ResultReport& report) const {
    report.set({"bins"}, static_cast<std::uint64_t>(escapes_.size()));
    ResultTable table{"angular", {}};
    appendColumns(table, columns(), stokes());
    report.addTable(std::move(table));
}

}  // namespace dropscope
