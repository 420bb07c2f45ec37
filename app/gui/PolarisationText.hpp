#pragma once

#include "optics/Polarisation.hpp"

#include <array>
#include <optional>
#include <string>

namespace dropscope::gui {

// The path inspector's words and numbers for the polarisation an event leaves with (PathPanel.cpp).

// I, Q, U, V (4 decimals: a Monte Carlo photon's I is 1) and the degree of linear polarisation (3), as the
// event table shows them; "-" each when the trace carried no polarisation.
std::array<std::string, 5> stokesCells(const std::optional<Polarisation>& light);

// What the polarisation ellipse drawn at the event shows: "unpolarised" (below
// render::kUnpolarisedDegree), else how polarised and the ellipse's orientation psi from the reference,
// its axis ratio b/a and handedness ("87.3 % polarised: psi 12.3 deg, b/a 0.070, right-handed", or
// "..., linear"); or that the trace carried no polarisation.
std::string polarisationSummary(const std::optional<Polarisation>& light);

// The frame the Stokes vector is given in: its reference (parallel) axis.
std::string referenceText(const Polarisation& light);

}  // namespace dropscope::gui
