#include "scene/RadiusDistribution.hpp"

#include "scene/JsonPath.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dropscope {

namespace {

// c[0] + c[1] x + ... + c[N-1] x^(N-1), by Horner's rule. Products are separate statements
// throughout this file so that a compiler contracting within expressions makes no fused multiply-add,
// whose different rounding would change the radii (docs/scene-format.md, "Reproducibility").
template <std::size_t N>
double polynomial(const std::array<double, N>& c, double x) {
    double sum = 0.0;
    for (std::size_t i = N; i-- > 0;) {
        const double product = sum * x;
        sum = product + c[i];
    }
    return sum;
}

// Wichura, Algorithm AS 241 (PPND16), Applied Statistics 37 (1988) 477-484: rational approximations
// of the standard normal quantile, relative error ~1e-16, on three ranges of p.
constexpr std::array<double, 8> kCentralNumerator{
    3.3871328727963666080e0, 1.3314166789178437745e2, 1.9715909503065514427e3, 1.3731693765509461125e4,
    4.5921953931549871457e4, 6.7265770927008700853e4, 3.3430575583588128105e4, 2.5090809287301226727e3};
constexpr std::array<double, 8> kCentralDenominator{1.0,
                                                    4.2313330701600911252e1,
                                                    6.8718700749205790830e2,
                                                    5.3941960214247511077e3,
                                                    2.1213794301586595867e4,
                                                    3.9307895800092710610e4,
                                                    2.8729085735721942674e4,
                                                    5.2264952788528545610e3};
constexpr std::array<double, 8> kNearNumerator{
    1.42343711074968357734e0, 4.63033784615654529590e0,  5.76949722146069140550e0,  3.64784832476320460504e0,
    1.27045825245236838258e0, 2.41780725177450611770e-1, 2.27238449892691845833e-2, 7.74545014278341407640e-4};
constexpr std::array<double, 8> kNearDenominator{1.0,
                                                 2.05319162663775882187e0,
                                                 1.67638483018380384940e0,
                                                 6.89767334985100004550e-1,
                                                 1.48103976427480074590e-1,
                                                 1.51986665636164571966e-2,
                                                 5.47593808499534494600e-4,
                                                 1.05075007164441684324e-9};
constexpr std::array<double, 8> kFarNumerator{
    6.65790464350110377720e0,  5.46378491116411436990e0,  1.78482653991729133580e0,  2.96560571828504891230e-1,
    2.65321895265761230930e-2, 1.24266094738807843860e-3, 2.71155556874348757815e-5, 2.01033439929228813265e-7};
constexpr std::array<double, 8> kFarDenominator{1.0,
                                                5.99832206555887937690e-1,
                                                1.36929880922735805310e-1,
                                                1.48753612908506148525e-2,
                                                7.86869131145613259100e-4,
                                                1.84631831751005468180e-5,
                                                1.42151175831644588870e-7,
                                                2.04426310338993978564e-15};

// The largest double below 1: probabilities are kept under it so that no quantile is infinite.
constexpr double kBelowOne = 1.0 - 0x1p-53;

}  // namespace

double normalQuantile(double p) {
    const double q = p - 0.5;
    if (std::abs(q) <= 0.425) {
        const double q2 = q * q;
        const double r = 0.180625 - q2;
        return q * polynomial(kCentralNumerator, r) / polynomial(kCentralDenominator, r);
    }
    double r = std::sqrt(-std::log(q < 0.0 ? p : 1.0 - p));
    double z = 0.0;
    if (r <= 5.0) {
        r -= 1.6;
        z = polynomial(kNearNumerator, r) / polynomial(kNearDenominator, r);
    } else {
        r -= 5.0;
        z = polynomial(kFarNumerator, r) / polynomial(kFarDenominator, r);
    }
    return q < 0.0 ? -z : z;
}

// Accurate in the lower tail, where erfc keeps its relative precision.
double normalCdf(double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); }

RadiusDistribution::RadiusDistribution(Kind kind, double location, double spread, double min, double max)
    : kind_(kind), location_(location), spread_(spread), min_(min), max_(max) {}

RadiusDistribution RadiusDistribution::fixed(double value) {
    return RadiusDistribution(Kind::Fixed, value, 0.0, value, value);
}

RadiusDistribution RadiusDistribution::uniform(double min, double max) {
    return RadiusDistribution(Kind::Uniform, min, max - min, min, max);
}

RadiusDistribution RadiusDistribution::lognormal(double median, double sigma, double min, double max) {
    if (sigma == 0.0) {
        if (median < min || median > max) {
            throw std::invalid_argument("[\"min\", \"max\"] excludes the median " + jsonpath::number(median) +
                                        ", the only radius when \"sigma\" is 0");
        }
        return fixed(median);
    }
    RadiusDistribution distribution(Kind::Lognormal, std::log(median), sigma, min, max);
    distribution.truncate();
    return distribution;
}

RadiusDistribution RadiusDistribution::rosinRammler(double scale, double shape, double min, double max) {
    RadiusDistribution distribution(Kind::RosinRammler, scale, shape, min, max);
    distribution.truncate();
    return distribution;
}

double RadiusDistribution::standardOf(double radius) const {
    if (kind_ == Kind::Lognormal) return (std::log(radius) - location_) / spread_;
    return std::pow(radius / location_, spread_);
}

double RadiusDistribution::radiusOf(double standard) const {
    if (kind_ == Kind::Lognormal) {
        const double spreadTimesStandard = spread_ * standard;
        return std::exp(location_ + spreadTimesStandard);  // r = median e^(sigma z)
    }
    return location_ * std::pow(standard, 1.0 / spread_);  // r = X t^(1/q)
}

void RadiusDistribution::truncate() {
    const bool lognormal = kind_ == Kind::Lognormal;
    // Lower-tail CDF F and upper-tail S = 1 - F of the standard variable, each computed directly.
    const auto lowerCdf = [&](double x) { return lognormal ? normalCdf(x) : -std::expm1(-x); };
    const auto upperCdf = [&](double x) { return lognormal ? normalCdf(-x) : std::exp(-x); };
    const double a = standardOf(min_);
    const double b = standardOf(max_);
    const double standardMedian = lognormal ? 0.0 : std::numbers::ln2;
    // A window above the median is taken on S, where its probabilities keep their digits.
    upperTail_ = a > standardMedian;
    windowStart_ = upperTail_ ? upperCdf(b) : lowerCdf(a);
    windowWidth_ = upperTail_ ? upperCdf(a) - upperCdf(b) : lowerCdf(b) - lowerCdf(a);
    if (!(windowWidth_ >= kMinKeptProbability)) {
        throw std::invalid_argument("[\"min\", \"max\"] keeps less than " + jsonpath::number(kMinKeptProbability) +
                                    " of the distribution; check the units of the bounds and of the parameters");
    }
}

double RadiusDistribution::sample(RandomStream& random) const {
    if (kind_ == Kind::Fixed) return location_;
    return quantile(random.openUniform());
}

double RadiusDistribution::quantile(double u) const {
    if (!(u > 0.0 && u < 1.0)) {
        throw std::invalid_argument("probability " + jsonpath::number(u) + " is outside the open interval 0..1");
    }
    if (kind_ == Kind::Fixed) return location_;
    if (kind_ == Kind::Uniform) {
        const double offset = u * spread_;
        return std::clamp(location_ + offset, min_, max_);
    }
    const double offset = u * windowWidth_;
    const double p = std::min(windowStart_ + offset, kBelowOne);
    double standard = 0.0;
    if (kind_ == Kind::Lognormal) {
        standard = upperTail_ ? -normalQuantile(p) : normalQuantile(p);
    } else {
        standard = upperTail_ ? -std::log(p) : -std::log1p(-p);  // t = -ln S = -ln(1 - F)
    }
    // Rounding in exp/pow must not step outside the truncation.
    return std::clamp(radiusOf(standard), min_, max_);
}

}  // namespace dropscope
