#pragma once

#include <malloc.h>

#include <chrono>
#include <cstddef>

namespace dropscope::bench {

// Bytes the program holds from glibc's malloc right now (all arenas, mmapped blocks included).
inline std::size_t heapInUse() {
    const struct mallinfo2 info = mallinfo2();
    return info.uordblks + info.hblkhd;
}

class Stopwatch {
public:
    Stopwatch() : start_(std::chrono::steady_clock::now()) {}
    double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

private:
    std::chrono::steady_clock::time_point start_;
};

}  // namespace dropscope::bench
