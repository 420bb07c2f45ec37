#include "tally/BudgetTally.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>

namespace dropscope {

BudgetTally::BudgetTally(const std::vector<Detector>& detectors, std::vector<std::string> media)
    : detectors_(detectors), media_(std::move(media)), absorbedBy_(media_.size(), 0), detectedBy_(detectors.size(), 0) {
    for (std::size_t i = 0; i < detectors_.size(); ++i) {
        if (detectors_[i].type != DetectorType::FarField) continue;
        cameras_.emplace_back(detectors_[i]);
        cameraDetectors_.push_back(i);
    }
    escapedInto_.assign(cameras_.size(), 0);
}

std::unique_ptr<Tally> BudgetTally::emptyCopy() const { return std::make_unique<BudgetTally>(detectors_, media_); }

void BudgetTally::score(const Event& event, const TallyContext&) {
    switch (event.type) {
    case EventType::Emit: ++photons_; return;
    case EventType::Escape:
        for (std::size_t c = 0; c < cameras_.size(); ++c) {
            if (cameras_[c].pixelOf(-event.direction.vector())) {
                ++escapedInto_[c];
                return;
            }
        }
        ++escapedElsewhere_;
        return;
    case EventType::Absorb:
        if (event.from >= absorbedBy_.size()) throw std::logic_error("absorbed in a medium the budget does not know");
        ++absorbedBy_[event.from];
        return;
    case EventType::Detect:
        if (event.detector >= detectedBy_.size()) throw std::logic_error("detected by an unknown detector");
        ++detectedBy_[event.detector];
        return;
    case EventType::Lost: ++lostBy_[static_cast<std::size_t>(event.lostReason)]; return;
    default: return;
    }
}

void BudgetTally::merge(const Tally& other) {
    const BudgetTally& more = sameTally(*this, other);
    if (more.media_ != media_ || more.detectedBy_.size() != detectedBy_.size()) {
        throw std::logic_error("merging budgets of different scenes");
    }
    photons_ += more.photons_;
    escapedElsewhere_ += more.escapedElsewhere_;
    for (std::size_t i = 0; i < escapedInto_.size(); ++i) escapedInto_[i] += more.escapedInto_[i];
    for (std::size_t i = 0; i < absorbedBy_.size(); ++i) absorbedBy_[i] += more.absorbedBy_[i];
    for (std::size_t i = 0; i < detectedBy_.size(); ++i) detectedBy_[i] += more.detectedBy_[i];
    for (std::size_t i = 0; i < lostBy_.size(); ++i) lostBy_[i] += more.lostBy_[i];
}

void BudgetTally::writeScores(ScoreWriter& out) const {
    out.word(photons_);
    out.word(escapedElsewhere_);
    for (const auto* counts : {&escapedInto_, &absorbedBy_, &detectedBy_}) out.words(*counts);
    out.words(lostBy_);
}

void BudgetTally::readScores(ScoreReader& in) {
    photons_ = in.word();
    escapedElsewhere_ = in.word();
    for (auto* counts : {&escapedInto_, &absorbedBy_, &detectedBy_}) in.words(*counts);
    in.words(lostBy_);
}

void BudgetTally::report(ResultReport& report) const {
    const auto put = [&](std::vector<std::string> path, std::uint64_t count) {
        path.insert(path.begin(), "budget");
        path.push_back("count");
        report.set(path, count);
        path.back() = "share";
        report.set(std::move(path),
                   photons_ > 0 ? static_cast<double>(count) / static_cast<double>(photons_) : std::nan(""));
    };
    const auto total = [](const auto& counts) {
        return std::accumulate(counts.begin(), counts.end(), std::uint64_t{0});
    };
    report.set({"budget", "photons"}, photons_);
    put({"escaped"}, escapedElsewhere_ + total(escapedInto_));
    for (std::size_t c = 0; c < cameras_.size(); ++c) {
        put({"escaped", "far_field", detectors_[cameraDetectors_[c]].name}, escapedInto_[c]);
    }
    put({"escaped", "elsewhere"}, escapedElsewhere_);
    put({"absorbed"}, total(absorbedBy_));
    for (std::size_t m = 0; m < media_.size(); ++m) put({"absorbed", "by_medium", media_[m]}, absorbedBy_[m]);
    put({"detected"}, total(detectedBy_));
    for (std::size_t d = 0; d < detectors_.size(); ++d) {
        if (detectors_[d].type == DetectorType::Plane && detectors_[d].absorbing) {
            put({"detected", "by_detector", detectors_[d].name}, detectedBy_[d]);
        }
    }
    put({"lost"}, total(lostBy_));
    for (std::size_t r = 0; r < kLostReasonCount; ++r) {
        put({"lost", "by_reason", std::string(lostReasonName(static_cast<LostReason>(r)))}, lostBy_[r]);
    }
}

}  // namespace dropscope
