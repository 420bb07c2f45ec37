#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace dropscope {

// Bytes this process may still allocate: the smaller of its share of the memory the machine has available
// (MemAvailable of /proc/meminfo, or the physical memory where that is missing, divided among the processes
// sharing the machine) and the process's address-space and data limits (ulimit -v, -d). Work that would need
// more is refused up front with its estimate (docs/limits.md).
std::uint64_t availableMemoryBytes();

// The processes of one run on this machine (MPI ranks on one node), which share its available memory; 1
// unless set. Set once, before any estimate.
void shareMachineMemory(int processes);

// "the 1.3 GB this machine has available", or with shared memory "the 1.3 GB this machine has available
// for each of its 3 ranks": how every refusal names what was available.
std::string availableMemoryText(double availableBytes);

// "3.2 GB", "640 MB", "12 kB": decimal units, two or three significant digits.
std::string bytesText(double bytes);

// Peak bytes one generated droplet takes while a scene loads (the sphere, its octree entry, the placement
// grid, the overlap check), measured: `dropscope inspect` of a cloud of 1e6 droplets peaked at 576 MB.
inline constexpr double kGeneratedDropletBytes = 600.0;

// "N droplets need about B to load (...), more than the A this machine has available (docs/limits.md)" when a
// scene of `shapes` shapes cannot take `droplets` generated ones, or nothing.
std::optional<std::string> cloudMemoryProblem(std::size_t shapes, std::size_t droplets);

}  // namespace dropscope
