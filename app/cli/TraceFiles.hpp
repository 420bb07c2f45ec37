#pragma once

#include "scene/Medium.hpp"
#include "transport/TraceRun.hpp"

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace dropscope {

// What the files of a `dropscope trace` run describe besides the result itself.
struct TraceRunInfo {
    std::string scenePath;  // as given on the command line
    std::size_t sourceCount = 0;
    TraceSettings settings;
};

std::string_view fresnelModelName(FresnelModel model);  // "exact", "schlick"

// summary.json: counts, fractions of the photons traced (null when none was), event counts, and the
// run's settings; keys in docs/cli.md. Numbers are written so they read back exactly.
void writeTraceSummary(const TraceResult& result, const TraceRunInfo& info, std::ostream& out);

// angular.csv: `theta_lo_deg,theta_hi_deg,fraction,fraction_per_sr`, one row per bin of the angle
// between escape and emission directions; fraction of the photons traced, and that over the bin's
// solid angle 2 pi (cos lo - cos hi). Shortest round-trip numbers.
void writeAngularCsv(const TraceTally& tally, std::ostream& out);

// paths.jsonl: one JSON object per recorded photon, with every event; media by name.
void writePathsJsonl(const std::vector<PhotonPath>& paths, const std::vector<Medium>& media, std::ostream& out);

// Writes angular.csv, paths.jsonl and summary.json into `directory`, all three or none
// (writeFilesAtomically): a summary.json is only ever beside the files of the same run.
void writeTraceFiles(const std::filesystem::path& directory, const TraceResult& result, const TraceRunInfo& info,
                     const std::vector<Medium>& media);

}  // namespace dropscope
