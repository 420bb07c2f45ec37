#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
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

// "N droplets need about B to load (...), more than the A this machine has available (docs/limits.md)" when a
// scene of `shapes` shapes cannot take `droplets` generated ones, or nothing.
std::optional<std::string> cloudMemoryProblem(std::size_t shapes, std::size_t droplets);

}  // namespace dropscope
