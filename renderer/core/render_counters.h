#pragma once
// Counters bumped on hot paths (ray casts, intersection tests). Each thread increments its own block, so
// counting costs no atomics; totals are summed on demand.
#include <cstdint>
#include <map>
#include <span>
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

void count_ray(RayKind kind);
void count_test(int slot);
void count_candidate_hit(int slot);
void count_closest_hit(int slot);
void count_nan_sample();

// Plugin-specific counters: register a name once, then add to its slot from any thread. Names beyond the table's
// 1023 share the slot "counters.overflow". A counter registered with `total_slot` (a slot registered before it) is
// also added into that slot when totals are read: a per-object counter and its type's total are then counted once
// on the hot path, not twice. (A part that lands in the overflow slot no longer reaches its total.)
int named_counter_slot(const std::string& name, int total_slot = -1);
// Adds amounts[i] to slot slots[i] (one lookup of the thread's block for all of them: hot paths count several).
void add_to_named(std::span<const int> slots, std::span<const std::uint64_t> amounts);

CounterTotals totals();
void reset();

}  // namespace counters
}  // namespace isotrace
