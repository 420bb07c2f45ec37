#include "spectrum/Spectrum.hpp"

#include "spectrum/Decimal.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dropscope {

namespace {

// The blackbody grid starts with this many segments and doubles until the cdf stops changing by more than
// kBlackbodyCdfError (docs/spectra.md, "Spectra", on blackbodies).
constexpr std::size_t kFirstBlackbodySegments = 256;
// Beyond this many segments (16 MB of tables) a blackbody is refused: its emission lies in a band too narrow
// for a uniform grid over [lo, hi] (a body far too cold for the range, e.g. 0.1 K over the visible; 1 K still works).
constexpr std::size_t kMaxBlackbodySegments = std::size_t{1} << 20;

void requireWavelength(double nm, const std::string& what) {
    if (!std::isfinite(nm) || nm <= 0.0) {
        throw std::invalid_argument(what + " must be finite and > 0 nm (got " + shortestDecimal(nm) + ")");
    }
}

void requireRange(double loNm, double hiNm, const std::string& what) {
    requireWavelength(loNm, what + " lo");
    requireWavelength(hiNm, what + " hi");
    if (!(loNm < hiNm)) {
        throw std::invalid_argument(what + " needs lo < hi (" + shortestDecimal(loNm) + " >= " + shortestDecimal(hiNm) +
                                    " nm)");
    }
}

// log(lambda^-5 / expm1(x)), x = hc/(lambda k T), lambda in metres: finite where the density itself under-
// or overflows (a cold body's short wavelengths, x in the hundreds).
double logPlanckDensity(double wavelengthNm, double kelvin) {
    const double metres = wavelengthNm * 1e-9;
    const double x = kSecondRadiationConstant / (metres * kelvin);
    // expm1(x) overflows beyond x ~ 709; log(expm1(x)) = x + log1p(-exp(-x)) there (and is x to rounding).
    const double logExpm1 = x > 30.0 ? x + std::log1p(-std::exp(-x)) : std::log(std::expm1(x));
    return -5.0 * std::log(metres) - logExpm1;
}

// A piecewise-linear density through (grid[i], weight[i]) normalised to integral 1, and its cumulative
// integral at the nodes by the trapezoid rule (exact for it). Both are divided by the same total, so the
// last cumulative value is exactly 1 and trailing segments of zero weight stay at 1.
struct PiecewiseLinear {
    std::vector<double> density;
    std::vector<double> cumulative;
};

PiecewiseLinear normalise(const std::vector<double>& grid, std::vector<double> weights) {
    PiecewiseLinear result;
    result.cumulative.assign(grid.size(), 0.0);
    for (std::size_t i = 1; i < grid.size(); ++i) {
        result.cumulative[i] = result.cumulative[i - 1] + 0.5 * (weights[i - 1] + weights[i]) * (grid[i] - grid[i - 1]);
    }
    const double total = result.cumulative.back();
    for (double& value : result.cumulative) value /= total;
    for (double& value : weights) value /= total;
    result.density = std::move(weights);
    return result;
}

// Planck's density at segments + 1 equally spaced nodes over [lo, hi] (scaled by its largest value there
// before normalising, so that a cold body's tiny values do not underflow), and the nodes.
std::pair<std::vector<double>, PiecewiseLinear> tabulatePlanck(double kelvin, double loNm, double hiNm,
                                                               std::size_t segments) {
    std::vector<double> grid(segments + 1);
    std::vector<double> logDensity(segments + 1);
    for (std::size_t i = 0; i <= segments; ++i) {
        const double t = static_cast<double>(i) / static_cast<double>(segments);
        grid[i] = i == segments ? hiNm : loNm + t * (hiNm - loNm);
        logDensity[i] = logPlanckDensity(grid[i], kelvin);
    }
    const double peak = *std::max_element(logDensity.begin(), logDensity.end());
    std::vector<double> density(segments + 1);
    for (std::size_t i = 0; i <= segments; ++i) density[i] = std::exp(logDensity[i] - peak);
    PiecewiseLinear normalised = normalise(grid, std::move(density));
    return {std::move(grid), std::move(normalised)};
}

}  // namespace

Spectrum Spectrum::line(double wavelengthNm) { return lines({{wavelengthNm, 1.0}}); }

Spectrum Spectrum::lines(std::vector<std::pair<double, double>> linesNm) {
    if (linesNm.empty()) throw std::invalid_argument("a lines spectrum needs at least one line");
    for (const auto& [nm, weight] : linesNm) {
        requireWavelength(nm, "a line's wavelength");
        if (!std::isfinite(weight) || weight <= 0.0) {
            throw std::invalid_argument("a line's weight must be finite and > 0 (got " + shortestDecimal(weight) +
                                        " at " + shortestDecimal(nm) + " nm)");
        }
    }
    Spectrum spectrum(Kind::Lines);
    spectrum.points_ = std::move(linesNm);
    // The distinct wavelengths ascending (so that sample() is monotone in u), repeated lines' weights added.
    std::vector<std::pair<double, double>> sorted = spectrum.points_;
    std::sort(sorted.begin(), sorted.end());
    std::vector<double> weights;
    for (const auto& [nm, weight] : sorted) {
        if (!spectrum.gridNm_.empty() && spectrum.gridNm_.back() == nm) {
            weights.back() += weight;
        } else {
            spectrum.gridNm_.push_back(nm);
            weights.push_back(weight);
        }
    }
    double total = 0.0;
    for (double& weight : weights) {
        total += weight;
        weight = total;
    }
    for (double& partial : weights) partial /= total;
    spectrum.cumulative_ = std::move(weights);
    return spectrum;
}

Spectrum Spectrum::uniform(double loNm, double hiNm) {
    requireRange(loNm, hiNm, "a uniform spectrum");
    Spectrum spectrum(Kind::Uniform);
    spectrum.bounds_ = {loNm, hiNm};
    return spectrum;
}

Spectrum Spectrum::table(std::vector<std::pair<double, double>> pointsNm) {
    if (pointsNm.size() < 2) throw std::invalid_argument("a table spectrum needs at least 2 points");
    bool anyPositive = false;
    for (std::size_t i = 0; i < pointsNm.size(); ++i) {
        const auto& [nm, weight] = pointsNm[i];
        requireWavelength(nm, "a table's wavelength");
        if (i > 0 && !(pointsNm[i - 1].first < nm)) {
            throw std::invalid_argument("a table's wavelengths must be strictly ascending (" +
                                        shortestDecimal(pointsNm[i - 1].first) + " then " + shortestDecimal(nm) +
                                        " nm)");
        }
        if (!std::isfinite(weight) || weight < 0.0) {
            throw std::invalid_argument("a table's weight must be finite and >= 0 (got " + shortestDecimal(weight) +
                                        " at " + shortestDecimal(nm) + " nm)");
        }
        anyPositive = anyPositive || weight > 0.0;
    }
    if (!anyPositive) throw std::invalid_argument("a table spectrum needs a weight > 0");
    Spectrum spectrum(Kind::Table);
    spectrum.points_ = std::move(pointsNm);
    std::vector<double> weights;
    for (const auto& [nm, weight] : spectrum.points_) {
        spectrum.gridNm_.push_back(nm);
        weights.push_back(weight);
    }
    PiecewiseLinear normalised = normalise(spectrum.gridNm_, std::move(weights));
    spectrum.density_ = std::move(normalised.density);
    spectrum.cumulative_ = std::move(normalised.cumulative);
    return spectrum;
}

Spectrum Spectrum::blackbody(double kelvin, double loNm, double hiNm) {
    if (!std::isfinite(kelvin) || kelvin <= 0.0) {
        throw std::invalid_argument("a blackbody's temperature must be finite and > 0 K (got " +
                                    shortestDecimal(kelvin) + ")");
    }
    requireRange(loNm, hiNm, "a blackbody spectrum");
    // Doubling the segments halves h and quarters the piecewise-linear error (~ h^2): once the cdf at the
    // fine grid's nodes moves by less than kBlackbodyCdfError, the finer grid's own error is about a third.
    PiecewiseLinear coarse = tabulatePlanck(kelvin, loNm, hiNm, kFirstBlackbodySegments).second;
    for (std::size_t segments = 2 * kFirstBlackbodySegments;; segments *= 2) {
        if (segments > kMaxBlackbodySegments) {
            throw std::invalid_argument("a blackbody at " + shortestDecimal(kelvin) +
                                        " K emits in too narrow a band of [" + shortestDecimal(loNm) + ", " +
                                        shortestDecimal(hiNm) + "] nm to tabulate");
        }
        auto [grid, fine] = tabulatePlanck(kelvin, loNm, hiNm, segments);
        // Compare at every fine node: the shared ones, and the coarse segments' midpoints, where the coarse
        // cdf is C_k + h (3 f_k + f_k+1) / 8 (a steep tail inside one coarse segment shows only there).
        double change = 0.0;
        for (std::size_t i = 0; i < coarse.cumulative.size(); ++i) {
            change = std::max(change, std::abs(fine.cumulative[2 * i] - coarse.cumulative[i]));
            if (i + 1 < coarse.cumulative.size()) {
                const double h = grid[2 * i + 2] - grid[2 * i];
                const double midpoint =
                    coarse.cumulative[i] + h * (3.0 * coarse.density[i] + coarse.density[i + 1]) / 8.0;
                change = std::max(change, std::abs(fine.cumulative[2 * i + 1] - midpoint));
            }
        }
        if (change < kBlackbodyCdfError) {
            Spectrum spectrum(Kind::Blackbody);
            spectrum.kelvin_ = kelvin;
            spectrum.bounds_ = {loNm, hiNm};
            spectrum.gridNm_ = std::move(grid);
            spectrum.density_ = std::move(fine.density);
            spectrum.cumulative_ = std::move(fine.cumulative);
            return spectrum;
        }
        coarse = std::move(fine);
    }
}

Spectrum Spectrum::sun() {
    Spectrum spectrum = blackbody(kSunKelvin, kSunRangeNm.first, kSunRangeNm.second);
    spectrum.kind_ = Kind::Sun;
    return spectrum;
}

double Spectrum::sample(double u) const {
    u = std::clamp(u, 0.0, 1.0);
    switch (kind_) {
    case Kind::Lines: {
        // The first line whose cumulative probability exceeds u: line i for u in [P(< i), P(<= i)).
        const auto above = std::upper_bound(cumulative_.begin(), cumulative_.end(), u);
        const std::size_t i = std::min<std::size_t>(above - cumulative_.begin(), gridNm_.size() - 1);
        return gridNm_[i];
    }
    case Kind::Uniform: return bounds_.first + u * (bounds_.second - bounds_.first);
    case Kind::Table:
    case Kind::Blackbody:
    case Kind::Sun: break;
    }
    // Segment k with cumulative_[k] <= u < cumulative_[k + 1] (never one of zero probability).
    const auto above = std::upper_bound(cumulative_.begin(), cumulative_.end(), u);
    const std::size_t k = std::clamp<std::size_t>(above - cumulative_.begin(), 1, gridNm_.size() - 1) - 1;
    const double x0 = gridNm_[k];
    const double h = gridNm_[k + 1] - x0;
    const double f0 = density_[k];
    const double slope = density_[k + 1] - f0;
    // The cdf within the segment is cumulative_[k] + h (f0 t + slope t^2 / 2), t in [0, 1]; solve for t with
    // the root written so that nothing cancels: t = 2r / (f0 + sqrt(f0^2 + 2 slope r)), r = (u - C_k) / h.
    const double r = (u - cumulative_[k]) / h;
    const double denominator = f0 + std::sqrt(std::max(0.0, f0 * f0 + 2.0 * slope * r));
    const double t = denominator > 0.0 ? std::clamp(2.0 * r / denominator, 0.0, 1.0) : 0.0;
    return std::min(x0 + t * h, gridNm_[k + 1]);
}

bool Spectrum::drawsRandomNumbers() const { return !(kind_ == Kind::Lines && gridNm_.size() == 1); }

double Spectrum::cdf(double wavelengthNm) const {
    switch (kind_) {
    case Kind::Lines: {
        const auto above = std::upper_bound(gridNm_.begin(), gridNm_.end(), wavelengthNm);
        return above == gridNm_.begin() ? 0.0 : cumulative_[above - gridNm_.begin() - 1];
    }
    case Kind::Uniform: return std::clamp((wavelengthNm - bounds_.first) / (bounds_.second - bounds_.first), 0.0, 1.0);
    case Kind::Table:
    case Kind::Blackbody:
    case Kind::Sun: break;
    }
    if (!(wavelengthNm > gridNm_.front())) return 0.0;
    if (wavelengthNm >= gridNm_.back()) return 1.0;
    const std::size_t k = std::upper_bound(gridNm_.begin(), gridNm_.end(), wavelengthNm) - gridNm_.begin() - 1;
    const double h = gridNm_[k + 1] - gridNm_[k];
    const double t = (wavelengthNm - gridNm_[k]) / h;
    const double within = h * t * (density_[k] + 0.5 * (density_[k + 1] - density_[k]) * t);
    return std::clamp(cumulative_[k] + within, cumulative_[k], cumulative_[k + 1]);
}

std::pair<double, double> Spectrum::rangeNm() const {
    switch (kind_) {
    case Kind::Lines: return {gridNm_.front(), gridNm_.back()};
    case Kind::Uniform:
    case Kind::Blackbody:
    case Kind::Sun: return bounds_;
    case Kind::Table: break;
    }
    // From the last node with nothing below it to the first with everything below it.
    const std::size_t first = std::upper_bound(cumulative_.begin(), cumulative_.end(), 0.0) - cumulative_.begin() - 1;
    const std::size_t last = std::lower_bound(cumulative_.begin(), cumulative_.end(), 1.0) - cumulative_.begin();
    return {gridNm_[first], gridNm_[last]};
}

double planckDensity(double wavelengthNm, double kelvin) {
    const double metres = wavelengthNm * 1e-9;
    const double x = kSecondRadiationConstant / (metres * kelvin);
    return 1.0 / (std::pow(metres, 5) * std::expm1(x));
}

}  // namespace dropscope
