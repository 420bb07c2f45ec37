#pragma once

#include <cstdint>
#include <string>

namespace dropscope {

// Bytes this process may still allocate: the smaller of the memory the machine has available (MemAvailable of
// /proc/meminfo; the physical memory where that is missing) and the process's address-space and data limits
// (ulimit -v, -d). Work that would need more is refused up front with its estimate (docs/limits.md).
std::uint64_t availableMemoryBytes();

// "3.2 GB", "640 MB", "12 kB": decimal units, two or three significant digits.
std::string bytesText(double bytes);

// Peak bytes one generated droplet takes while a scene loads (the sphere, its octree entry, the placement
// grid, the overlap check), measured: `dropscope inspect` of a cloud of 1e6 droplets peaked at 576 MB.
inline constexpr double kGeneratedDropletBytes = 600.0;

}  // namespace dropscope
