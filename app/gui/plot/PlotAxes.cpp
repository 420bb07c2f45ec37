#include "gui/plot/PlotAxes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace dropscope::gui::plot {

namespace {

// A tick this close to an end of the range, in steps, is on the axis: the ends are often computed
// (0.1 + 0.2) and must not lose their tick to the last bit.
constexpr double kEdgeSlack = 1e-9;
// Linear labels are fixed-point for steps of at least 10^-3 and values below 10^5, else 1.5e-6.
constexpr int kFixedFinestExponent = -3;
constexpr double kFixedLargest = 1e5;
// Log labels are plain numbers when every decade labelled is within 10^-3 .. 10^4, else 1e-5.
constexpr int kPlainDecadeLow = -3;
constexpr int kPlainDecadeHigh = 4;
// fittedTicks tries at most this many major ticks: beyond it an axis is read no better.
constexpr int kMostMajorTicks = 12;
constexpr std::array<int, 3> kMantissas{1, 2, 5};

bool validRange(AxisRange range) { return std::isfinite(range.lo) && std::isfinite(range.hi) && range.lo < range.hi; }

// 10^p correctly rounded (std::pow need not be); exact for 0 <= p <= 22.
double powerOfTen(int p) { return std::strtod(("1e" + std::to_string(p)).c_str(), nullptr); }

// multiple x 10^p with one rounding, so ticks are the decimals they are labelled (3 x 0.1 gives 0.3,
// not 0.30000000000000004).
double scaled(double multiple, int p) { return p >= 0 ? multiple * powerOfTen(p) : multiple / powerOfTen(-p); }

struct Step {
    int mantissa = 1;
    int exponent = 0;
    double value() const { return scaled(mantissa, exponent); }
};

// The multiples of `step` in [lo, hi]: first and last multiple.
std::pair<double, double> multiples(double lo, double hi, double step) {
    return {std::ceil(lo / step - kEdgeSlack), std::floor(hi / step + kEdgeSlack)};
}

// "1.5e-06" -> "1.5e-6", "1e+02" -> "1e2".
std::string compactExponent(const std::string& text) {
    const std::size_t e = text.find('e');
    if (e == std::string::npos) return text;
    return text.substr(0, e + 1) + std::to_string(std::atoi(text.c_str() + e + 1));
}

std::string formatted(const char* format, int digits, double value) {
    char text[64];
    std::snprintf(text, sizeof text, format, digits, value);
    return text;
}

std::string linearLabel(double value, Step step, bool scientific) {
    if (value == 0.0) return "0";
    if (!scientific) {
        std::string text = formatted("%.*f", std::max(0, -step.exponent), value);
        return text.find_first_not_of("-0.") == std::string::npos ? "0" : text;  // no "-0.0"
    }
    const int magnitude = static_cast<int>(std::floor(std::log10(std::abs(value))));
    return compactExponent(formatted("%.*e", std::max(0, magnitude - step.exponent), value));
}

// The finest 1-2-5 step with at most maxMajor multiples in the range.
Step linearStep(AxisRange range, int maxMajor) {
    Step step{1, static_cast<int>(std::floor(std::log10(range.span() / maxMajor))) - 1};
    for (;; ++step.exponent) {
        for (int mantissa : kMantissas) {
            step.mantissa = mantissa;
            const auto [first, last] = multiples(range.lo, range.hi, step.value());
            if (last - first + 1.0 <= maxMajor) return step;
        }
    }
}

// The k-th of the steps 1, 2, 5, 10, 20, 50, ... (in decades).
int decadeStep(int k) { return kMantissas[static_cast<std::size_t>(k % 3)] * static_cast<int>(powerOfTen(k / 3)); }

int floorDiv(int a, int b) { return a / b - (a % b != 0 && (a < 0) != (b < 0)); }

// Every `decades`-th decade from first to last (multiples of `decades`).
std::vector<int> decadeMultiples(int first, int last, int decades) {
    std::vector<int> exponents;
    for (int e = floorDiv(first + decades - 1, decades) * decades; e <= last; e += decades) exponents.push_back(e);
    return exponents;
}

std::string decadeLabel(int exponent, bool plain) {
    if (!plain) return "1e" + std::to_string(exponent);
    return formatted("%.*f", std::max(0, -exponent), powerOfTen(exponent));
}

// The 2..9 x 10^e in the range, for every e whose decade reaches into it.
void addLogMinorTicks(AxisRange range, std::vector<Tick>& ticks) {
    const int low = static_cast<int>(std::floor(std::log10(range.lo)));
    const int high = static_cast<int>(std::floor(std::log10(range.hi)));
    for (int e = low; e <= high; ++e) {
        for (int m = 2; m <= 9; ++m) {
            const double value = scaled(m, e);
            if (value >= range.lo && value <= range.hi) ticks.push_back({value, "", false});
        }
    }
}

}  // namespace

bool drawable(double value, Scale scale) { return std::isfinite(value) && (scale == Scale::Linear || value > 0.0); }

double AxisMapping::toPixel(double value) const {
    if (!drawable(value, scale)) return std::numeric_limits<double>::quiet_NaN();
    const double t = scale == Scale::Log
                         ? (std::log10(value) - std::log10(range.lo)) / (std::log10(range.hi) - std::log10(range.lo))
                         : (value - range.lo) / range.span();
    return pixelLo + t * (pixelHi - pixelLo);
}

double AxisMapping::toValue(double pixel) const {
    const double t = (pixel - pixelLo) / (pixelHi - pixelLo);
    if (scale == Scale::Linear) return range.lo + t * range.span();
    return std::pow(10.0, std::log10(range.lo) + t * (std::log10(range.hi) - std::log10(range.lo)));
}

std::vector<Tick> linearTicks(AxisRange range, int maxMajor) {
    if (!validRange(range)) return {};
    const Step step = linearStep(range, std::max(maxMajor, 2));
    const auto [first, last] = multiples(range.lo, range.hi, step.value());
    const bool scientific =
        step.exponent < kFixedFinestExponent || std::max(std::abs(range.lo), std::abs(range.hi)) >= kFixedLargest;
    std::vector<Tick> ticks;
    // Counted in ints: far from zero, first + 1 can equal first, but there are at most maxMajor ticks.
    const int count = static_cast<int>(last - first) + 1;
    for (int n = 0; n < count; ++n) {
        const double value = scaled((first + n) * step.mantissa, step.exponent);
        ticks.push_back({value, linearLabel(value, step, scientific), true});
    }
    return ticks;
}

std::vector<Tick> logTicks(AxisRange range, int maxMajor) {
    if (!validRange(range) || range.lo <= 0.0) return {};
    const int first = static_cast<int>(std::ceil(std::log10(range.lo) - kEdgeSlack));
    const int last = static_cast<int>(std::floor(std::log10(range.hi) + kEdgeSlack));
    if (last - first + 1 < 2) return linearTicks(range, maxMajor);
    int k = 0;
    while (decadeMultiples(first, last, decadeStep(k)).size() > static_cast<std::size_t>(std::max(maxMajor, 2))) ++k;
    const int decades = decadeStep(k);
    const std::vector<int> majors = decadeMultiples(first, last, decades);
    const bool plain = majors.front() >= kPlainDecadeLow && majors.back() <= kPlainDecadeHigh;
    std::vector<Tick> ticks;
    for (int e : majors) ticks.push_back({powerOfTen(e), decadeLabel(e, plain), true});
    if (decades == 1) {
        addLogMinorTicks(range, ticks);
    } else {
        for (int e = first; e <= last; ++e) {
            if (e % decades != 0) ticks.push_back({powerOfTen(e), "", false});
        }
    }
    std::sort(ticks.begin(), ticks.end(), [](const Tick& a, const Tick& b) { return a.value < b.value; });
    return ticks;
}

std::vector<Tick> axisTicks(AxisRange range, Scale scale, int maxMajor) {
    return scale == Scale::Log ? logTicks(range, maxMajor) : linearTicks(range, maxMajor);
}

std::vector<Tick> fittedTicks(const AxisMapping& mapping, const std::function<double(const std::string&)>& labelExtent,
                              double gap) {
    for (int maxMajor = kMostMajorTicks; maxMajor > 2; --maxMajor) {
        std::vector<Tick> ticks = axisTicks(mapping.range, mapping.scale, maxMajor);
        bool fits = true;
        const Tick* previous = nullptr;
        for (const Tick& tick : ticks) {
            if (!tick.major) continue;
            if (previous) {
                const double apart = std::abs(mapping.toPixel(tick.value) - mapping.toPixel(previous->value));
                fits = fits && apart >= 0.5 * (labelExtent(previous->label) + labelExtent(tick.label)) + gap;
            }
            previous = &tick;
        }
        if (fits) return ticks;
    }
    return axisTicks(mapping.range, mapping.scale, 2);
}

}  // namespace dropscope::gui::plot
