#pragma once

#include "run/TraceRun.hpp"
#include "scene/Medium.hpp"
#include "tally/ResultReport.hpp"

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dropscope {

// What the files of a `dropscope trace` run describe besides the result itself.
struct TraceRunInfo {
    std::string scenePath;  // as given on the command line
    std::size_t sourceCount = 0;
    TraceSettings settings;
    double sceneWavelengthNm = 0.0;      // 0: not reported
    std::vector<Source> sources = {};    // their spectra and divergences are reported (none: not reported)
    std::string sceneJson = {};          // the scene file's text, kept in results.h5
    std::optional<double> maxLost = {};  // trace --max-lost, reported as max_lost (null without it)
};

std::string_view fresnelModelName(FresnelModel model);  // "exact", "schlick"

// Everything a run reports: the run's own values (version, photons, seed, threads, seconds, photons_requested,
// partial, scene, fresnel, polarisation, max_events, paths, sources, wavelength_nm, spectra) and then every
// tally's report.
ResultReport traceReport(const TraceResult& result, const TraceRunInfo& info);

// summary.json: the report's summary, keys in the order docs/cli.md gives them, then any others.
void writeTraceSummary(const ResultReport& report, std::ostream& out);

// The files writeTraceFiles writes for runs with these tallies, in the order docs/cli.md names them:
// summary.json, one NAME.csv per table they report, one NAME.png per image, paths.jsonl, results.h5.
std::vector<std::string> traceFileNames(const TallySet& tallies);

// Writes every file of traceFileNames into `directory`, all or none (writeFilesAtomically): a
// summary.json is only ever beside the files of the same run. Tables as CSV (writeTableCsv), images as PNG, and
// everything in results.h5 (writeResultsHdf5, docs/results-format.md).
void writeTraceFiles(const std::filesystem::path& directory, const TraceResult& result, const TraceRunInfo& info,
                     const std::vector<Medium>& media);

}  // namespace dropscope
