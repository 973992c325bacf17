#pragma once
// isotrace::parallel_for: every parallel loop of isotrace. Exactly tbb::parallel_for (same ranges, grain sizes and
// partitioners, so work is split as before and images stay bit-identical); only under -fsanitize=thread does it
// also tell ThreadSanitizer about the fork and the join that happen inside Debian's uninstrumented TBB
// (thread_sanitizer.h).
#include <atomic>
#include <concepts>
#include <utility>

#include <tbb/parallel_for.h>

#include "renderer/core/thread_sanitizer.h"

namespace isotrace {

#ifdef ISOTRACE_THREAD_SANITIZER
namespace parallel_for_detail {

// The body TBB copies into its tasks and hands between threads: only a pointer to the loop on the caller's stack.
// Its copies and the read in each chunk are relaxed atomics, because TBB orders them inside libtbb where TSan
// cannot see it; everything else the chunk reads comes after the loop's acquire.
template <class Body>
class LoopPointer {
public:
    explicit LoopPointer(const AnnouncedLoop<Body>& loop) { std::atomic_ref(loop_).store(&loop, kRelaxed); }
    LoopPointer(const LoopPointer& other) { std::atomic_ref(loop_).store(other.get(), kRelaxed); }
    LoopPointer& operator=(const LoopPointer&) = delete;

    template <class Range>
    void operator()(const Range& range) const {
        (*get())(range);
    }

private:
    static constexpr std::memory_order kRelaxed = std::memory_order_relaxed;
    const AnnouncedLoop<Body>* get() const { return std::atomic_ref(loop_).load(kRelaxed); }

    // No initialiser: that would be a plain store, racing (for TSan) with the atomic loads of an earlier task
    // that TBB ran in the same memory. mutable: atomic_ref needs a non-const object, even to load.
    mutable const AnnouncedLoop<Body>* loop_;
};

}  // namespace parallel_for_detail
#endif

namespace parallel_for_detail {

struct ParallelFor {
    // f(i) for every i in [first, last), like tbb::parallel_for(first, last, f) (auto_partitioner, grain size 1).
    template <std::integral Index, class Function>
        requires std::invocable<const Function&, Index>
    void operator()(Index first, Index last, const Function& f) const {
#ifdef ISOTRACE_THREAD_SANITIZER
        const AnnouncedLoop<Function> loop(f);
        loop.fork();
        tbb::parallel_for(first, last, loop);  // TBB keeps a reference to loop (parallel_for_body_wrapper)
#else
        tbb::parallel_for(first, last, f);
#endif
    }

    // body(subrange) over a split of range, like tbb::parallel_for(range, body[, partitioner]).
    template <class Range, class Body, class... Partitioner>
        requires std::invocable<const Body&, const Range&>
    void operator()(const Range& range, const Body& body, Partitioner&&... partitioner) const {
#ifdef ISOTRACE_THREAD_SANITIZER
        const AnnouncedLoop<Body> loop(body);
        const LoopPointer<Body> pointer(loop);
        loop.fork();
        tbb::parallel_for(range, pointer, std::forward<Partitioner>(partitioner)...);
#else
        tbb::parallel_for(range, body, std::forward<Partitioner>(partitioner)...);
#endif
    }
};

}  // namespace parallel_for_detail

// A function object, not a function template: a call with a tbb::blocked_range argument would otherwise also find
// tbb::parallel_for by argument-dependent lookup, and TBB's non-variadic overload would win, silently.
inline constexpr parallel_for_detail::ParallelFor parallel_for{};

}  // namespace isotrace
