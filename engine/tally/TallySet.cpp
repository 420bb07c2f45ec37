#include "tally/TallySet.hpp"

#include <stdexcept>
#include <string>

namespace dropscope {

TallySet::TallySet(const TallySet& other) {
    for (const auto& tally : other.tallies_) add(tally->clone());
}

TallySet& TallySet::operator=(const TallySet& other) {
    if (this != &other) *this = TallySet(other);
    return *this;
}

void TallySet::add(std::unique_ptr<Tally> tally) {
    for (const auto& existing : tallies_) {
        if (existing->name() == tally->name()) {
            throw std::invalid_argument("two tallies named " + std::string(tally->name()));
        }
    }
    if (tally->scoresFlights()) flightTallies_.push_back(tally.get());
    tallies_.push_back(std::move(tally));
}

TallySet TallySet::emptyCopy() const {
    TallySet copy;
    for (const auto& tally : tallies_) copy.add(tally->emptyCopy());
    return copy;
}

void TallySet::merge(const TallySet& other) {
    if (other.tallies_.size() != tallies_.size()) throw std::logic_error("merging tally sets of different runs");
    for (std::size_t i = 0; i < tallies_.size(); ++i) tallies_[i]->merge(*other.tallies_[i]);
}

void TallySet::writeScores(ScoreWriter& out) const {
    out.word(tallies_.size());
    for (const auto& tally : tallies_) tally->writeScores(out);
}

void TallySet::readScores(ScoreReader& in) {
    if (in.word() != tallies_.size()) throw std::runtime_error("tally scores: another run's set of tallies");
    for (const auto& tally : tallies_) tally->readScores(in);
}

void TallySet::report(ResultReport& report) const {
    for (const auto& tally : tallies_) tally->report(report);
}

}  // namespace dropscope
