#pragma once

#include "run/TraceRun.hpp"

#include <iosfwd>
#include <string>

namespace dropscope {

// "trace: 1234567 / 100000000 photons (1.2%), 2468013 photons/s, 40 s left"
std::string formatProgress(const TraceProgress& progress);

// The progress line of a long run on a terminal: nothing during the first second, then the line
// rewritten in place (\r, padded over the previous one) on every update; finish() shows the final
// count and ends the line, if anything was shown at all. Style::Lines writes whole lines instead, at most
// one every kLineSeconds, for output that may be a log file (an MPI run's rank 0, whose stderr goes
// through mpirun).
class ProgressLine {
public:
    enum class Style { InPlace, Lines };
    static constexpr double kLineSeconds = 10.0;

    explicit ProgressLine(std::ostream& terminal, Style style = Style::InPlace) : terminal_(terminal), style_(style) {}
    void update(const TraceProgress& progress);
    void finish(const TraceProgress& progress);

private:
    void show(const TraceProgress& progress);

    std::ostream& terminal_;
    Style style_;
    double lastShown_ = 0.0;  // Style::Lines: seconds into the run of the last line
    bool shown_ = false;
    std::size_t width_ = 0;  // of the line last shown
};

// True when `err` writes to the process's stderr and that is a terminal: the in-process tests pass
// string streams, which must never see a progress line.
bool isTerminal(const std::ostream& err);

}  // namespace dropscope
