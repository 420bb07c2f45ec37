#pragma once

#include "scene/RandomStream.hpp"

#include <limits>

namespace dropscope {

// The radii of a droplet cloud (docs/scene-format.md, "Radius distributions"). Every sample is one
// inverse-CDF evaluation of one RandomStream::openUniform(), so a truncated distribution costs no
// rejection loop, and the same stream gives the same radii for the same libm.
class RadiusDistribution {
public:
    static constexpr double kUnbounded = std::numeric_limits<double>::infinity();
    // A truncation must keep at least this probability of the untruncated distribution: below it the
    // bounds are almost surely a mistake (units), and the inverse CDF would lose digits.
    static constexpr double kMinKeptProbability = 1e-6;

    // Every radius is `value` (> 0).
    static RadiusDistribution fixed(double value);
    // Uniform in radius on [min, max], 0 < min < max.
    static RadiusDistribution uniform(double min, double max);
    // ln r normal with mean ln(median) and standard deviation sigma >= 0, truncated to [min, max].
    static RadiusDistribution lognormal(double median, double sigma, double min = 0.0, double max = kUnbounded);
    // Weibull in radius by count: P(R <= r) = 1 - exp(-(r/scale)^shape), truncated to [min, max].
    static RadiusDistribution rosinRammler(double scale, double shape, double min = 0.0, double max = kUnbounded);

    // quantile(u) of one RandomStream::openUniform() draw u; a fixed distribution draws nothing.
    double sample(RandomStream& random) const;
    // The radius below which a share p (0 < p < 1) of the radii fall, under the truncation: the inverse CDF
    // that sample() evaluates, so sample() == quantile(the same draw) bit for bit.
    double quantile(double p) const;

    // Bounds every sample honours (min 0 and max infinity when not truncated).
    double min() const { return min_; }
    double max() const { return max_; }

private:
    enum class Kind { Fixed, Uniform, Lognormal, RosinRammler };

    RadiusDistribution(Kind kind, double location, double spread, double min, double max);
    // Standard variable x of the radius (z of a lognormal, t = (r/scale)^shape of a Rosin-Rammler).
    double standardOf(double radius) const;
    double radiusOf(double standard) const;
    // Fixes the probability window [windowStart_, windowStart_ + windowWidth_] that the truncation
    // keeps, on the lower-tail CDF or, for bounds above the median, on the upper-tail one.
    void truncate();

    Kind kind_;
    double location_;  // value, min, log(median), or scale
    double spread_;    // 0, max - min, sigma, or shape
    double min_;
    double max_;
    bool upperTail_ = false;
    double windowStart_ = 0.0;
    double windowWidth_ = 1.0;
};

// The standard normal distribution behind the lognormal: Phi^-1(p) for 0 < p < 1 by Wichura's
// AS 241 (relative error ~1e-16), and Phi(z) = erfc(-z / sqrt 2) / 2.
double normalQuantile(double p);
double normalCdf(double z);

}  // namespace dropscope
