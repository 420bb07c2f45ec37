#include "tree/LargePageAllocator.hpp"

#include <atomic>
#include <cstdint>
#include <limits>

// AddressSanitizer checks only the memory its allocator hands out: under it these arrays come from operator new.
#if defined(__SANITIZE_ADDRESS__)
#define DROPSCOPE_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DROPSCOPE_ADDRESS_SANITIZER 1
#endif
#endif

#if defined(__linux__) && !defined(DROPSCOPE_ADDRESS_SANITIZER)
#include <sys/mman.h>
#include <unistd.h>
#define DROPSCOPE_LARGE_PAGES 1
#endif

namespace dropscope {

namespace {

#ifdef DROPSCOPE_LARGE_PAGES
std::size_t roundUp(std::size_t bytes, std::size_t unit) { return (bytes + unit - 1) / unit * unit; }
#endif

std::atomic<std::size_t> mappedBytes{0};

}  // namespace

#ifdef DROPSCOPE_LARGE_PAGES

// A mapping one huge page longer than needed, trimmed at both ends to the aligned part: the kernel can back
// only whole aligned 2 MiB stretches of a mapping with a huge page.
void* allocateLargePages(std::size_t bytes) {
    if (bytes > std::numeric_limits<std::size_t>::max() / 2) throw std::bad_alloc();
    const std::size_t length = roundUp(bytes, systemPageBytes());
    void* raw = mmap(nullptr, length + kLargePageBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) throw std::bad_alloc();
    const auto start = reinterpret_cast<std::uintptr_t>(raw);
    const std::uintptr_t aligned = roundUp(start, kLargePageBytes);
    if (aligned > start) munmap(raw, aligned - start);
    const std::uintptr_t end = start + length + kLargePageBytes;
    if (end > aligned + length) munmap(reinterpret_cast<void*>(aligned + length), end - (aligned + length));
    madvise(reinterpret_cast<void*>(aligned), length, MADV_HUGEPAGE);  // a hint: refused, the pages stay small
    mappedBytes += length;
    return reinterpret_cast<void*>(aligned);
}

void releaseLargePages(void* memory, std::size_t bytes) noexcept {
    const std::size_t length = roundUp(bytes, systemPageBytes());
    munmap(memory, length);
    mappedBytes -= length;
}

#else

void* allocateLargePages(std::size_t bytes) { return ::operator new (bytes, std::align_val_t{kLargePageBytes}); }

void releaseLargePages(void* memory, std::size_t) noexcept {
    ::operator delete (memory, std::align_val_t{kLargePageBytes});
}

#endif

std::size_t largePageBytesInUse() { return mappedBytes.load(); }

std::size_t systemPageBytes() {
#ifdef DROPSCOPE_LARGE_PAGES
    static const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    return page;
#else
    return 4096;
#endif
}

bool largePagesAdvised() {
#ifdef DROPSCOPE_LARGE_PAGES
    return true;
#else
    return false;
#endif
}

}  // namespace dropscope
