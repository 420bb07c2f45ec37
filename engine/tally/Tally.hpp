#pragma once

#include "tally/ResultReport.hpp"
#include "tally/ScoreBytes.hpp"
#include "transport/PhotonObserver.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

namespace dropscope {

// The photon a tally is scoring: its index in the run, its source, and what the tracer knows of it.
struct TallyContext {
    std::uint64_t photon;
    std::size_t source;
    const PhotonState& state;
};

// Something a trace run counts (docs/transport.md, "Tallies"). A tally is told every event of every
// photon (emission, interfaces, absorption, escape or loss) and, if it asks, every flight between
// them (detector crossings); it keeps only what it is for. A run scores photons on several threads
// (later ranks), each into its own empty copy, and merges the copies at the end in no fixed order, so
// a tally's merge must be exact: integer counts, or FixedPointSum for weighted scores. Then the sums
// are the same bits for any thread count. report() states the result in no file format.
class Tally {
public:
    virtual ~Tally() = default;

    // Unique within a run; also the name of the table it reports, if any.
    virtual std::string_view name() const = 0;
    // The same tally (bins, filters) with nothing scored.
    virtual std::unique_ptr<Tally> emptyCopy() const = 0;
    virtual std::unique_ptr<Tally> clone() const = 0;

    virtual void score(const Event& event, const TallyContext& photon) = 0;
    virtual void scoreFlight(const Flight&, const TallyContext&) {}
    virtual bool scoresFlights() const { return false; }

    // Adds the scores of `other`, an emptyCopy() of this tally that was scored separately.
    virtual void merge(const Tally& other) = 0;
    // The scores alone (not the bins or filters), for a run split across processes: readScores on an
    // emptyCopy() of the same tally in another process restores them exactly, and merge() adds them there.
    virtual void writeScores(ScoreWriter& out) const = 0;
    virtual void readScores(ScoreReader& in) = 0;

    virtual void report(ResultReport& report) const = 0;
};

// `other` as the tally type T of `self`, for merge(); a different type is a programming error.
template <class T>
const T& sameTally(const T& self, const Tally& other) {
    const auto* same = dynamic_cast<const T*>(&other);
    if (!same)
        throw std::logic_error("cannot merge tally " + std::string(other.name()) + " into " + std::string(self.name()));
    return *same;
}

}  // namespace dropscope
