#include "gui/DetectorImage.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string_view>
#include <variant>

namespace dropscope::gui {

namespace {

const std::vector<double>& numbers(const ResultTable& table, std::string_view name) {
    const ResultColumn* column = table.column(name);
    if (!column) throw std::logic_error("detector table " + table.name + " has no column " + std::string(name));
    return std::get<std::vector<double>>(column->values);
}

// A ResultImage's pixels (top row first) in pixel order, iy * nx + ix with row 0 at the bottom.
std::vector<std::uint8_t> skyByPixel(const ResultImage& sky, const PixelGrid& grid) {
    std::vector<std::uint8_t> rgb(sky.rgb.size());
    const auto row = static_cast<std::ptrdiff_t>(3 * grid.nx);
    for (int iy = 0; iy < grid.ny; ++iy) {
        const auto from = sky.rgb.begin() + static_cast<std::ptrdiff_t>(grid.ny - 1 - iy) * row;
        std::copy(from, from + row, rgb.begin() + static_cast<std::ptrdiff_t>(iy) * row);
    }
    return rgb;
}

}  // namespace

const char* densityName(const Detector& detector) {
    return detector.type == DetectorType::FarField ? "radiance" : "irradiance";
}

const char* densityUnit(const Detector& detector) {
    return detector.type == DetectorType::FarField ? "1/sr" : "1/unit^2";
}

std::optional<DetectorImage> detectorImage(const DetectorTally& tally) {
    const Detector& detector = tally.detector();
    if (detector.type != DetectorType::Plane && detector.type != DetectorType::FarField) return std::nullopt;
    ResultReport report;
    tally.report(report);
    const ResultTable* table = report.table(tally.name());
    if (!table) throw std::logic_error("detector " + detector.name + " reported no table");
    const bool farField = detector.type == DetectorType::FarField;
    DetectorImage image;
    image.detector = detector;
    image.fraction = numbers(*table, "fraction");
    image.density = numbers(*table, farField ? "radiance" : "irradiance");
    const std::vector<double>& a = numbers(*table, farField ? "theta_deg" : "u");
    const std::vector<double>& b = numbers(*table, farField ? "azimuth_deg" : "v");
    for (std::size_t k = 0; k < a.size(); ++k) image.where.push_back({a[k], b[k]});
    for (const ResultImage& sky : report.images()) {
        if (sky.name == tally.name()) image.sky = skyByPixel(sky, detector.pixels);
    }
    for (double value : image.density) {
        if (std::isfinite(value)) image.maxDensity = std::max(image.maxDensity, value);
    }
    image.photons = tally.photons();
    image.hits = tally.hits();
    return image;
}

}  // namespace dropscope::gui
