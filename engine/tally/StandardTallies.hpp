#pragma once

#include "tally/TallySet.hpp"

namespace dropscope {

// What `dropscope trace` and the app count: a FateTally and an AngularTally of `angularBins` bins.
TallySet standardTallies(int angularBins = 180);

}  // namespace dropscope
