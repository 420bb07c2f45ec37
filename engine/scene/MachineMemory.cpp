#include "scene/MachineMemory.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace dropscope {

namespace {

// MemAvailable in bytes, or 0 when /proc/meminfo does not say.
std::uint64_t memAvailable() {
    std::ifstream meminfo("/proc/meminfo");
    std::string line;
    while (std::getline(meminfo, line)) {
        std::istringstream fields(line);
        std::string key;
        std::uint64_t kilobytes = 0;
        if (fields >> key >> kilobytes && key == "MemAvailable:") return kilobytes * 1024;
    }
    return 0;
}

std::uint64_t softLimit(int resource) {
    rlimit limit{};
    if (::getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return UINT64_MAX;
    return static_cast<std::uint64_t>(limit.rlim_cur);
}

// The address space the process already uses (the first field of /proc/self/statm, in pages), which counts
// against the address-space limit.
std::uint64_t addressSpaceInUse() {
    std::ifstream statm("/proc/self/statm");
    std::uint64_t pages = 0;
    if (!(statm >> pages)) return 0;
    const long pageSize = ::sysconf(_SC_PAGESIZE);
    return pageSize > 0 ? pages * static_cast<std::uint64_t>(pageSize) : 0;
}

int processesSharing = 1;

}  // namespace

void shareMachineMemory(int processes) { processesSharing = std::max(processes, 1); }

std::string availableMemoryText(double availableBytes) {
    std::string text = "the " + bytesText(availableBytes) + " this machine has available";
    if (processesSharing > 1) text += " for each of its " + std::to_string(processesSharing) + " ranks";
    return text;
}

std::uint64_t availableMemoryBytes() {
    std::uint64_t available = memAvailable();
    if (available == 0) {
        const long pages = ::sysconf(_SC_PHYS_PAGES);
        const long pageSize = ::sysconf(_SC_PAGESIZE);
        available = pages > 0 && pageSize > 0 ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(pageSize)
                                              : UINT64_MAX;
    }
    available /= static_cast<std::uint64_t>(processesSharing);
    const std::uint64_t addressLimit = softLimit(RLIMIT_AS);
    const std::uint64_t inUse = addressSpaceInUse();
    const std::uint64_t addressLeft =
        addressLimit == UINT64_MAX ? UINT64_MAX : (addressLimit > inUse ? addressLimit - inUse : 0);
    return std::min({available, addressLeft, softLimit(RLIMIT_DATA)});
}

std::string bytesText(double bytes) {
    static constexpr const char* kUnits[] = {"bytes", "kB", "MB", "GB", "TB", "PB"};
    std::size_t unit = 0;
    while (bytes >= 1000.0 && unit + 1 < std::size(kUnits)) {
        bytes /= 1000.0;
        ++unit;
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.3g %s", bytes, kUnits[unit]);
    return text;
}

std::optional<std::string> cloudMemoryProblem(std::size_t shapes, std::size_t droplets) {
    const double need = static_cast<double>(shapes + droplets) * kGeneratedDropletBytes;
    const auto available = static_cast<double>(availableMemoryBytes());
    if (need <= available) return std::nullopt;
    return std::to_string(droplets) + " droplets need about " + bytesText(need) + " to load (" +
           bytesText(kGeneratedDropletBytes) + " each, with the scene's other shapes), more than " +
           availableMemoryText(available) + " (docs/limits.md)";
}

}  // namespace dropscope
