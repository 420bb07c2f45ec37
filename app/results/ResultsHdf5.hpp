#pragma once

#include "tally/ResultReport.hpp"

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace dropscope {

// What results.h5 records besides the report.
struct ResultsFileInfo {
    std::string version;    // the root attribute dropscope_version (dropscopeVersion())
    std::string sceneJson;  // the dataset /scene_json: the scene the run traced, as JSON text
    // Summary keys (and groups of keys) left out of /summary: values that differ between runs of the same
    // scene, seed and photon count (on more threads or ranks), which would make their files differ. summary.json
    // keeps them.
    std::vector<std::vector<std::string>> omittedSummaryKeys = {{"seconds"}, {"threads"}, {"ranks"}};
};

// results.h5 (docs/results-format.md): the report's summary, tables and images, the version, seed, photon count
// and scene, as one HDF5 file. The same report and info give the same bytes: no time is recorded, and every
// group lists its members in the order the report has them. Throws std::runtime_error naming the HDF5 call
// that failed.
std::vector<std::byte> resultsHdf5Bytes(const ResultReport& report, const ResultsFileInfo& info);

// Writes resultsHdf5Bytes to `out` (e.g. the stream writeFilesAtomically hands a file's writer).
void writeResultsHdf5(const ResultReport& report, const ResultsFileInfo& info, std::ostream& out);

}  // namespace dropscope
