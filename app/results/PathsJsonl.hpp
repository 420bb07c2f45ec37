#pragma once

#include "run/TraceRun.hpp"
#include "scene/Medium.hpp"

#include <iosfwd>
#include <vector>

namespace dropscope {

// paths.jsonl: one JSON object per recorded photon, with every event; media by name (docs/cli.md).
void writePathsJsonl(const std::vector<PhotonPath>& paths, const std::vector<Medium>& media, std::ostream& out);

}  // namespace dropscope
