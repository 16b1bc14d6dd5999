// HugePageAllocator: a std::allocator for large arrays that are read at random places, such as
// the event solver's disk records and calendar slots. It places every allocation of at least
// one huge page (2 MiB on x86-64 Linux) on a huge-page boundary and asks the kernel to back it
// with transparent huge pages (madvise(MADV_HUGEPAGE); on kernels where THP is "madvise", the
// usual default, nothing is backed by huge pages unless asked).
//
// Why: a random access into an array far larger than the TLB's reach (about 8 MiB with 4 KiB
// pages) needs a page-table walk on top of its cache miss. With 2 MiB pages the same TLB
// covers gigabytes. The event solver at N = 1e6 (128 MB of records and slots) gains 15-20 %
// per collision from this; below a few MiB it makes no difference (bench/journal.md, "Prefetching the coming events").
//
// Nothing depends on the advice being followed: where THP is off, or on another system, the
// memory is ordinary memory. Small allocations go to the ordinary operator new.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <limits>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace collide {

inline constexpr std::size_t huge_page_bytes = std::size_t(2) << 20;

template <typename T>
class HugePageAllocator {
public:
    using value_type = T;

    HugePageAllocator() noexcept = default;
    template <typename U>
    HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        // (No object may exceed PTRDIFF_MAX bytes, rounding up to a page included.)
        constexpr std::size_t max_bytes = std::size_t(std::numeric_limits<std::ptrdiff_t>::max()) - huge_page_bytes;
        if (n > max_bytes / sizeof(T)) throw std::bad_array_new_length();
        const std::size_t bytes = n * sizeof(T);
        if (bytes < huge_page_bytes)
            return static_cast<T*>(::operator new(bytes, std::align_val_t(alignof(T))));
        const std::size_t rounded = (bytes + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
        void* p = std::aligned_alloc(huge_page_bytes, rounded);
        if (p == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        madvise(p, rounded, MADV_HUGEPAGE);  // advice only: a refusal changes nothing but speed
#endif
        return static_cast<T*>(p);
    }

    void deallocate(T* p, std::size_t n) noexcept {
        if (n * sizeof(T) < huge_page_bytes) ::operator delete(p, std::align_val_t(alignof(T)));
        else std::free(p);
    }

    template <typename U>
    bool operator==(const HugePageAllocator<U>&) const noexcept { return true; }
    template <typename U>
    bool operator!=(const HugePageAllocator<U>&) const noexcept { return false; }
};

// A vector whose storage, once it reaches 2 MiB, lies on huge pages.
template <typename T>
using HugePageVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace collide
