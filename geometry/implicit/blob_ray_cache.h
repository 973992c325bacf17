#pragma once
// What one thread has learnt about the ray it is tracing through a blob group. Embree asks every element whose
// bounds the ray meets, one after another, and each query would otherwise slice the same nearby elements along the
// same line and search the same stretches of it again. Two things carry over between those queries:
//   - each element's slices along the line (they depend on neither t_near nor t_far), and
//   - "settled" stretches: where a query has proven that the field keeps one sign, later queries start after them.
// Both are facts about the line and the field alone, so they stay valid while the group, the ray's origin,
// direction and t_near stay the same; anything else starts afresh.
#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "geometry/implicit/metacube_ray_slices.h"

namespace isotrace {

class BlobGroup;

class BlobRayCache {
public:
    // Starts (or continues) the ray (group, origin, direction, t_min).
    void begin(const BlobGroup& group, const Vec3d& origin, const Vec3d& direction, double t_min);

    // The slices of `element` along the current ray (nullptr when the line misses its support). The pointer stays
    // valid until the ray changes.
    const MetacubeRaySlices* slices(std::uint32_t element);

    // A stretch (lo, hi) of the current ray on which the field has sign `sign` and no crossing.
    struct Settled {
        double lo, hi;
        int sign;
    };
    // The settled stretch with lo ≤ t < hi, if any.
    std::optional<Settled> settled_at(double t) const;
    // The settled stretch with lo < t ≤ hi, if any.
    std::optional<Settled> settled_before(double t) const;
    void settle(double lo, double hi, int sign);

    // The calling thread's cache.
    static BlobRayCache& for_this_thread();

private:
    static constexpr std::size_t kSlots = 512;
    struct Entry {
        std::uint64_t generation = 0;
        std::uint32_t element = 0;
        std::optional<MetacubeRaySlices> slices;
    };
    const BlobGroup* group_ = nullptr;
    std::uint64_t group_identity_ = 0;
    Vec3d origin_, direction_;
    double t_min_ = 0;
    std::uint64_t generation_ = 1;
    std::array<Entry, kSlots> table_{};
    std::deque<std::optional<MetacubeRaySlices>> overflow_;  // when the table is crowded; stable addresses
    std::vector<Settled> settled_;                           // sorted by lo, disjoint
};

}  // namespace isotrace
