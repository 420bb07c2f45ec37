#include "tally/FateTally.hpp"

#include <cmath>
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
}

void FateTally::readScores(ScoreReader& in) {
    for (std::uint64_t* count : {&photons_, &escaped_, &absorbed_, &lost_, &detected_, &unscattered_})
        *count = in.word();
    in.words(lostReasons_);
    for (std::uint64_t* count :
         {&events_.reflect, &events_.refract, &events_.tir, &events_.absorb, &events_.diffract}) {
        *count = in.word();
    }
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
}

}  // namespace dropscope
