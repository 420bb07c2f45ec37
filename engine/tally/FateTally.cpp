#include "tally/FateTally.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace dropscope {

void FateTally::score(const Event& event, const TallyContext& photon) {
    switch (event.type) {
    case EventType::Emit: ++photons_; break;
    case EventType::Reflect: ++events_.reflect; break;
    case EventType::Refract: ++events_.refract; break;
    case EventType::Tir: ++events_.tir; break;
    case EventType::Absorb:
        ++events_.absorb;
        ++absorbed_;
        break;
    case EventType::Escape:
        ++escaped_;
        if (!photon.state.metSurface) ++unscattered_;
        break;
    case EventType::Lost:
        ++lost_;
        ++lostReasons_[static_cast<std::size_t>(event.lostReason)];
        if (!firstLost_ || photon.photon < firstLost_->photon) {
            firstLost_ = FirstLost{photon.photon, event.lostReason, event.lostAt, event.position};
        }
        break;
    case EventType::Detect: ++detected_; break;
    case EventType::Diffract: ++events_.diffract; break;
    case EventType::Truncated: break;  // ray trees only
    }
}

void FateTally::writeScores(ScoreWriter& out) const {
    for (const std::uint64_t count : {photons_, escaped_, absorbed_, lost_, detected_, unscattered_}) out.word(count);
    out.words(lostReasons_);
    for (const std::uint64_t count :
         {events_.reflect, events_.refract, events_.tir, events_.absorb, events_.diffract}) {
        out.word(count);
    }
    out.word(firstLost_ ? 1 : 0);
    if (!firstLost_) return;
    out.word(firstLost_->photon);
    out.word(static_cast<std::uint64_t>(firstLost_->reason));
    out.word(firstLost_->shape);
    for (Eigen::Index axis = 0; axis < 3; ++axis) out.real(firstLost_->position[axis]);
}

void FateTally::readScores(ScoreReader& in) {
    for (std::uint64_t* count : {&photons_, &escaped_, &absorbed_, &lost_, &detected_, &unscattered_})
        *count = in.word();
    in.words(lostReasons_);
    for (std::uint64_t* count :
         {&events_.reflect, &events_.refract, &events_.tir, &events_.absorb, &events_.diffract}) {
        *count = in.word();
    }
    firstLost_.reset();
    if (in.word() == 0) return;
    FirstLost first;
    first.photon = in.word();
    const std::uint64_t reason = in.word();
    if (reason >= kLostReasonCount) throw std::runtime_error("fates: lost reason out of range");
    first.reason = static_cast<LostReason>(reason);
    first.shape = static_cast<ShapeId>(in.word());
    for (Eigen::Index axis = 0; axis < 3; ++axis) first.position[axis] = in.real();
    firstLost_ = first;
}

void FateTally::merge(const Tally& other) {
    const FateTally& more = sameTally(*this, other);
    photons_ += more.photons_;
    escaped_ += more.escaped_;
    absorbed_ += more.absorbed_;
    lost_ += more.lost_;
    detected_ += more.detected_;
    unscattered_ += more.unscattered_;
    for (std::size_t i = 0; i < lostReasons_.size(); ++i) lostReasons_[i] += more.lostReasons_[i];
    events_ += more.events_;
    if (more.firstLost_ && (!firstLost_ || more.firstLost_->photon < firstLost_->photon)) firstLost_ = more.firstLost_;
}

LostReason FateTally::mainLostReason() const {
    std::size_t main = 0;
    for (std::size_t reason = 1; reason < kLostReasonCount; ++reason) {
        if (lostReasons_[reason] > lostReasons_[main]) main = reason;
    }
    return static_cast<LostReason>(main);
}

std::optional<std::string> FateTally::lossWarning() const {
    if (lost_ == 0 || !firstLost_) return std::nullopt;
    const LostReason main = mainLostReason();
    char line[512];
    std::snprintf(line, sizeof line,
                  "lost %.3g %% of the photons (%llu of %llu), mostly %s (%s: %llu); the first, photon %llu, ",
                  100.0 * static_cast<double>(lost_) / static_cast<double>(photons_),
                  static_cast<unsigned long long>(lost_), static_cast<unsigned long long>(photons_),
                  std::string(lostReasonMeaning(main)).c_str(), std::string(lostReasonName(main)).c_str(),
                  static_cast<unsigned long long>(lost(main)), static_cast<unsigned long long>(firstLost_->photon));
    std::string text = line;
    if (firstLost_->shape != RayHit::kNone) {
        text += shapeLabel_ ? "on " + shapeLabel_(firstLost_->shape) + " at "
                            : "at shape " + std::to_string(firstLost_->shape) + " ";
    }
    const Point& p = firstLost_->position;
    std::snprintf(line, sizeof line, "(%.6g, %.6g, %.6g), %s", p.x(), p.y(), p.z(),
                  std::string(lostReasonName(firstLost_->reason)).c_str());
    return text + line;
}

void FateTally::report(ResultReport& report) const {
    // Shares of the photons traced; NaN (null in summary.json) when none was.
    const auto share = [&](std::uint64_t count) {
        return photons_ > 0 ? static_cast<double>(count) / static_cast<double>(photons_) : std::nan("");
    };
    report.set({"fractions", "escaped"}, share(escaped_));
    report.set({"fractions", "absorbed"}, share(absorbed_));
    report.set({"fractions", "lost"}, share(lost_));
    report.set({"fractions", "unscattered"}, share(unscattered_));
    report.set({"fractions", "detected"}, share(detected_));
    report.set({"events", "reflect"}, events_.reflect);
    report.set({"events", "refract"}, events_.refract);
    report.set({"events", "tir"}, events_.tir);
    report.set({"events", "absorb"}, events_.absorb);
    report.set({"events", "diffract"}, events_.diffract);
    report.set({"counts", "escaped"}, escaped_);
    report.set({"counts", "absorbed"}, absorbed_);
    report.set({"counts", "lost"}, lost_);
    report.set({"counts", "unscattered"}, unscattered_);
    report.set({"counts", "detected"}, detected_);
    for (std::size_t reason = 0; reason < kLostReasonCount; ++reason) {
        report.set({"lost_reasons", std::string(lostReasonName(static_cast<LostReason>(reason)))},
                   lostReasons_[reason]);
    }
    const std::optional<std::string> warning = lossWarning();
    report.set({"lost_warning"}, warning ? SummaryValue(*warning) : SummaryValue(nullptr));
    if (firstLost_) {
        report.set({"first_lost", "photon"}, firstLost_->photon);
        report.set({"first_lost", "reason"}, std::string(lostReasonName(firstLost_->reason)));
        report.set({"first_lost", "shape"}, firstLost_->shape == RayHit::kNone
                                                ? SummaryValue(nullptr)
                                                : SummaryValue(static_cast<std::uint64_t>(firstLost_->shape)));
        if (shapeLabel_ && firstLost_->shape != RayHit::kNone)
            report.set({"first_lost", "shape_label"}, shapeLabel_(firstLost_->shape));
        report.set({"first_lost", "x"}, firstLost_->position.x());
        report.set({"first_lost", "y"}, firstLost_->position.y());
        report.set({"first_lost", "z"}, firstLost_->position.z());
    }
}

}  // namespace dropscope
