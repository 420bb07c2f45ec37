#pragma once

#include "tally/Tally.hpp"

#include <memory>
#include <utility>
#include <vector>

namespace dropscope {

// The tallies of one run, in the order they report. Copying copies every tally with its scores.
class TallySet {
public:
    TallySet() = default;
    TallySet(const TallySet& other);
    TallySet& operator=(const TallySet& other);
    TallySet(TallySet&&) noexcept = default;
    TallySet& operator=(TallySet&&) noexcept = default;
    ~TallySet() = default;

    // Throws std::invalid_argument when a tally of the same name is already in the set.
    void add(std::unique_ptr<Tally> tally);
    std::size_t size() const { return tallies_.size(); }

    // The first tally of type T; throws std::logic_error when there is none.
    template <class T>
    const T& get() const {
        if (const T* tally = find<T>()) return *tally;
        throw std::logic_error("the run has no tally of the type asked for");
    }
    template <class T>
    T& get() {
        return const_cast<T&>(std::as_const(*this).template get<T>());
    }
    template <class T>
    const T* find() const {
        for (const auto& tally : tallies_) {
            if (const auto* typed = dynamic_cast<const T*>(tally.get())) return typed;
        }
        return nullptr;
    }

    // Every tally of type T, in order.
    template <class T>
    std::vector<const T*> all() const {
        std::vector<const T*> found;
        for (const auto& tally : tallies_) {
            if (const auto* typed = dynamic_cast<const T*>(tally.get())) found.push_back(typed);
        }
        return found;
    }

    TallySet emptyCopy() const;
    void score(const Event& event, const TallyContext& photon) {
        for (const auto& tally : tallies_) tally->score(event, photon);
    }
    void scoreFlight(const Flight& flight, const TallyContext& photon) {
        for (const auto& tally : flightTallies_) tally->scoreFlight(flight, photon);
    }
    bool scoresFlights() const { return !flightTallies_.empty(); }
    // Merges each tally of `other` (an emptyCopy() of this set) into its own.
    void merge(const TallySet& other);
    // Every tally's scores in order (Tally::writeScores); readScores into an emptyCopy() of the same set.
    void writeScores(ScoreWriter& out) const;
    void readScores(ScoreReader& in);
    // Every tally's report, in order.
    void report(ResultReport& report) const;

private:
    std::vector<std::unique_ptr<Tally>> tallies_;
    std::vector<Tally*> flightTallies_;  // those of tallies_ that score flights
};

}  // namespace dropscope
