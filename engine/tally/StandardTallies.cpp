#include "tally/StandardTallies.hpp"

#include "tally/AngularTally.hpp"
#include "tally/FateTally.hpp"

namespace dropscope {

TallySet standardTallies(int angularBins, PolarisationModel polarisation, std::optional<WavelengthBins> wavelengths) {
    const bool stokes = polarisation == PolarisationModel::Stokes;
    TallySet tallies;
    tallies.add(std::make_unique<FateTally>());
    tallies.add(std::make_unique<AngularTally>(angularBins, stokes));
    if (wavelengths) tallies.add(std::make_unique<SpectralAngularTally>(angularBins, *wavelengths, stokes));
    return tallies;
}

}  // namespace dropscope
