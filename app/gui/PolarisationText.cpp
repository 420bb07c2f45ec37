#include "gui/PolarisationText.hpp"

#include "render/PolarisationEllipse.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace dropscope::gui {

namespace {

// An axis ratio below this prints as 0.000: the light is called linear.
constexpr double kLinearRatio = 5e-4;

template <class... Values>
std::string format(const char* pattern, Values... values) {
    char text[160];
    std::snprintf(text, sizeof text, pattern, values...);
    return text;
}

// `value` to `decimals` decimals, without the sign of a value that rounds to 0 ("0.0000", not "-0.0000"
// for a rounding error of -1e-17).
std::string fixedText(double value, int decimals) {
    const std::string text = format("%.*f", decimals, value);
    return text.find_first_not_of("-0.") == std::string::npos && text.front() == '-' ? text.substr(1) : text;
}

std::string degreesText(double radians) { return fixedText(radians * 180.0 / std::numbers::pi, 1); }

}  // namespace

std::array<std::string, 5> stokesCells(const std::optional<Polarisation>& light) {
    if (!light) return {"-", "-", "-", "-", "-"};
    const StokesVector& s = light->stokes;
    return {fixedText(s[0], 4), fixedText(s[1], 4), fixedText(s[2], 4), fixedText(s[3], 4),
            fixedText(degreeOfLinearPolarisation(s), 3)};
}

std::string polarisationSummary(const std::optional<Polarisation>& light) {
    if (!light) return "no polarisation: traced with 'none' (Fire panel)";
    const render::EllipseShape ellipse = render::polarisationEllipse(light->stokes);
    if (ellipse.degree < render::kUnpolarisedDegree)
        return format("unpolarised (%.2g %% polarised)", 100.0 * ellipse.degree);
    const double ratio = std::abs(std::tan(ellipse.ellipticity));
    const std::string shape = ratio < kLinearRatio ? std::string("linear")
                                                   : format("b/a %.3f, %s", ratio,
                                                            ellipse.ellipticity > 0.0 ? "right-handed" : "left-handed");
    return format("%.1f %% polarised: psi ", 100.0 * ellipse.degree) + degreesText(ellipse.orientation) + " deg, " +
           shape;
}

std::string referenceText(const Polarisation& light) {
    const Eigen::Vector3d& r = light.reference;
    return format(
        "Stokes vector in the frame of reference (parallel axis) (%.4f, %.4f, %.4f);\n"
        "perpendicular axis = reference x direction",
        r.x(), r.y(), r.z());
}

}  // namespace dropscope::gui
