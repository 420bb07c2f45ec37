#pragma once

#include "tally/TallySet.hpp"
#include "transport/SurfaceCrossing.hpp"

namespace dropscope {

// What `dropscope trace` and the app count: a FateTally and an AngularTally of `angularBins` bins, with
// the Stokes columns when the photons carry polarisation (it must be the run's TransportSettings model).
TallySet standardTallies(int angularBins = 180, PolarisationModel polarisation = PolarisationModel::Stokes);

}  // namespace dropscope
