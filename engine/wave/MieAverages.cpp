#include "scene/JsonPath.hpp"
#include "wave/Mie.hpp"
#include "wave/MieNumerics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dropscope {

namespace {

void addScaled(std::vector<double>& sum, const std::vector<double>& values, double weight) {
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += weight * values[i];
}

// The cloud's average over equally probable size parameters: every efficiency and bin weighted by the
// geometric cross-section (x^2), g by the scattering cross-section (x^2 Q_sca). Each size is computed
// into its own slot (on OpenMP threads) and the slots are summed in order, so the result does not
// depend on the thread count.
MieResult averageOverSizes(std::complex<double> m, const std::vector<double>& sizes, std::size_t bins) {
    if (sizes.size() == 1) return mieSphere(m, sizes.front(), bins);  // exactly the sphere, not x^2 Q / x^2
    // Checked here, not in the threads: an exception must not leave an OpenMP region.
    mieCoefficients(m, sizes.front());
    std::vector<MieResult> each(sizes.size());
    const auto count = static_cast<std::ptrdiff_t>(sizes.size());
#pragma omp parallel for schedule(dynamic)
    for (std::ptrdiff_t i = 0; i < count; ++i) {
        each[static_cast<std::size_t>(i)] = mieSphere(m, sizes[static_cast<std::size_t>(i)], bins);
    }
    MieResult result;
    result.sizes = sizes.size();
    MieAngularBins& sum = result.bins;
    for (auto* column : {&sum.fraction, &sum.s12, &sum.s33, &sum.s34}) column->assign(bins, 0.0);
    MieEfficiencies& q = result.efficiencies;
    double crossSection = 0.0;
    double scattering = 0.0;
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        const double x = sizes[i];
        const double weight = x * x;
        const MieEfficiencies& e = each[i].efficiencies;
        crossSection += weight;
        q.qext += weight * e.qext;
        q.qsca += weight * e.qsca;
        q.qabs += weight * e.qabs;
        q.qback += weight * e.qback;
        scattering += weight * e.qsca;
        q.g += weight * e.qsca * e.g;
        result.xMean += weight * x;
        addScaled(sum.fraction, each[i].bins.fraction, weight);
        addScaled(sum.s12, each[i].bins.s12, weight);
        addScaled(sum.s33, each[i].bins.s33, weight);
        addScaled(sum.s34, each[i].bins.s34, weight);
    }
    const double perCrossSection = 1.0 / crossSection;
    q.qext *= perCrossSection;
    q.qsca *= perCrossSection;
    q.qabs *= perCrossSection;
    q.qback *= perCrossSection;
    q.g = scattering > 0.0 ? q.g / scattering : 0.0;
    result.xMean *= perCrossSection;
    for (auto* column : {&sum.fraction, &sum.s12, &sum.s33, &sum.s34}) {
        for (double& value : *column) value *= perCrossSection;
    }
    return result;
}

// `what` names the size parameter: "lowest size parameter x = 0.0001 is outside 1e-3..2e4".
void requireSizeParameter(double x, const std::string& what, const std::string& verb = " is outside ") {
    if (!(x >= kMinSizeParameter && x <= kMaxSizeParameter)) {
        throw std::invalid_argument(what + " = " + jsonpath::number(x) + verb + "1e-3..2e4");
    }
}

}  // namespace

MieResult mieSphere(std::complex<double> m, double x, std::size_t bins) {
    const MieCoefficients coefficients = mieCoefficients(m, x);
    MieResult result;
    result.efficiencies = mieEfficiencies(coefficients);
    result.bins = mieAngularBins(coefficients, bins);
    result.xMean = x;
    result.sizes = 1;
    return result;
}

MieResult mieAverageOverSizeParameter(std::complex<double> m, double xLo, double xHi, std::size_t count,
                                      std::size_t bins) {
    requireSizeParameter(xLo, "lowest size parameter x");
    requireSizeParameter(xHi, "highest size parameter x");
    if (xHi < xLo) {
        throw std::invalid_argument("size parameter range " + jsonpath::number(xLo) + ".." + jsonpath::number(xHi) +
                                    " is reversed");
    }
    if (count == 0) throw std::invalid_argument("an average over sizes needs at least one size");
    std::vector<double> sizes(count);
    const double step = (xHi - xLo) / static_cast<double>(count);
    for (std::size_t i = 0; i < count; ++i) {
        sizes[i] = std::clamp(xLo + (static_cast<double>(i) + 0.5) * step, xLo, xHi);
    }
    return averageOverSizes(m, sizes, bins);
}

MieResult mieAverageOverSizes(std::complex<double> m, const std::vector<double>& sizes, std::size_t bins) {
    if (sizes.empty()) throw std::invalid_argument("an average over sizes needs at least one size");
    for (double x : sizes) requireSizeParameter(x, "size parameter x");
    return averageOverSizes(m, sizes, bins);
}

std::size_t defaultSizeParameterCount(double xLo, double xHi) {
    const double width = std::abs(xHi - xLo);
    if (!(width >= 0.0) || !std::isfinite(width)) return 1;
    const double count = std::ceil(width / mie::kDefaultSpacing);
    return std::clamp(static_cast<std::size_t>(count), std::size_t{1}, mie::kMaxDefaultSizes);
}

MieResult mieAverageOverRadii(std::complex<double> m, const RadiusDistribution& radii, double wavenumber,
                              std::size_t bins) {
    if (!(wavenumber > 0.0) || !std::isfinite(wavenumber)) {
        throw std::invalid_argument("wavenumber " + jsonpath::number(wavenumber) + " must be finite and > 0");
    }
    // The number of probability midpoints follows the spread of x between the tails (MieNumerics.hpp).
    const double xLow = wavenumber * radii.quantile(mie::kSpreadTail);
    const double xHigh = wavenumber * radii.quantile(1.0 - mie::kSpreadTail);
    std::size_t count = 1;
    if (xHigh > xLow) count = std::max(defaultSizeParameterCount(xLow, xHigh), mie::kMinRadiusSamples);
    std::vector<double> sizes(count);
    for (std::size_t i = 0; i < count; ++i) {
        const double p = (static_cast<double>(i) + 0.5) / static_cast<double>(count);
        const double radius = radii.quantile(p);
        sizes[i] = wavenumber * radius;
        requireSizeParameter(sizes[i], "radius " + jsonpath::number(radius) + " gives size parameter x", ", outside ");
    }
    return averageOverSizes(m, sizes, bins);
}

}  // namespace dropscope
