#pragma once

#include <cstddef>
#include <new>

namespace dropscope {

// Arrays of this many bytes or more get memory of their own that the kernel may back with transparent huge
// pages: 2 MiB, the size of one such page on x86-64 (and arm64 with 4 KiB pages), so at least one whole page
// fits. The mappings are aligned to it; elsewhere the advice is only a hint the kernel may ignore.
inline constexpr std::size_t kLargePageBytes = std::size_t{2} << 20;

// Memory for `bytes` (at least kLargePageBytes) aligned to kLargePageBytes, which Linux is asked to back
// with transparent huge pages (madvise MADV_HUGEPAGE; honoured when THP is "always" or "madvise"). Elsewhere,
// and under AddressSanitizer (which checks only memory it allocates), plain operator new. Throws
// std::bad_alloc.
void* allocateLargePages(std::size_t bytes);
void releaseLargePages(void* memory, std::size_t bytes) noexcept;
// The bytes allocateLargePages holds mapped outside the C heap now (0 where it uses operator new), which
// malloc's own statistics do not see: the benchmarks' measure of memory adds them.
std::size_t largePageBytesInUse();
// Whether this build maps and advises them (Linux without AddressSanitizer), rather than using operator new.
bool largePagesAdvised();
// The size of the system's pages, to which those mappings are rounded (sysconf; 4096 where none is made).
std::size_t systemPageBytes();

// The allocator of the octree's arrays that a ray's search reads (cells, sphere blocks, their ids, the exact
// spheres): at 1e6 droplets they span tens of MB, read at random, so with 4 KiB pages nearly every access
// also misses the TLB, whose walk under a hypervisor costs as much as the access (docs/performance.md,
// "Huge pages"). Smaller arrays come from operator new as usual.
template <class T>
struct LargePageAllocator {
    using value_type = T;

    LargePageAllocator() = default;
    template <class U>
    LargePageAllocator(const LargePageAllocator<U>&) noexcept {}  // NOLINT(google-explicit-constructor): rebinding

    T* allocate(std::size_t count) {
        if (count > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
        const std::size_t bytes = count * sizeof(T);
        if (bytes >= kLargePageBytes) return static_cast<T*>(allocateLargePages(bytes));
        return static_cast<T*>(::operator new (bytes, std::align_val_t{alignof(T)}));
    }
    void deallocate(T* memory, std::size_t count) noexcept {
        const std::size_t bytes = count * sizeof(T);
        if (bytes >= kLargePageBytes) {
            releaseLargePages(memory, bytes);
        } else {
            ::operator delete (memory, std::align_val_t{alignof(T)});
        }
    }
    template <class U>
    friend bool operator==(const LargePageAllocator&, const LargePageAllocator<U>&) {
        return true;  // stateless: any one frees what another allocated
    }
};

}  // namespace dropscope
