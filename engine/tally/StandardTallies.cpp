#include "tally/StandardTallies.hpp"

#include "tally/AngularTally.hpp"
#include "tally/BudgetTally.hpp"
#include "tally/DetectorTallies.hpp"
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

void addDetectorTallies(TallySet& tallies, const Scene& scene, PolarisationModel polarisation) {
    const bool stokes = polarisation == PolarisationModel::Stokes;
    std::vector<std::string> mediumNames;
    for (const Medium& medium : scene.media) mediumNames.push_back(medium.name);
    for (std::size_t i = 0; i < scene.detectors.size(); ++i) {
        const Detector& detector = scene.detectors[i];
        switch (detector.type) {
        case DetectorType::Plane: tallies.add(std::make_unique<PlaneDetectorTally>(detector, i, stokes)); break;
        case DetectorType::FarField: tallies.add(std::make_unique<FarFieldTally>(detector, i, stokes)); break;
        case DetectorType::ShapeAbsorption: {
            std::vector<std::string> names, media;
            for (std::size_t id = 0; id < scene.shapes.size(); ++id) {
                names.push_back(id < scene.shapeNames.size() ? scene.shapeNames[id] : std::string());
                media.push_back(mediumNames.at(scene.shapes[id]->mediumId()));
            }
            tallies.add(std::make_unique<ShapeAbsorptionTally>(detector, i, std::move(names), std::move(media)));
            break;
        }
        }
    }
    tallies.add(std::make_unique<BudgetTally>(scene.detectors, std::move(mediumNames)));
}

}  // namespace dropscope
