#pragma once
// Counters bumped on hot paths (ray casts, intersection tests). Each thread increments its own block, so
// counting costs no atomics; totals are summed on demand.
#include <array>
#include <atomic>
#include <cstdint>
#include <map>
#include <string>

namespace isotrace {

enum class RayKind { Camera, Secondary, Shadow };

struct GeometryTypeCounts {
    std::uint64_t tests = 0;         // intersect/occluded callbacks (user geometry only; native triangles: 0)
    std::uint64_t candidate_hits = 0;  // roots accepted inside (t_near, t_far) by a callback
    std::uint64_t closest_hits = 0;    // rays whose final nearest hit is of this type
    bool counts_tests = false;         // false for types whose tests Embree performs internally
};

struct CounterTotals {
    std::uint64_t camera_rays = 0, secondary_rays = 0, shadow_rays = 0;
    std::uint64_t nan_samples = 0;  // radiance samples that were NaN/Inf and were discarded
    std::map<std::string, GeometryTypeCounts> geometry;
    std::map<std::string, std::uint64_t> named;  // plugin-specific work counters ("blobs.pieces", ...)
    std::uint64_t total_rays() const { return camera_rays + secondary_rays + shadow_rays; }
};

namespace counters {

// Registers a geometry type name once (at plugin construction) and returns its slot.
int geometry_type_slot(const std::string& type_name, bool counts_tests);

namespace detail {

inline constexpr int kMaxGeometryTypes = 64;
inline constexpr int kMaxNamedCounters = 1024;  // per-object counters of large scenes share the last slot

// Relaxed atomics written only by the owning thread: plain loads/stores in machine code, yet the progress
// display may read them mid-render without a data race.
using Counter = std::atomic<std::uint64_t>;

struct ThreadBlock {
    Counter rays[3] = {0, 0, 0};
    Counter nan_samples{0};
    std::array<std::array<Counter, 3>, kMaxGeometryTypes> geometry{};  // tests, candidates, closest
    std::array<Counter, kMaxNamedCounters> named{};

    void clear();
};

// A new block, registered for the totals, for a thread that counts for the first time.
ThreadBlock* new_block();

// The calling thread's block: the library's only per-thread state (everything else a query needs travels with
// it, docs/decisions.md). Per thread because a count sits inside a ray's arithmetic, where it must cost a plain
// increment: a shared counter would be an atomic read-modify-write on a cache line every thread writes, and a block
// passed down as an argument would reach every function that counts. Initial-exec TLS and a plain null test: the
// default model of a shared library calls __tls_get_addr and a guarded initialiser on every count, which on the blob
// hot path costs more than the count; __thread rather than thread_local, which other files would reach through a
// wrapper function (docs/decisions.md, "Work counters").
extern __thread ThreadBlock* thread_block __attribute__((tls_model("initial-exec")));

inline ThreadBlock& local_block() {
    if (!thread_block) [[unlikely]] thread_block = new_block();
    return *thread_block;
}

inline void bump(Counter& counter, std::uint64_t amount) {
    counter.store(counter.load(std::memory_order_relaxed) + amount, std::memory_order_relaxed);
}

}  // namespace detail

// Inline: the counts sit in the middle of a ray's arithmetic, where a call spills the caller's vector registers.
// Several at once where rays travel in packets.
inline void count_rays(RayKind kind, std::uint64_t count) { detail::bump(detail::local_block().rays[int(kind)], count); }
inline void count_ray(RayKind kind) { count_rays(kind, 1); }
inline void count_test(int slot) { detail::bump(detail::local_block().geometry[std::size_t(slot)][0], 1); }
inline void count_candidate_hit(int slot) { detail::bump(detail::local_block().geometry[std::size_t(slot)][1], 1); }
inline void count_closest_hit(int slot) { detail::bump(detail::local_block().geometry[std::size_t(slot)][2], 1); }
inline void count_nan_sample() { detail::bump(detail::local_block().nan_samples, 1); }

// Plugin-specific counters: register a name once, then add to its slot from any thread. Names beyond the table's
// 1023 share the slot "counters.overflow". A counter registered with `total_slot` (a slot registered before it) is
// also added into that slot when totals are read: a per-object counter and its type's total are then counted once
// on the hot path, not twice. (A part that lands in the overflow slot no longer reaches its total.)
int named_counter_slot(const std::string& name, int total_slot = -1);
// Adds amounts[i] to slot slots[i] (one lookup of the thread's block for all of them: hot paths count several).
// Inline with a fixed count, unrolled: every blob cell query adds ten, and a call with a loop over spans is a
// visible part of a query's cost (docs/decisions.md, "Work counters").
template <std::size_t N>
void add_to_named(const std::array<int, N>& slots, const std::array<std::uint64_t, N>& amounts) {
    detail::ThreadBlock& block = detail::local_block();
    for (std::size_t i = 0; i < N; ++i) detail::bump(block.named[std::size_t(slots[i])], amounts[i]);
}

CounterTotals totals();
void reset();

}  // namespace counters
}  // namespace isotrace
