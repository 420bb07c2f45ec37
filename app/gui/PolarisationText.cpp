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

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

}  // namespace

std::array<std::string, 5> stokesCells(const std::optional<Polarisation>& light) {
    if (!light) return {"-", "-", "-", "-", "-"};
    const StokesVector& s = light->stokes;
    return {format("%.4g", s[0]), format("%.4g", s[1]), format("%.4g", s[2]), format("%.4g", s[3]),
            format("%.3f", degreeOfLinearPolarisation(s))};
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
    return format("%.1f %% polarised: psi %.1f deg, ", 100.0 * ellipse.degree, degrees(ellipse.orientation)) + shape;
}

std::string referenceText(const Polarisation& light) {
    const Eigen::Vector3d& r = light.reference;
    return format(
        "Stokes vector in the frame of reference (parallel axis) (%.4f, %.4f, %.4f);\n"
        "perpendicular axis = reference x direction",
        r.x(), r.y(), r.z());
}

}  // namespace dropscope::gui
