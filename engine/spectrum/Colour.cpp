#include "spectrum/Colour.hpp"

#include "spectrum/EmbeddedData.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dropscope {

namespace {

constexpr const char* kCmfFile = "assets/data/cie1931_2deg_cmf.csv";

// The colour-matching functions at whole nanometres from firstNm (docs/spectra.md, "Colour").
struct CmfTable {
    double firstNm = 0.0;
    std::vector<Xyz> values;
};

const CmfTable& cmfTable() {
    // Parsed once, on first use (thread-safe initialisation of a function-local static).
    static const CmfTable table = [] {
        const auto rows = parseNumberTable(embedded::kCie1931Cmf, 4, kCmfFile);
        if (rows.size() < 2) throw std::logic_error(std::string(kCmfFile) + ": fewer than 2 rows");
        CmfTable parsed;
        parsed.firstNm = rows.front()[0];
        for (std::size_t i = 0; i < rows.size(); ++i) {
            // cieColourMatching indexes the table by wavelength: it must step by exactly 1 nm.
            if (rows[i][0] != parsed.firstNm + static_cast<double>(i)) {
                throw std::logic_error(std::string(kCmfFile) + ": wavelengths do not step by 1 nm at row " +
                                       std::to_string(i + 1));
            }
            parsed.values.push_back({rows[i][1], rows[i][2], rows[i][3]});
        }
        return parsed;
    }();
    return table;
}

using Matrix = std::array<std::array<double, 3>, 3>;

Matrix inverse(const Matrix& m) {
    const double a = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    const double b = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    const double c = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    const double determinant = m[0][0] * a + m[0][1] * b + m[0][2] * c;
    return {{{a / determinant, (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / determinant,
              (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / determinant},
             {b / determinant, (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / determinant,
              (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / determinant},
             {c / determinant, (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / determinant,
              (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / determinant}}};
}

Rgb times(const Matrix& m, const Rgb& v) {
    return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

// XYZ (Y = 1) of the chromaticity (x, y).
Rgb xyzOfChromaticity(double x, double y) { return {x / y, 1.0, (1.0 - x - y) / y}; }

// XYZ -> linear sRGB, computed in double precision from what IEC 61966-2-1:1999 defines sRGB by: the
// primaries' chromaticities (those of ITU-R BT.709) and the D65 white's, (0.3127, 0.3290), which (1, 1, 1)
// is. The standard's printed 4-decimal matrices are these rounded (docs/spectra.md, "Colour").
const Matrix& xyzToLinearSrgb() {
    static const Matrix matrix = [] {
        const Rgb red = xyzOfChromaticity(0.64, 0.33);
        const Rgb green = xyzOfChromaticity(0.30, 0.60);
        const Rgb blue = xyzOfChromaticity(0.15, 0.06);
        const Matrix primaries{{{red[0], green[0], blue[0]}, {red[1], green[1], blue[1]}, {red[2], green[2], blue[2]}}};
        // Each primary's amount such that the three add up to the white.
        const Rgb scale = times(inverse(primaries), xyzOfChromaticity(0.3127, 0.3290));
        Matrix linearSrgbToXyz{};
        for (int row = 0; row < 3; ++row) {
            for (int column = 0; column < 3; ++column)
                linearSrgbToXyz[row][column] = primaries[row][column] * scale[column];
        }
        return inverse(linearSrgbToXyz);
    }();
    return matrix;
}

// The linear value of the grey that displayColourOfWavelength gives outside the table.
constexpr double kOutsideTableGrey = 0.3;

}  // namespace

Xyz cieColourMatching(double wavelengthNm) {
    const CmfTable& table = cmfTable();
    const double offset = wavelengthNm - table.firstNm;
    const double last = static_cast<double>(table.values.size() - 1);
    if (!(offset >= 0.0 && offset <= last)) return {};
    const std::size_t i = std::min(static_cast<std::size_t>(offset), table.values.size() - 2);
    const double t = offset - static_cast<double>(i);
    const Xyz& a = table.values[i];
    const Xyz& b = table.values[i + 1];
    return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
}

std::pair<double, double> cieTableRangeNm() {
    const CmfTable& table = cmfTable();
    return {table.firstNm, table.firstNm + static_cast<double>(table.values.size() - 1)};
}

Xyz xyzOfLines(const std::vector<std::pair<double, double>>& linesNm) {
    Xyz sum;
    for (const auto& [nm, power] : linesNm) {
        const Xyz matching = cieColourMatching(nm);
        sum.x += power * matching.x;
        sum.y += power * matching.y;
        sum.z += power * matching.z;
    }
    return sum;
}

Rgb linearSrgbFromXyz(const Xyz& xyz) { return times(xyzToLinearSrgb(), {xyz.x, xyz.y, xyz.z}); }

double srgbEncode(double linear) {
    // IEC 61966-2-1: linear segment below 0.0031308, the offset power law above it.
    linear = std::clamp(linear, 0.0, 1.0);
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

Rgb displaySrgbFromXyz(const Xyz& xyz) {
    // No luminance, no light: black (also for the unphysical, e.g. negative or NaN, which white would colour).
    if (!(xyz.y > 0.0)) return {0.0, 0.0, 0.0};
    Rgb rgb = linearSrgbFromXyz(xyz);
    // Outside the gamut: add equal amounts of every primary (white, D65) until none is negative.
    const double lowest = std::min({rgb[0], rgb[1], rgb[2]});
    if (lowest < 0.0) {
        for (double& component : rgb) component -= lowest;
    }
    const double highest = std::max({rgb[0], rgb[1], rgb[2]});
    if (!(highest > 0.0)) return {0.0, 0.0, 0.0};
    for (double& component : rgb) component = srgbEncode(component / highest);
    return rgb;
}

Rgb exposedSrgb(const Xyz& xyz, double exposure) {
    Rgb rgb = linearSrgbFromXyz({exposure * xyz.x, exposure * xyz.y, exposure * xyz.z});
    for (double& c : rgb) c = srgbEncode(std::clamp(c, 0.0, 1.0));
    return rgb;
}

Rgb displayColourOfWavelength(double wavelengthNm) {
    const auto [lo, hi] = cieTableRangeNm();
    if (!(wavelengthNm >= lo && wavelengthNm <= hi)) {
        const double grey = srgbEncode(kOutsideTableGrey);
        return {grey, grey, grey};
    }
    // A single line lies on the spectrum locus, outside the gamut: its negative components are dropped rather
    // than filled with white, which would turn every red beyond 615 nm pink (docs/spectra.md, "Path colours").
    Rgb rgb = linearSrgbFromXyz(cieColourMatching(wavelengthNm));
    for (double& component : rgb) component = std::max(component, 0.0);
    const double highest = std::max({rgb[0], rgb[1], rgb[2]});
    if (!(highest > 0.0)) return {0.0, 0.0, 0.0};
    for (double& component : rgb) component = srgbEncode(component / highest);
    return rgb;
}

}  // namespace dropscope
