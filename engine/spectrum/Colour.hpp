#pragma once

#include <array>
#include <utility>
#include <vector>

namespace dropscope {

// Colour from spectra (docs/spectra.md, "Colour"): the CIE 1931 2-degree colour-matching functions as
// tabulated (assets/data/cie1931_2deg_cmf.csv, with its source), CIE XYZ, linear sRGB with the D65 white
// (IEC 61966-2-1), and the sRGB transfer curve.

struct Xyz {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
};

// xbar, ybar, zbar at `wavelengthNm`: linear between the tabulated 1 nm values, 0 outside the table.
Xyz cieColourMatching(double wavelengthNm);
// The table's range (360, 830).
std::pair<double, double> cieTableRangeNm();

// sum over samples of power * (xbar, ybar, zbar): the XYZ of light made of these (wavelength nm, power) parts.
Xyz xyzOfLines(const std::vector<std::pair<double, double>>& linesNm);

using Rgb = std::array<double, 3>;

// Linear sRGB (D65) of an XYZ colour; components may be negative (outside the gamut) or above 1.
Rgb linearSrgbFromXyz(const Xyz& xyz);
// The sRGB transfer curve, for a linear value in [0, 1].
double srgbEncode(double linear);
// A displayable sRGB colour (components in [0, 1], encoded) of an XYZ colour of any brightness: brought into
// the gamut by adding white (desaturating) until no component is negative, then scaled so the largest
// linear component is 1. Black stays black.
Rgb displaySrgbFromXyz(const Xyz& xyz);
// An image pixel's colour: the linear sRGB of `exposure` * xyz with each component clipped to [0, 1] (negative
// ones, outside the gamut, to 0; overexposed ones to 1), encoded. docs/detectors.md says how far-field images
// choose their exposure.
Rgb exposedSrgb(const Xyz& xyz, double exposure);

// The colour a path of that wavelength is drawn with: cieColourMatching(lambda) in linear sRGB with its
// negative components set to 0 (a spectral colour's nearest hue in the gamut; adding white, as
// displaySrgbFromXyz does, turns deep reds pink), scaled so the largest is 1, encoded. Outside the table: a
// dim grey, so infrared and ultraviolet paths stay visible.
Rgb displayColourOfWavelength(double wavelengthNm);

}  // namespace dropscope
