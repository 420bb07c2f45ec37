#pragma once

#include "cli/SceneSummary.hpp"
#include "scene/Scene.hpp"

#include <iosfwd>

namespace dropscope {

// The human-readable report of `dropscope inspect`: aligned tables, numbers to 6 significant digits.
void writeInspectTables(const Scene& scene, const SceneSummary& summary, std::ostream& out);

// The same as one JSON document (`inspect --json`, keys in docs/scene-format.md); numbers are
// written with every digit needed to read them back exactly.
void writeInspectJson(const Scene& scene, const SceneSummary& summary, std::ostream& out);

}  // namespace dropscope
