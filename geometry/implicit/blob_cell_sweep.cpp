// BlobCellQueries for one instruction set (blob_cell_queries.h): built into the library with ISOTRACE_BLOB_ISA
// = BlobIsa::Baseline and into the AVX2 module with BlobIsa::Avx2 (and ISOTRACE_BLOB_MODULE, for its entry).
#include <cmath>
#include <string_view>
#include <type_traits>

#include "geometry/implicit/blob_cell_queries.h"
#include "geometry/implicit/blob_group_with_kernel.h"
#include "renderer/core/version.h"
#include "renderer/math/line_box_clip.h"

#ifndef ISOTRACE_BLOB_ISA
#error "the build must define ISOTRACE_BLOB_ISA (BlobIsa::Baseline in the library, BlobIsa::Avx2 in the module)"
#endif

namespace isotrace {

template <>
class BlobCellSweep<ISOTRACE_BLOB_ISA> {
public:
    static std::optional<CellHit> first_crossing(const BlobGroup& group, std::uint32_t cell, const Vec3d& origin,
                                                 const Vec3d& direction, double t_min, double t_max,
                                                 BlobQueryWork& work) {
        std::optional<CellHit> found;
        sweep(
            group, cell, origin, direction, t_min, t_max, work,
            [&](const FieldCrossing& c, const auto& sweep) {
                const Vec3d hit_point = origin + direction * double(float(c.t));
                found = CellHit{c, field_sweep_detail::outward_normal(sweep.gradient_at(hit_point))};
                return true;
            },
            [] { return false; });  // where the crossing is matters
        return found;
    }

    static bool occluded(const BlobGroup& group, std::uint32_t cell, const Vec3d& origin, const Vec3d& direction,
                         double t_min, double t_max, BlobQueryWork& work) {
        bool occluded = false;
        sweep<false>(
            group, cell, origin, direction, t_min, t_max, work,
            [&](const FieldCrossing&, const auto&) { return occluded = true; },
            // Inside at the cell, outside at the ray's start (F ≤ T, the sweep's sign convention): an odd number of
            // crossings lies between them. A ray that starts within rounding of the surface (a shadow ray) counts as
            // outside only if it leaves the surface: one heading inwards crosses it at t_min itself, which the sweep
            // does not report.
            [&] {
                const Vec3d start = origin + direction * t_min;
                const double f = field(group, start);
                const double threshold = group.threshold();
                occluded = f <= threshold &&
                           (f < threshold * (1 - 1e-6) || dot(group.gradient(start), direction) < 0);
                work.roots += occluded ? 1 : 0;
                return occluded;
            });
        return occluded;
    }

    static void crossings(const BlobGroup& group, std::uint32_t cell, const Vec3d& origin, const Vec3d& direction,
                          double t_min, double t_max, std::vector<FieldCrossing>& out, std::size_t first,
                          BlobQueryWork& work) {
        sweep(
            group, cell, origin, direction, t_min, t_max, work,
            [&](const FieldCrossing& c, const auto&) {
                // A crossing on the face between two cells is found by both: keep it once.
                const bool repeated = out.size() > first && c.entering == out.back().entering &&
                                      c.t - out.back().t <= field_sweep_detail::same_place_tolerance(c.t);
                if (!repeated) out.push_back(c);
                return false;
            },
            [] { return false; });  // every crossing is wanted
    }

private:
    // F + T at a point: in lanes, with this build's instruction set, where the group's metaballs take MetaballSweep
    // (a tenth of a shadow ray went to BlobGroup::field at its start, one element at a time); else BlobGroup::field.
    static double field(const BlobGroup& group, const Vec3d& point) {
        if (!group.metaball_sweep_) return group.field(point);
        return group.with_kernel([&](const auto& kernel) {
            using Kernel = std::decay_t<decltype(kernel)>;
            const MetaballSweep<Kernel> sweep(kernel, group.threshold_, group.elements_, group.spheres_,
                                              group.centre_bound_);
            return sweep.field_at(point, group.cells_.elements_near(point));
        });
    }

    // Sweeps cell `cell`'s part of [t_min, t_max]; report(crossing, sweep) returns true to stop. When the part starts
    // inside after t_min, crossed_before() is asked whether that ends the sweep (FieldSweep::run). Without
    // kPlaceNeeded, a crossing's t may be any point of the piece it lies on (MetaballSweep::run).
    template <bool kPlaceNeeded = true, class Report, class CrossedBefore>
    static void sweep(const BlobGroup& group, std::uint32_t cell, const Vec3d& origin, const Vec3d& direction,
                      double t_min, double t_max, BlobQueryWork& work, Report&& report,
                      CrossedBefore&& crossed_before) {
        const BlobCells& cells = group.cells_;
        if (cell >= cells.surface_cell_count()) return;  // all inside or all outside: no crossing
        const BlobCells::Cell& box = cells.cells()[cell];
        const auto clip = clip_line_to_box(box.lower, box.upper, origin, direction, t_min, t_max);
        // A zero direction, or an unbounded query along a line parallel to every slab, has no finite stretch.
        if (!clip || !std::isfinite(clip->t_enter) || !std::isfinite(clip->t_exit)) return;
        const SweepStretch stretch{origin, direction, clip->t_enter, clip->t_exit, t_min, t_max};
        group.with_kernel([&](const auto& kernel) {
            using Kernel = std::decay_t<decltype(kernel)>;
            const std::span<const Metacube> elements(group.elements_);
            const std::span<const BoundingSphere> spheres(group.spheres_);
            if (group.metaball_sweep_) {
                MetaballSweep<Kernel> sweep(kernel, group.threshold_, elements, spheres, group.centre_bound_);
                if (sweep.template run<kPlaceNeeded>(cells.elements_of(cell), stretch, work, report, crossed_before))
                    return;
            }
            const auto sweep_with = [&]<bool kMetaballsOnly>() {
                FieldSweep<Kernel, kMetaballsOnly> sweep(kernel, group.threshold_, elements, spheres,
                                                         group.centre_bound_);
                sweep.run(cells.elements_of(cell), stretch, work, report, crossed_before);
            };
            if (group.metaballs_only_) sweep_with.template operator()<true>();
            else sweep_with.template operator()<false>();
        });
    }
};

namespace {

constexpr BlobCellQueries kQueries{&BlobCellSweep<ISOTRACE_BLOB_ISA>::first_crossing,
                                   &BlobCellSweep<ISOTRACE_BLOB_ISA>::occluded,
                                   &BlobCellSweep<ISOTRACE_BLOB_ISA>::crossings,
                                   ISOTRACE_BLOB_ISA == BlobIsa::Avx2 ? "avx2" : "baseline x86-64"};

}  // namespace

#ifdef ISOTRACE_BLOB_MODULE
extern "C" [[gnu::visibility("default")]] const BlobCellQueries* isotrace_blob_cell_queries(const char* version) {
    return std::string_view(version) == kIsotraceVersion ? &kQueries : nullptr;
}
#else
const BlobCellQueries& baseline_blob_cell_queries() { return kQueries; }
#endif

}  // namespace isotrace
