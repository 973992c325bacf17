#pragma once
// InlineVector: a vector of trivially copyable values that keeps its first N in place (on the stack, for a local
// variable) and moves to the heap only beyond them — per-query scratch lists of a hot path, without a heap
// allocation in the common case and without per-thread state.
#include <cstddef>
#include <cstring>
#include <new>
#include <memory>
#include <type_traits>
#include <utility>

namespace isotrace {

template <class T, std::size_t N>
class InlineVector {
    static_assert(std::is_trivially_copyable_v<T>, "elements are moved by memcpy");
    static_assert(alignof(T) <= alignof(std::max_align_t), "heap storage is aligned for max_align_t");

public:
    InlineVector() = default;
    InlineVector(const InlineVector&) = delete;
    InlineVector& operator=(const InlineVector&) = delete;

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    T* begin() { return data_; }
    T* end() { return data_ + size_; }
    const T* begin() const { return data_; }
    const T* end() const { return data_ + size_; }
    T& operator[](std::size_t i) { return data_[i]; }
    const T& operator[](std::size_t i) const { return data_[i]; }
    T& back() { return data_[size_ - 1]; }

    void clear() { size_ = 0; }
    // Appends T(args...) built in place and returns it.
    template <class... Args>
    T& emplace_back(Args&&... args) {
        if (size_ == capacity_) grow();
        return *new (data_ + size_++) T(std::forward<Args>(args)...);
    }
    T& push_back(const T& value) { return emplace_back(value); }
    // Room for `count` more values past the end, written by a caller that then keeps them with truncate's
    // counterpart extend_to: an append of a variable number of values without a branch per value.
    T* room_for(std::size_t count) {
        while (size_ + count > capacity_) grow();
        return data_ + size_;
    }
    // Keeps the values written past the end up to `count` in all (count ≤ size() + the room asked for).
    void extend_to(std::size_t count) { size_ = count; }
    // Keeps the first `count` elements.
    void truncate(std::size_t count) {
        if (count < size_) size_ = count;
    }

private:
    void grow() {
        const std::size_t capacity = capacity_ * 2;
        auto heap = std::make_unique_for_overwrite<std::byte[]>(capacity * sizeof(T));
        std::memcpy(heap.get(), static_cast<const void*>(data_), size_ * sizeof(T));
        heap_ = std::move(heap);
        data_ = reinterpret_cast<T*>(heap_.get());
        capacity_ = capacity;
    }

    alignas(T) unsigned char storage_[N * sizeof(T)];
    T* data_ = reinterpret_cast<T*>(storage_);
    std::size_t size_ = 0, capacity_ = N;
    std::unique_ptr<std::byte[]> heap_;
};

}  // namespace isotrace
