#include "tally/StandardTallies.hpp"

#include "tally/AngularTally.hpp"
#include "tally/FateTally.hpp"

namespace dropscope {

TallySet standardTallies(int angularBins) {
    TallySet tallies;
    tallies.add(std::make_unique<FateTally>());
    tallies.add(std::make_unique<AngularTally>(angularBins));
    return tallies;
}

}  // namespace dropscope
