// A ray through a blob group, from Embree's callback to the accepted crossing, for one instruction set
// (blob_cell_queries.h): built into the library, and with ISOTRACE_BLOB_MODULE into the AVX2 module.
//   1. Embree offers a ray and a cell (a primitive: blob_group_shape.h); the ray is clipped to the cell's box;
//   2. the cell's stretch of the ray is marched over pieces, front to back (piece_march.h), with the group's kernel
//      as its concrete class so that its calls inline: in lanes for metaballs of a one-piece polynomial kernel
//      (metaball_march.h), else over a list of joined elements (field_march.h); each piece is bounded, tested and
//      solved by march_piece.h;
//   3. each crossing goes to the query (below), which says whether the march stops: the nearest hit takes the first
//      and its normal, occlusion any, CSG every one.
#include <cmath>
#include <limits>
#include <string_view>

#include "geometry/implicit/blob_cell_queries.h"
#include "geometry/implicit/field_kernels.h"
#include "geometry/implicit/field_march.h"
#include "geometry/implicit/metaball_march.h"
#include "renderer/core/render_counters.h"
#include "renderer/core/version.h"
#include "renderer/embree/user_geometry.h"
#include "renderer/math/line_box_clip.h"

namespace isotrace {
namespace {

// What the march does with the crossings it finds (in increasing t): found(crossing, march) returns true to stop;
// crossed_before() is asked when the stretch starts inside after t_min, and a true ends the march. Without
// kPlaceNeeded, a crossing's t may be any point of the piece it lies on (MetaballMarch).

// The nearest crossing and the outward normal where the renderer places it (o + d·float(t)), summed from the march's
// own elements: nearly every candidate hit is accepted, so a normal per crossing costs less than a second search of
// the cell.
struct FirstHit {
    static constexpr bool kPlaceNeeded = true;
    const Vec3d& origin;
    const Vec3d& direction;
    std::optional<CellHit> hit;

    template <class March>
    bool found(const FieldCrossing& crossing, const March& march) {
        const Vec3d hit_point = origin + direction * double(float(crossing.t));
        hit = CellHit{crossing, outward_normal(march.gradient_at(hit_point))};
        return true;
    }
    bool crossed_before() { return false; }  // where the crossing is matters
};

// Whether any crossing lies in the cell's stretch. Shadow rays meet cells in the order of Embree's hierarchy, not
// along the ray, and marching the inside of a blob to its far side would be most of their work: a cell that starts
// inside after a ray start outside ends at once, for the ray crossed the surface before the cell.
struct Occlusion {
    static constexpr bool kPlaceNeeded = false;
    const BlobGroup& group;
    const Vec3d& origin;
    const Vec3d& direction;
    double t_min;
    BlobQueryWork& work;
    bool occluded = false;

    template <class March>
    bool found(const FieldCrossing&, const March&) {
        return occluded = true;
    }
    // Inside at the cell, outside at the ray's start (F ≤ T, the march's sign convention): an odd number of crossings
    // lies between them. A ray that starts within rounding of the surface (a shadow ray) counts as outside only if it
    // leaves the surface: one heading inwards crosses it at t_min itself, which the march does not report.
    bool crossed_before() {
        const Vec3d start = origin + direction * t_min;
        const double f = field_at_start(start);
        const double threshold = group.threshold();
        occluded = f <= threshold && (f < threshold * (1 - 1e-6) || dot(group.gradient(start), direction) < 0);
        work.roots += occluded ? 1 : 0;
        return occluded;
    }
    // F + T at the ray's start: in lanes, with this build's instruction set, where the group's metaballs take
    // MetaballMarch; else BlobGroup::field, one element at a time.
    double field_at_start(const Vec3d& point) const {
        const BlobGroupView view = group.view();
        if (!view.metaball_march) return group.field(point);
        return with_kernel(view.kernel_index, view.kernel, [&]<class Kernel>(const Kernel& kernel) {
            const MetaballMarch<Kernel> march(kernel, view.threshold, view.elements, view.spheres, view.centre_bound);
            return march.field_at(point, view.cells.elements_near(point));
        });
    }
};

// Every crossing, appended to `out`; one on the face between two cells is found by both, and kept once.
struct AllCrossings {
    static constexpr bool kPlaceNeeded = true;
    std::vector<FieldCrossing>& out;
    std::size_t first;  // out's crossings before this ray's

    template <class March>
    bool found(const FieldCrossing& crossing, const March&) {
        const bool repeated = out.size() > first && crossing.entering == out.back().entering &&
                              crossing.t - out.back().t <= same_place_tolerance(crossing.t);
        if (!repeated) out.push_back(crossing);
        return false;
    }
    bool crossed_before() { return false; }  // every crossing is wanted
};

// Marches cell `cell`'s part of o + t·d, t in [t_min, t_max], for `query`.
template <class Query>
void march_cell(const BlobGroupView& group, std::uint32_t cell, const Vec3d& origin, const Vec3d& direction,
                double t_min, double t_max, BlobQueryWork& work, Query& query) {
    if (cell >= group.cells.surface_cell_count()) return;  // all inside or all outside: no crossing
    const BlobCells::Cell& box = group.cells.cells()[cell];
    const auto clip = clip_line_to_box(box.lower, box.upper, origin, direction, t_min, t_max);
    // A zero direction, or an unbounded query along a line parallel to every slab, has no finite stretch.
    if (!clip || !std::isfinite(clip->t_enter) || !std::isfinite(clip->t_exit)) return;
    const MarchStretch stretch{origin, direction, clip->t_enter, clip->t_exit, t_min, t_max};
    const std::span<const std::uint32_t> listed = group.cells.elements_of(cell);
    with_kernel(group.kernel_index, group.kernel, [&]<class Kernel>(const Kernel& kernel) {
        // MetaballMarch declines a stretch near more elements than its lanes hold.
        if (group.metaball_march &&
            MetaballMarch<Kernel>(kernel, group.threshold, group.elements, group.spheres, group.centre_bound)
                .run(listed, stretch, work, query))
            return;
        if (group.metaballs_only)
            FieldMarch<Kernel, true>(kernel, group.threshold, group.elements, group.spheres, group.centre_bound)
                .run(listed, stretch, work, query);
        else
            FieldMarch<Kernel, false>(kernel, group.threshold, group.elements, group.spheres, group.centre_bound)
                .run(listed, stretch, work, query);
    });
}

std::optional<CellHit> first_hit_in_cell(const BlobGroup& group, std::uint32_t cell, const Vec3d& origin,
                                         const Vec3d& direction, double t_min, double t_max, BlobQueryWork& work) {
    FirstHit query{origin, direction, std::nullopt};
    march_cell(group.view(), cell, origin, direction, t_min, t_max, work, query);
    return query.hit;
}

bool occluded_in_cell(const BlobGroup& group, std::uint32_t cell, const Vec3d& origin, const Vec3d& direction,
                      double t_min, double t_max, BlobQueryWork& work) {
    Occlusion query{group, origin, direction, t_min, work};
    march_cell(group.view(), cell, origin, direction, t_min, t_max, work, query);
    return query.occluded;
}

void crossings_in_cell(const BlobGroup& group, std::uint32_t cell, const Vec3d& origin, const Vec3d& direction,
                       double t_min, double t_max, std::vector<FieldCrossing>& out, std::size_t first,
                       BlobQueryWork& work) {
    AllCrossings query{out, first};
    march_cell(group.view(), cell, origin, direction, t_min, t_max, work, query);
}

// Embree's intersect callback: per active ray, the cell's first crossing before the ray's t_far becomes its hit
// (cells are disjoint, so the shrinking t_far makes the nearest cell's crossing the ray's hit).
void intersect(const RTCIntersectFunctionNArguments* args) {
    const auto& target = *static_cast<const BlobRayTarget*>(args->geometryUserPtr);
    const BlobGroupView group = target.group->view();
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        counters::count_test(target.counter_slot);
        const Vec3d origin = user_geometry::ray_origin(rays, args->N, i);
        const Vec3d direction = user_geometry::ray_direction(rays, args->N, i);
        const float t_far = RTCRayN_tfar(rays, args->N, i);
        BlobQueryWork work;
        FirstHit query{origin, direction, std::nullopt};
        march_cell(group, args->primID, origin, direction, double(RTCRayN_tnear(rays, args->N, i)), t_far, work,
                   query);
        count_blob_work(target.work_slots, work);
        if (!query.hit || !(float(query.hit->crossing.t) < t_far)) continue;
        counters::count_candidate_hit(target.counter_slot);
        user_geometry::store_hit(args, i, float(query.hit->crossing.t), query.hit->normal.value_or(Vec3d(0, 0, 0)));
    }
}

// Embree's occluded callback: a crossing in the cell's stretch occludes the ray (t_far = −∞).
void occluded(const RTCOccludedFunctionNArguments* args) {
    const auto& target = *static_cast<const BlobRayTarget*>(args->geometryUserPtr);
    const BlobGroupView group = target.group->view();
    RTCRayN* rays = args->ray;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        counters::count_test(target.counter_slot);
        const Vec3d origin = user_geometry::ray_origin(rays, args->N, i);
        const Vec3d direction = user_geometry::ray_direction(rays, args->N, i);
        float& t_far = RTCRayN_tfar(rays, args->N, i);
        const double t_near = RTCRayN_tnear(rays, args->N, i);
        BlobQueryWork work;
        Occlusion query{*target.group, origin, direction, t_near, work};
        march_cell(group, args->primID, origin, direction, t_near, t_far, work, query);
        count_blob_work(target.work_slots, work);
        if (!query.occluded) continue;
        counters::count_candidate_hit(target.counter_slot);
        t_far = -std::numeric_limits<float>::infinity();
    }
}

#ifdef ISOTRACE_BLOB_MODULE
constexpr const char* kIsa = "avx2";
#else
constexpr const char* kIsa = "baseline x86-64";
#endif

constexpr BlobCellQueries kQueries{&intersect, &occluded, &first_hit_in_cell, &occluded_in_cell, &crossings_in_cell,
                                   kIsa};

}  // namespace

#ifdef ISOTRACE_BLOB_MODULE
extern "C" [[gnu::visibility("default")]] const BlobCellQueries* isotrace_blob_cell_queries(const char* version) {
    return std::string_view(version) == kIsotraceVersion ? &kQueries : nullptr;
}
#else
const BlobCellQueries& baseline_blob_cell_queries() { return kQueries; }
#endif

}  // namespace isotrace
