#pragma once

#include "scene/Scene.hpp"
#include "tally/SpectralAngularTally.hpp"
#include "tally/TallySet.hpp"
#include "transport/SurfaceCrossing.hpp"

#include <optional>

namespace dropscope {

// What `dropscope trace` and the app count: a FateTally and an AngularTally of `angularBins` bins (180 in the
// app), with the Stokes columns when the photons carry polarisation: `polarisation` must be the run's
// TransportSettings model (a Stokes tally given unpolarised photons throws std::logic_error). With
// `wavelengths`, also a SpectralAngularTally of the same angular bins.
TallySet standardTallies(int angularBins, PolarisationModel polarisation,
                         std::optional<WavelengthBins> wavelengths = std::nullopt);

// Adds what the scene's detectors count, one tally per detector in scene order (PlaneDetectorTally,
// FarFieldTally, ShapeAbsorptionTally, with Stokes columns when `polarisation` is Stokes), and the BudgetTally.
void addDetectorTallies(TallySet& tallies, const Scene& scene, PolarisationModel polarisation);

}  // namespace dropscope
