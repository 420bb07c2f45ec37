#pragma once

// Runs with the scene's detectors and the ray orders (what `dropscope trace --orders` counts), and reading
// their results back from the run's report (docs/validation.md, "Detectors and ray orders").

#include "ValidationRuns.hpp"

#include "tally/DetectorTallies.hpp"
#include "tally/OrderTally.hpp"

#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace dropscope::validation {

// Angular bins of the runs' AngularTally and OrderTally: 1 degree, as `dropscope trace` writes by default.
constexpr int kDetectorRunBins = 180;

// `photons` photons of `scene` (seed 1) counted by standardTallies, the scene's detectors and the OrderTally.
inline TraceResult traceDetectors(const Scene& scene, std::uint64_t photons,
                                  PolarisationModel polarisation = PolarisationModel::None, int threads = 0) {
    TraceSettings settings;
    settings.photons = photons;
    settings.seed = 1;
    settings.threads = threads;
    settings.transport.polarisation = polarisation;
    TallySet tallies = standardTallies(kDetectorRunBins, polarisation);
    addDetectorTallies(tallies, scene, polarisation);
    tallies.add(std::make_unique<OrderTally>(kDetectorRunBins));
    return runTrace(OpticalScene(scene), scene.sources, settings, tallies);
}

inline ResultReport reportOf(const TraceResult& result) {
    ResultReport report;
    result.tallies.report(report);
    return report;
}

inline const ResultTable& tableOf(const ResultReport& report, const std::string& name) {
    const ResultTable* table = report.table(name);
    if (table == nullptr) throw std::logic_error("the run reported no table " + name);
    return *table;
}

// Column `name` of `table` as values of type T (std::uint64_t, double or std::string).
template <class T>
const std::vector<T>& columnOf(const ResultTable& table, const std::string& name) {
    for (const ResultColumn& column : table.columns) {
        if (column.name == name) return std::get<std::vector<T>>(column.values);
    }
    throw std::logic_error(table.name + " has no column " + name);
}

// A count of the summary, e.g. {"detectors", "screen", "hits"}.
inline std::uint64_t summaryCount(const ResultReport& report, const std::vector<std::string>& path) {
    const SummaryValue* value = report.find(path);
    if (value == nullptr) throw std::logic_error("the run reported no " + path.back());
    return std::get<std::uint64_t>(*value);
}

}  // namespace dropscope::validation
