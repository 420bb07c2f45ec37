#include "optics/Fresnel.hpp"

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
    const double cosT = transmittedCosine(cosIncidence, n1, n2);
    if (cosT < 0.0) return {1.0, 1.0};
    const double s = squared((n1 * cosIncidence - n2 * cosT) / (n1 * cosIncidence + n2 * cosT));
    const double p = squared((n1 * cosT - n2 * cosIncidence) / (n1 * cosT + n2 * cosIncidence));
    return {s, p};
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
