#pragma once
// An allocator for large, long-lived buffers that are first touched all at once (a film's accumulators): it asks
// the kernel for transparent huge pages, so that zeroing 40 MB takes ~20 page faults instead of ~10,000. On the
// 2-core VM a 4 KiB fault costs several microseconds, which made creating a 512x512 film ~0.1 s of the process.

#include <sys/mman.h>

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>

namespace isotrace {

inline constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

template <class T>
struct HugePageAllocator {
    using value_type = T;

    HugePageAllocator() = default;
    template <class U>
    HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

    T* allocate(std::size_t count) {
        // The size rounded up to whole huge pages must fit a size_t.
        if (count > (std::size_t(-1) - kHugePageBytes) / sizeof(T)) throw std::bad_array_new_length();
        const std::size_t bytes = count * sizeof(T);
        if (bytes < kHugePageBytes) return std::allocator<T>().allocate(count);
        const std::size_t rounded = (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
        void* memory = std::aligned_alloc(kHugePageBytes, rounded);
        if (!memory) throw std::bad_alloc();
        madvise(memory, rounded, MADV_HUGEPAGE);  // advice: where the kernel has no huge pages, ordinary ones serve
        return static_cast<T*>(memory);
    }

    void deallocate(T* memory, std::size_t count) noexcept {
        if (count * sizeof(T) < kHugePageBytes)
            std::allocator<T>().deallocate(memory, count);
        else
            std::free(memory);
    }

    template <class U>
    bool operator==(const HugePageAllocator<U>&) const noexcept {
        return true;
    }
};

}  // namespace isotrace
