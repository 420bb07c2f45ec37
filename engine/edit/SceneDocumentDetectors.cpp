// The document's detector edits: every detector checked by the loader's rules (checkDetector), names unique.
#include "edit/SceneDocument.hpp"

#include "scene/JsonPath.hpp"

#include <unordered_set>

namespace dropscope {

namespace {

[[noreturn]] void refuse(const std::string& message) { throw EditRefused(message); }

std::string detectorTitle(const Detector& detector) { return "detector " + jsonpath::quoted(detector.name); }

void checkDetectors(const std::vector<Detector>& detectors) {
    std::unordered_set<std::string> names;
    for (const Detector& detector : detectors) {
        try {
            checkDetector(detector);
        } catch (const std::invalid_argument& error) {
            refuse(detectorTitle(detector) + ": " + error.what());
        }
        if (const auto problem = detectorLimitProblem(detector)) refuse(detectorTitle(detector) + ": " + *problem);
        if (!names.insert(detector.name).second) {
            refuse("detector name " + jsonpath::quoted(detector.name) + " is already used");
        }
    }
}

}  // namespace

const Detector& SceneDocument::liveDetector(std::size_t index) const {
    if (index >= detectors().size()) {
        refuse("there is no detector " + std::to_string(index) + " (" + std::to_string(detectors().size()) +
               " detectors)");
    }
    return detectors()[index];
}

void SceneDocument::commitDetectors(std::string label, std::vector<Detector> detectors, bool mergeWithPrevious) {
    checkDetectors(detectors);
    Properties after = properties();
    after.detectors = std::move(detectors);
    checkScale(ScaleExtremes{}, "the detectors", std::nullopt, after);
    if (mergeWithPrevious && redo_.empty() && !undo_.empty() && undo_.back().kind == StepKind::Detectors) {
        setProperties(after);
        undo_.back().after = std::move(after);
        advance(StepKind::Detectors);
        return;
    }
    commitProperties(std::move(label), std::move(after), StepKind::Detectors);
}

void SceneDocument::setDetectors(std::vector<Detector> detectors, bool mergeWithPrevious) {
    commitDetectors("edit detectors", std::move(detectors), mergeWithPrevious);
}

void SceneDocument::addDetector(const Detector& detector) {
    std::vector<Detector> after = detectors();
    after.push_back(detector);
    commitDetectors("add " + detectorTitle(detector), std::move(after), false);
}

void SceneDocument::removeDetector(std::size_t index) {
    const std::string label = "delete " + detectorTitle(liveDetector(index));
    std::vector<Detector> after = detectors();
    after.erase(after.begin() + static_cast<std::ptrdiff_t>(index));
    commitDetectors(label, std::move(after), false);
}

void SceneDocument::setDetector(std::size_t index, const Detector& detector, bool mergeWithPrevious) {
    const std::string label = "edit " + detectorTitle(liveDetector(index));
    std::vector<Detector> after = detectors();
    after[index] = detector;
    commitDetectors(label, std::move(after), mergeWithPrevious);
}

}  // namespace dropscope
