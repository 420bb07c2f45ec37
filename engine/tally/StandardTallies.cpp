#include "tally/StandardTallies.hpp"

#include "tally/AngularTally.hpp"
#include "tally/FateTally.hpp"

namespace dropscope {

TallySet standardTallies(int angularBins, PolarisationModel polarisation) {
    TallySet tallies;
    tallies.add(std::make_unique<FateTally>());
    tallies.add(std::make_unique<AngularTally>(angularBins, polarisation == PolarisationModel::Stokes));
    return tallies;
}

}  // namespace dropscope
