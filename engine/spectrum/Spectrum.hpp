#pragma once

#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace dropscope {

// The wavelengths a source emits (docs/scene-format.md, "Sources"; docs/spectra.md, "Spectra"), as a
// probability distribution of the vacuum wavelength in nm that each photon draws from.
//   lines      (lambda, weight) pairs, weights > 0 (need not sum to 1): lambda_i with probability w_i / sum w;
//   uniform    uniform on [lo, hi];
//   table      a piecewise-linear density through (lambda, weight) points (lambda strictly ascending,
//              weights >= 0, not all 0), 0 outside them;
//   blackbody  Planck's spectral radiance per unit wavelength at `kelvin`, restricted to [lo, hi];
//   sun        the blackbody at kSunKelvin over kSunRangeNm (written back as "sun").
class Spectrum {
public:
    enum class Kind { Lines, Uniform, Table, Blackbody, Sun };

    // One line at 532 nm; Spectrum::line(nm) for another.
    Spectrum() : Spectrum(line(532.0)) {}
    static Spectrum line(double wavelengthNm);
    // Each throws std::invalid_argument naming what is wrong (not where) for empty lists, wavelengths that
    // are not finite and > 0, weights that are not finite, negative or all 0, lo >= hi, kelvin <= 0, ...
    static Spectrum lines(std::vector<std::pair<double, double>> linesNm);
    static Spectrum uniform(double loNm, double hiNm);
    static Spectrum table(std::vector<std::pair<double, double>> pointsNm);
    static Spectrum blackbody(double kelvin, double loNm, double hiNm);
    static Spectrum sun();

    Kind kind() const { return kind_; }

    // The wavelength at cumulative probability u in (0, 1): the inverse of cdf(), a line's wavelength for
    // lines. Monotone in u.
    double sample(double u) const;
    // False for a single line: its photons draw no random number for their wavelength.
    bool drawsRandomNumbers() const;
    // P(lambda <= wavelengthNm).
    double cdf(double wavelengthNm) const;
    // The shortest and the longest wavelength emitted (a single line: both its wavelength).
    std::pair<double, double> rangeNm() const;

    // What the scene file gave, for writing it back.
    const std::vector<std::pair<double, double>>& pointsNm() const { return points_; }  // lines, table
    double kelvin() const { return kelvin_; }
    std::pair<double, double> boundsNm() const { return bounds_; }  // uniform, blackbody, sun

    friend bool operator==(const Spectrum& a, const Spectrum& b) {
        return a.kind_ == b.kind_ && a.points_ == b.points_ && a.kelvin_ == b.kelvin_ && a.bounds_ == b.bounds_;
    }

private:
    // The factories' start (the public default constructor is itself a factory's result).
    explicit Spectrum(Kind kind) : kind_(kind) {}

    Kind kind_ = Kind::Lines;
    std::vector<std::pair<double, double>> points_;
    double kelvin_ = 0.0;
    std::pair<double, double> bounds_{0.0, 0.0};
    // Sampling tables built by the factories (docs/spectra.md, "Spectra"). Lines: the distinct wavelengths,
    // ascending, and the probability of lambda <= each. Table, blackbody, sun: the nodes of a piecewise-linear
    // density (the table's points; a fine grid over bounds_), the density there (normalised: integral 1)
    // and the cumulative probability at each node.
    std::vector<double> gridNm_;
    std::vector<double> density_;
    std::vector<double> cumulative_;
};

// "lines", "uniform", "table", "blackbody", "sun": as scene files and summary.json name them.
inline std::string_view spectrumKindName(Spectrum::Kind kind) {
    switch (kind) {
    case Spectrum::Kind::Lines: return "lines";
    case Spectrum::Kind::Uniform: return "uniform";
    case Spectrum::Kind::Table: return "table";
    case Spectrum::Kind::Blackbody: return "blackbody";
    case Spectrum::Kind::Sun: return "sun";
    }
    return "?";
}

inline constexpr double kSunKelvin = 5778.0;
// The largest error of a blackbody's tabulated cdf (docs/spectra.md, "Spectra"): a thousandth of
// the statistical noise, 1e-4, of a band's share of 1e8 photons (the largest runs), so no run can see it.
inline constexpr double kBlackbodyCdfError = 1e-7;
inline constexpr std::pair<double, double> kSunRangeNm{380.0, 780.0};

// hc/k, the second radiation constant, in m K (CODATA 2018: h, c and k are exact in the 2019 SI).
inline constexpr double kSecondRadiationConstant = 1.438776877e-2;
// Planck's spectral radiance per unit wavelength, up to a constant factor: lambda^-5 / (exp(hc/(lambda k T)) - 1)
// with lambda in metres (B_lambda / 2hc^2, in m^-5).
double planckDensity(double wavelengthNm, double kelvin);

}  // namespace dropscope
