#pragma once

#include "tree/RayHit.hpp"

#include <iosfwd>
#include <vector>

namespace dropscope {

// Writes the hits of `dropscope query` as CSV: the header `ray,shape,distance`, then one line a ray in
// order, `i,shape,distance` with the distance as printf's "%.17g" prints it (it reads back exactly), or
// `i,-1,nan` for a miss. The text is formatted with std::to_chars into a buffer of about a megabyte that goes
// to `out` in one write each time it fills: several million rays a second, docs/performance.md ("Query I/O").
void writeHitCsv(const std::vector<RayHit>& hits, std::ostream& out);

}  // namespace dropscope
