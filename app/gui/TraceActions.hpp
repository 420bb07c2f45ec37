#pragma once

#include "gui/AppState.hpp"

namespace dropscope::gui {

// What the Fire and Paths panels and their shortcuts do with traces. Each reports what it did, or why it
// could not, in the status line; none throws.

// Starts the Monte Carlo trace of the fire settings off the UI thread; the last result stays shown
// until the new one arrives.
void fireTrace(AppState& state);
void cancelTrace(AppState& state);
// Traces the selected source's central ray as a ray tree (both branches at every interface).
void fireRayTree(AppState& state);
// Takes a finished trace from the job; traces again when the scene changed under a live trace.
void updateTraces(AppState& state);

// Selects photon `path`'s event `event` (clamped), and the octree traversal of the segment from it.
void selectEvent(TraceState& traces, int path, int event);
void stepEvent(TraceState& traces, int delta);

// The tallies the result views show: the run in progress's so far, else the last finished run's.
struct ShownTallies {
    const TallySet* tallies = nullptr;  // null: none yet
    std::uint64_t photons = 0;          // traced into them
    std::uint64_t requested = 0;
    bool filling = false;  // a run is going on: they fill in as its batches finish
};
ShownTallies shownTallies(const TraceState& traces);

// Drops the results shown and the event selected in them (another scene was opened).
void forgetTraces(TraceState& traces);

}  // namespace dropscope::gui
