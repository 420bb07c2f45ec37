#include "scene/JsonPath.hpp"
#include "wave/Mie.hpp"

#include <cmath>
#include <stdexcept>

namespace dropscope {

MieEfficiencies mieEfficiencies(const MieCoefficients& coefficients) {
    const auto& a = coefficients.a;
    const auto& b = coefficients.b;
    const std::size_t terms = a.size();
    double extinction = 0.0;
    double scattering = 0.0;
    double asymmetry = 0.0;
    std::complex<double> backward{0.0, 0.0};
    for (std::size_t i = 0; i < terms; ++i) {
        const double n = static_cast<double>(i + 1);
        const double weight = 2.0 * n + 1.0;
        extinction += weight * (a[i].real() + b[i].real());
        scattering += weight * (std::norm(a[i]) + std::norm(b[i]));
        const double sign = (i + 1) % 2 == 0 ? 1.0 : -1.0;  // (-1)^n
        backward += (weight * sign) * (a[i] - b[i]);
        // g Q_sca x^2 / 4 (B&H p. 120): n(n+2)/(n+1) Re(a_n a*_(n+1) + b_n b*_(n+1)) + (2n+1)/(n(n+1)) Re(a_n b*_n)
        if (i + 1 < terms) {
            const std::complex<double> pairs = a[i] * std::conj(a[i + 1]) + b[i] * std::conj(b[i + 1]);
            asymmetry += n * (n + 2.0) / (n + 1.0) * pairs.real();
        }
        asymmetry += weight / (n * (n + 1.0)) * (a[i] * std::conj(b[i])).real();
    }
    const double x2 = coefficients.x * coefficients.x;
    MieEfficiencies result;
    result.qext = 2.0 / x2 * extinction;  // B&H eq. 4.62
    result.qsca = 2.0 / x2 * scattering;  // B&H eq. 4.61
    result.qabs = result.qext - result.qsca;
    result.qback = std::norm(backward) / x2;  // B&H eq. 4.82
    result.g = result.qsca > 0.0 ? 4.0 / (x2 * result.qsca) * asymmetry : 0.0;
    return result;
}

MieAmplitudes mieAmplitudes(const MieCoefficients& coefficients, double cosTheta) {
    if (!(cosTheta >= -1.0 && cosTheta <= 1.0)) {
        throw std::invalid_argument("cos theta = " + jsonpath::number(cosTheta) + " is outside -1..1");
    }
    // pi_n and tau_n by upward recurrence (B&H eq. 4.47): pi_0 = 0, pi_1 = 1,
    // pi_n = (2n-1)/(n-1) mu pi_(n-1) - n/(n-1) pi_(n-2), tau_n = n mu pi_n - (n+1) pi_(n-1).
    double piPrevious = 0.0;
    double pi = 1.0;
    MieAmplitudes result{{0.0, 0.0}, {0.0, 0.0}};
    for (std::size_t i = 0; i < coefficients.a.size(); ++i) {
        const double n = static_cast<double>(i + 1);
        const double tau = n * cosTheta * pi - (n + 1.0) * piPrevious;
        const double weight = (2.0 * n + 1.0) / (n * (n + 1.0));
        // S1 and S2 (B&H eq. 4.74)
        result.s1 += weight * (coefficients.a[i] * pi + coefficients.b[i] * tau);
        result.s2 += weight * (coefficients.a[i] * tau + coefficients.b[i] * pi);
        const double piNext = ((2.0 * n + 1.0) * cosTheta * pi - (n + 1.0) * piPrevious) / n;
        piPrevious = pi;
        pi = piNext;
    }
    return result;
}

MieMueller mieMueller(const MieAmplitudes& amplitudes) {
    const double s1Squared = std::norm(amplitudes.s1);
    const double s2Squared = std::norm(amplitudes.s2);
    const std::complex<double> product = amplitudes.s1 * std::conj(amplitudes.s2);
    // B&H eq. 4.77: S33 = Re(S1 S2*), S34 = Im(S2 S1*) = -Im(S1 S2*)
    return {0.5 * (s1Squared + s2Squared), 0.5 * (s2Squared - s1Squared), product.real(), -product.imag()};
}

}  // namespace dropscope
