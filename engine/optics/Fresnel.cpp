#include "optics/Fresnel.hpp"

#include <algorithm>
#include <cmath>

namespace dropscope {

namespace {

// cos(theta_t) from Snell's law, or a negative value past the critical angle.
double transmittedCosine(double cosIncidence, double n1, double n2) {
    const double ratio = n1 / n2;
    const double sineSquared = ratio * ratio * (1.0 - cosIncidence) * (1.0 + cosIncidence);
    return sineSquared > 1.0 ? -1.0 : std::sqrt(1.0 - sineSquared);
}

double squared(double x) { return x * x; }

}  // namespace

FresnelReflectance fresnelReflectance(double cosIncidence, double n1, double n2) {
    const FresnelAmplitudes a = fresnelAmplitudes(cosIncidence, n1, n2);
    if (a.totalInternalReflection) return {1.0, 1.0};
    return {std::norm(a.rs), std::norm(a.rp)};
}

FresnelAmplitudes fresnelAmplitudes(double cosIncidence, double n1, double n2, bool totalReflection) {
    FresnelAmplitudes a;
    const double ratio = n1 / n2;
    const double sineTSquared = ratio * ratio * (1.0 - cosIncidence) * (1.0 + cosIncidence);
    if (totalReflection) {
        // rs = (n1 cos i - i n2 g) / (n1 cos i + i n2 g), rp = (n2 cos i - i n1 g) / (n2 cos i + i n1 g)
        const double g = std::sqrt(std::max(sineTSquared - 1.0, 0.0));  // cos(theta_t) = i g
        const std::complex<double> sNumerator(n1 * cosIncidence, -n2 * g);
        const std::complex<double> pNumerator(n2 * cosIncidence, -n1 * g);
        a.rs = sNumerator / std::conj(sNumerator);
        a.rp = pNumerator / std::conj(pNumerator);
        a.totalInternalReflection = true;
        return a;
    }
    const double cosT = std::sqrt(std::max(1.0 - sineTSquared, 0.0));
    const double sDenominator = n1 * cosIncidence + n2 * cosT;
    const double pDenominator = n2 * cosIncidence + n1 * cosT;
    a.rs = (n1 * cosIncidence - n2 * cosT) / sDenominator;
    a.rp = (n2 * cosIncidence - n1 * cosT) / pDenominator;
    a.ts = 2.0 * n1 * cosIncidence / sDenominator;
    a.tp = 2.0 * n1 * cosIncidence / pDenominator;
    a.transmittedPower = n2 * cosT / (n1 * cosIncidence);
    return a;
}

FresnelAmplitudes fresnelAmplitudes(double cosIncidence, double n1, double n2) {
    return fresnelAmplitudes(cosIncidence, n1, n2, transmittedCosine(cosIncidence, n1, n2) < 0.0);
}

double schlickReflectance(double cosIncidence, double n1, double n2) {
    double cosine = cosIncidence;
    if (n1 > n2) {
        cosine = transmittedCosine(cosIncidence, n1, n2);
        if (cosine < 0.0) return 1.0;
    }
    const double r0 = squared((n1 - n2) / (n1 + n2));
    return r0 + (1.0 - r0) * std::pow(1.0 - cosine, 5.0);
}

}  // namespace dropscope
