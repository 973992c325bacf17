#pragma once
// ScratchArena: bump allocation for short-lived per-sample objects (BSDFs at each path vertex), reset once per
// camera sample, so the path tracer never touches the heap in its inner loop.
#include <cstddef>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace isotrace {

class ScratchArena {
public:
    explicit ScratchArena(std::size_t bytes = 16 * 1024) : storage_(bytes) {}

    // reset() reuses the memory without running destructors: only for types whose destructor has no effect
    // (BSDFs hold values and references, never owned resources).
    template <class T, class... Args>
    T* make(Args&&... args) {
        std::size_t offset = (used_ + alignof(T) - 1) / alignof(T) * alignof(T);
        if (offset + sizeof(T) > storage_.size()) throw std::bad_alloc();
        used_ = offset + sizeof(T);
        return new (storage_.data() + offset) T(std::forward<Args>(args)...);
    }

    void reset() { used_ = 0; }

private:
    std::vector<std::byte> storage_;
    std::size_t used_ = 0;
};

}  // namespace isotrace
