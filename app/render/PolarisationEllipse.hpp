#pragma once

#include "optics/Polarisation.hpp"
#include "render/DrawData.hpp"

namespace dropscope::render {

inline constexpr Colour kEllipseColour{1.0f, 1.0f, 1.0f, 1.0f};         // white: apart from viridis and the marker
inline constexpr Colour kUnpolarisedColour{0.75f, 0.75f, 0.75f, 1.0f};  // light grey: the plane, no field

// Light polarised less than this (degree of polarisation) is drawn, and called, unpolarised: the ellipse
// is drawn at full size whatever the degree, so at 1 % it would overstate how polarised the light is, and
// its orientation comes from Q and U down at their rounding errors as the degree goes to 0.
inline constexpr double kUnpolarisedDegree = 0.01;

// The polarisation ellipse of a Stokes vector (I, Q, U, V) (Bohren and Huffman 1983, sect. 2.11): the
// curve the electric field of its polarised part traces, in its frame (parallel axis = the reference,
// perpendicular axis = reference x k).
struct EllipseShape {
    double degree = 0.0;       // of polarisation, sqrt(Q^2 + U^2 + V^2) / I
    double orientation = 0.0;  // psi = atan2(U, Q) / 2 (rad): the major axis, from the reference towards the
                               // perpendicular axis, in [-pi/2, pi/2]
    double ellipticity = 0.0;  // chi = asin(V / sqrt(Q^2 + U^2 + V^2)) / 2 (rad), in [-pi/4, pi/4]; the axis
                               // ratio b/a is |tan chi|, 0 for linear and 1 for circular light; > 0 right-handed
};

EllipseShape polarisationEllipse(const StokesVector& stokes);

// The polarisation ellipse of `light` travelling along `direction` at `at`, in the plane perpendicular to
// `direction`, in kEllipseColour: semi-major axis `size` along psi, semi-minor axis size |tan chi| (a
// segment for linear light), and a line `size` long along `direction`. Then, in kUnpolarisedColour, the
// circle of radius `size` in that plane, which shows the plane; it is all there is of light polarised less
// than kUnpolarisedDegree (its line along `direction` grey too). Segments in that order: where the
// ellipse of circular light lies on the circle, it wins the depth test.
void addPolarisationEllipse(LineBatch& lines, const Point& at, const Direction& direction, const Polarisation& light,
                            double size);

}  // namespace dropscope::render
