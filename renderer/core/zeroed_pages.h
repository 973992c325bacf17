#pragma once
// A fixed-length array of T on pages fresh from the kernel, for large, long-lived buffers (a film's accumulators).
// The pages arrive zeroed and are not written here: every element starts as all-zero bytes, and the kernel zeroes
// each page where a thread first touches it. A film's pages are so first touched by the render's threads, spread
// over the first pass, instead of all at once by the thread that made the film, and never zeroed twice. Transparent
// huge pages are asked for (a hint the kernel may ignore), so that a 40 MB buffer takes ~20 page faults, not ~10,000.

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>

namespace isotrace {

inline constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

template <class T>
class ZeroedPages {
    // Such objects can begin their lives as the bytes already there.
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);
    static_assert(alignof(T) <= alignof(std::max_align_t));

public:
    ZeroedPages() = default;
    explicit ZeroedPages(std::size_t count) : size_(count) {
        if (count == 0) return;
        // The size rounded up to whole huge pages, plus one for the alignment, must fit a size_t.
        if (count > (std::size_t(-1) - 2 * kHugePageBytes) / sizeof(T)) throw std::bad_array_new_length();
        const std::size_t bytes = count * sizeof(T);
        if (bytes < kHugePageBytes) {
            data_ = static_cast<T*>(std::calloc(count, sizeof(T)));
            if (!data_) throw std::bad_alloc();
            return;
        }
        // Mapped directly: the allocator's large blocks may be reused memory, and a huge page must start on its size.
        mapped_bytes_ = (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
        void* mapping =
            mmap(nullptr, mapped_bytes_ + kHugePageBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (mapping == MAP_FAILED) throw std::bad_alloc();
        const auto start = reinterpret_cast<std::uintptr_t>(mapping);
        const std::uintptr_t aligned = (start + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
        if (aligned > start) munmap(mapping, aligned - start);
        if (const std::uintptr_t tail = start + kHugePageBytes - aligned; tail > 0)
            munmap(reinterpret_cast<void*>(aligned + mapped_bytes_), tail);
        madvise(reinterpret_cast<void*>(aligned), mapped_bytes_, MADV_HUGEPAGE);
        data_ = reinterpret_cast<T*>(aligned);
    }
    ZeroedPages(ZeroedPages&& other) noexcept { swap(other); }
    ZeroedPages& operator=(ZeroedPages&& other) noexcept {
        ZeroedPages(std::move(other)).swap(*this);
        return *this;
    }
    ZeroedPages(const ZeroedPages&) = delete;
    ZeroedPages& operator=(const ZeroedPages&) = delete;
    ~ZeroedPages() {
        if (mapped_bytes_) munmap(data_, mapped_bytes_);
        else std::free(data_);
    }

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    T* data() { return data_; }
    const T* data() const { return data_; }
    T& operator[](std::size_t i) { return data_[i]; }
    const T& operator[](std::size_t i) const { return data_[i]; }
    T* begin() { return data_; }
    T* end() { return data_ + size_; }
    const T* begin() const { return data_; }
    const T* end() const { return data_ + size_; }

private:
    void swap(ZeroedPages& other) noexcept {
        std::swap(data_, other.data_);
        std::swap(size_, other.size_);
        std::swap(mapped_bytes_, other.mapped_bytes_);
    }

    T* data_ = nullptr;
    std::size_t size_ = 0;
    std::size_t mapped_bytes_ = 0;  // 0: from calloc
};

}  // namespace isotrace
