#pragma once

#include "scene/RadiusDistribution.hpp"

#include <complex>
#include <cstddef>
#include <vector>

namespace dropscope {

// Lorenz-Mie scattering by a homogeneous sphere (docs/mie.md): relative index m = (n + i kappa) / n_ambient
// (kappa >= 0 absorbs; time dependence exp(-i omega t) as Bohren & Huffman) and size parameter
// x = 2 pi a n_ambient / lambda. Valid for 1e-3 <= x <= 2e4 (kMinSizeParameter, kMaxSizeParameter).

inline constexpr double kMinSizeParameter = 1e-3;
inline constexpr double kMaxSizeParameter = 2e4;

// a_n and b_n for n = 1 .. N (element n - 1), N = x + 4 x^(1/3) + 2 terms (Wiscombe 1980).
struct MieCoefficients {
    std::complex<double> m;
    double x = 0.0;
    std::vector<std::complex<double>> a;
    std::vector<std::complex<double>> b;
};

// Throws std::invalid_argument for x outside [kMinSizeParameter, kMaxSizeParameter], Re m <= 0 or Im m < 0.
MieCoefficients mieCoefficients(std::complex<double> m, double x);

// Efficiencies (cross-sections over pi a^2) and the asymmetry parameter g = <cos theta>.
struct MieEfficiencies {
    double qext = 0.0;
    double qsca = 0.0;
    double qabs = 0.0;
    double qback = 0.0;
    double g = 0.0;
};
MieEfficiencies mieEfficiencies(const MieCoefficients& coefficients);

// The amplitude scattering functions S1 (perpendicular) and S2 (parallel) at scattering angle theta.
struct MieAmplitudes {
    std::complex<double> s1;
    std::complex<double> s2;
};
MieAmplitudes mieAmplitudes(const MieCoefficients& coefficients, double cosTheta);

// Bohren & Huffman's (4.77): S11 = (|S1|^2 + |S2|^2) / 2, S12 = (|S2|^2 - |S1|^2) / 2, S33 = Re(S1 S2*),
// S34 = Im(S2 S1*). -S12 / S11 is the degree of linear polarisation of scattered unpolarised light.
struct MieMueller {
    double s11 = 0.0;
    double s12 = 0.0;
    double s33 = 0.0;
    double s34 = 0.0;
};
MieMueller mieMueller(const MieAmplitudes& amplitudes);

// The angular distribution in `bins` equal bins of theta over [0, 180] degrees: per bin, the integral of
// S11, S12, S33 and S34 over the bin's solid angle divided by pi x^2, i.e. the power scattered into the
// bin per unit power incident on the geometric cross-section. The `fraction` column adds up to Q_sca.
// The bin integrals are accurate however fast S11 oscillates (period about pi / x): Gauss-Legendre in theta
// with nodes in proportion to x times the bin width (docs/mie.md, "Angular bins"). bins = 0 gives empty columns.
struct MieAngularBins {
    std::vector<double> fraction;  // integral of S11
    std::vector<double> s12;
    std::vector<double> s33;
    std::vector<double> s34;
};
MieAngularBins mieAngularBins(const MieCoefficients& coefficients, std::size_t bins);

// One sphere, or an average over sizes weighted as a cloud's (every quantity weighted by geometric
// cross-section, i.e. per unit power incident on the ensemble's cross-section; g by scattering
// cross-section).
struct MieResult {
    MieEfficiencies efficiencies;
    MieAngularBins bins;
    double xMean = 0.0;     // the size parameter, or its mean weighted by cross-section
    std::size_t sizes = 1;  // how many size parameters were evaluated
};

// bins = 0: the efficiencies alone.
MieResult mieSphere(std::complex<double> m, double x, std::size_t bins);

// Uniform in x over [xLo, xHi] by `count` midpoints (count >= 1, xLo <= xHi, both in the valid range). One
// size (count = 1 or xLo = xHi) gives exactly mieSphere of the midpoint. Sizes run on OpenMP threads, and the
// result does not depend on their number.
MieResult mieAverageOverSizeParameter(std::complex<double> m, double xLo, double xHi, std::size_t count,
                                      std::size_t bins);

// The default count for mieAverageOverSizeParameter: enough to sample the ripple, one size per 0.1 of x, at
// least 1 and at most 1000 (docs/mie.md, "Averages").
std::size_t defaultSizeParameterCount(double xLo, double xHi);

// Over droplets of the given size parameters, one droplet each (a cloud's droplets, or a sample of them; at least
// one, each in the valid range): weighted as above. One size gives exactly mieSphere.
MieResult mieAverageOverSizes(std::complex<double> m, const std::vector<double>& sizes, std::size_t bins);

// Over a cloud's radius distribution (by count), with x = wavenumber * r (wavenumber = 2 pi n_ambient /
// lambda in the radii's unit), sampled at probability midpoints through RadiusDistribution::quantile: one
// per 0.1 of x between its 1e-3 and 1 - 1e-3 quantiles, at least 32; a fixed distribution is one size, exactly
// mieSphere. Throws std::invalid_argument when a sampled radius gives x outside the valid range.
MieResult mieAverageOverRadii(std::complex<double> m, const RadiusDistribution& radii, double wavenumber,
                              std::size_t bins);

}  // namespace dropscope
