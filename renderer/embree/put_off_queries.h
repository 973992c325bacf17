#pragma once
// The occlusion queries that the first pass of a two-pass occlusion query put off (OcclusionPass), kept as the
// primitives' callbacks saw them (the ray in the primitive's own space), so that a ray no other primitive blocks is
// asked again without a second traversal of the scene. A query that finds no room, or whose ray is not the query's
// own (a copy Embree made), is only counted: the query then traverses the scene again for the queries put off.
#include <cstdint>

#include "renderer/core/render_counters.h"
#include "renderer/math/vec3.h"

namespace isotrace {

struct PutOffQuery {
    // Whether the primitive blocks the ray, as its occluded callback would answer (`shape`: the geometry's user data).
    using Ask = bool (*)(const void* shape, std::uint32_t primitive, const Vec3d& origin, const Vec3d& direction,
                         double t_near, float t_far);
    Ask ask;
    const void* shape;
    std::uint32_t primitive;
    int counter_slot;
    unsigned lane;                   // the ray's lane in the query's packet
    double origin[3], direction[3];  // plain arrays: the list's slots stay uninitialised until used
    double t_near;
    float t_far;
};

class PutOffQueries {
public:
    // Enough for a packet of eight rays each leaving a surface where two primitives put it off.
    static constexpr unsigned kMostKept = 16;

    // Notes a query put off, kept when `own_ray` (the callback's ray is the query's own) and there is room.
    void add(const PutOffQuery& query, bool own_ray) {
        if (own_ray && count_ < kMostKept) kept_[count_] = query;
        else all_kept_ = false;
        ++count_;
    }
    bool any() const { return count_ > 0; }
    bool all_kept() const { return all_kept_; }

    // Asks the queries of the lanes in `open` (a bit per lane) in the order they were put off, each lane until one
    // blocks it, counted like the callbacks' own tests; returns the lanes blocked. Requires all_kept().
    unsigned ask(unsigned open) const {
        unsigned blocked = 0;
        for (unsigned k = 0; k < count_; ++k) {
            const PutOffQuery& q = kept_[k];
            if (!(open >> q.lane & 1u) || (blocked >> q.lane & 1u)) continue;
            counters::count_test(q.counter_slot);
            const Vec3d origin(q.origin[0], q.origin[1], q.origin[2]);
            const Vec3d direction(q.direction[0], q.direction[1], q.direction[2]);
            if (!q.ask(q.shape, q.primitive, origin, direction, q.t_near, q.t_far)) continue;
            counters::count_candidate_hit(q.counter_slot);
            blocked |= 1u << q.lane;
        }
        return blocked;
    }

private:
    PutOffQuery kept_[kMostKept];
    unsigned count_ = 0;
    bool all_kept_ = true;
};

}  // namespace isotrace
