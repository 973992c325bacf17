#include "geometry/isosurface/isosurface_shape.h"

#include <algorithm>
#include <span>

#include "geometry/csg/inside_span_list.h"
#include "renderer/core/parallel_for.h"
#include "renderer/core/render_counters.h"
#include "renderer/embree/user_geometry.h"
#include "renderer/math/line_box_clip.h"

namespace isotrace {

IsosurfaceShape::IsosurfaceShape(std::shared_ptr<const ImplicitField> field, const Container& container,
                                 std::vector<IntervalBox> cells, const IsosurfaceSettings& settings,
                                 CellFields cell_fields, std::vector<std::unique_ptr<Shape>> keep_alive)
    : keep_alive_(std::move(keep_alive)),
      field_(std::move(field)),
      container_(container),
      cells_(std::move(cells)),
      cell_fields_(std::move(cell_fields)),
      resolution_(settings.resolution > 0
                      ? settings.resolution
                      : 1e-6 * length(container.bounds().upper() - container.bounds().lower())),
      max_work_(settings.max_work) {
    // Within the container by more than rounding can move a clip's ends: its clip cannot cut the cell's.
    const IntervalBox& box = container_.bounds();
    const double margin = 1e-9 * length(box.upper() - box.lower());
    within_container_.resize(cells_.size());
    for (std::size_t i = 0; i < cells_.size(); ++i)
        within_container_[i] = container_.distance_range(cells_[i]).hi < -margin;
    cell_bounds_.resize(cells_.size());
    parallel_for(std::size_t(0), cells_.size(),
                 [&](std::size_t i) { cell_bounds_[i] = LinearCellBound::of(field_of(std::uint32_t(i)), cells_[i]); });
}

Bounds3f IsosurfaceShape::bounds() const {
    Bounds3f b;
    for (const IntervalBox& cell : cells_) {
        b.extend(Vec3f(cell.lower()));
        b.extend(Vec3f(cell.upper()));
    }
    return b;
}

std::optional<double> IsosurfaceShape::field_value(const Vec3d& point) const {
    return -std::max(field_->value(point), container_.signed_distance(point));
}

Vec3d IsosurfaceShape::field_gradient(const Vec3d& point) const {
    if (container_.signed_distance(point) > field_->value(point)) return -container_.normal(point);
    return -field_->gradient(point);
}

RTCGeometry IsosurfaceShape::create_geometry(RTCDevice device) {
    counter_slot_ = counters::geometry_type_slot(type_name(), true);
    work_slots_ = {counters::named_counter_slot("isosurface.interval_bounds"),
                   counters::named_counter_slot("isosurface.slope_bounds"),
                   counters::named_counter_slot("isosurface.slope_proofs"),
                   counters::named_counter_slot("isosurface.evaluations"),
                   counters::named_counter_slot("isosurface.halvings"),
                   counters::named_counter_slot("isosurface.refined_crossings"),
                   counters::named_counter_slot("isosurface.budget_exhausted")};
    return user_geometry::create<bounds_callback>(device, this, unsigned(cells_.size()), intersect_callback,
                                                  occluded_callback);
}

void IsosurfaceShape::record_work(const IsosurfaceWork& work) const {
    const std::array<std::uint64_t, 7> amounts{
        work.search.interval_bounds, work.search.slope_bounds, work.search.slope_proofs, work.search.evaluations,
        work.search.halvings,        work.search.crossings,    work.budget_exhausted ? 1u : 0u};
    counters::add_to_named(work_slots_, amounts);
}

template <CrossingPrecision precision, class Visit>
void IsosurfaceShape::search(const ImplicitField& field, const Vec3d& origin, const Vec3d& direction, double a,
                             double b, double g_a, double g_b, std::optional<FieldRanges> ranges_a_b,
                             IsosurfaceWork& work, Visit&& visit) const {
    const auto point = [&](double t) { return origin + direction * t; };
    const auto value = [&](double t) { return field.value(point(t)); };
    const auto segment_box = [&](double lo, double hi) {
        IntervalBox box = IntervalBox::point(point(lo));
        box.extend(point(hi));
        return box;
    };
    const auto spent = [&] {
        const CrossingSearchWork& s = work.search;
        if (s.evaluations + s.interval_bounds + s.slope_bounds < max_work_) return false;
        work.budget_exhausted = true;
        return true;
    };
    // Past the budget, every stretch without a sign change is dropped and every bracket held is refined as one
    // crossing: the search ends within a few steps per segment on its stack. A stretch's value and slope come
    // from one run (the search asks for the slope of a stretch right after a value range that holds 0); the
    // whole segment's ranges, when given, are the first such pair (counted already).
    struct StretchRanges {
        double lo, hi;
        FieldRanges ranges;
    };
    std::optional<StretchRanges> last;
    if (ranges_a_b) last = StretchRanges{a, b, *ranges_a_b};
    const auto bound = [&](double lo, double hi) {
        if (spent()) return Interval::point(1);
        if (last && lo == a && hi == b && last->lo == a && last->hi == b) {
            --work.search.interval_bounds;
            return last->ranges.value;
        }
        last = StretchRanges{lo, hi, field.value_and_slope_range(segment_box(lo, hi), direction)};
        return last->ranges.value;
    };
    const auto slope = [&](double lo, double hi) {
        if (spent()) return Interval::point(1);
        if (last && last->lo == lo && last->hi == hi) return last->ranges.slope;
        return field.slope_range(segment_box(lo, hi), direction);
    };
    // Brackets are refined by Newton steps along the ray: fewer evaluations than regula falsi's.
    const auto point_slope = [&](double t) { return field.value_and_slope(point(t), direction); };
    search_crossings<precision>(a, b, g_a, g_b, resolution_ / length(direction), false, value, bound, slope,
                                work.search, visit, point_slope);
}

Vec3d IsosurfaceShape::surface_normal(const Vec3d& p, const Vec3d& direction) const {
    return safe_normalize(field_->gradient(p), -normalize(direction));
}

std::optional<IsosurfaceShape::Hit> IsosurfaceShape::first_hit(std::uint32_t index, const Vec3d& origin,
                                                               const Vec3d& direction, double t_near, double t_far,
                                                               IsosurfaceWork& work) const {
    bool undecided = false;
    return surface_in_cell<CrossingPrecision::Refined>(index, origin, direction, t_near, t_far, work, undecided);
}

bool IsosurfaceShape::occludes(std::uint32_t index, const Vec3d& origin, const Vec3d& direction, double t_near,
                               float t_far, IsosurfaceWork& work) const {
    bool undecided = false;
    std::optional<Hit> hit =
        surface_in_cell<CrossingPrecision::Bracketed>(index, origin, direction, t_near, t_far, work, undecided);
    if (undecided) hit = first_hit(index, origin, direction, t_near, t_far, work);
    return hit && float(hit->t) < t_far;
}

template <CrossingPrecision precision>
std::optional<IsosurfaceShape::Hit> IsosurfaceShape::surface_in_cell(std::uint32_t index, const Vec3d& origin,
                                                                     const Vec3d& direction, double t_near,
                                                                     double t_far, IsosurfaceWork& work,
                                                                     bool& undecided) const {
    // The container's stretch of the ray, unless the cell lies within the container (most do).
    std::optional<Interval> inside;
    double a = t_near, b = t_far;
    if (!(index < cells_.size() && within_container_[index])) {
        inside = container_.clip(origin, direction, t_near, t_far);
        if (!inside) return std::nullopt;
        a = inside->lo;
        b = inside->hi;
    }
    if (index < cells_.size()) {
        const IntervalBox& cell = cells_[index];
        const auto clip = clip_line_to_box(cell.lower(), cell.upper(), origin, direction, a, b);
        if (!clip) return std::nullopt;
        a = clip->t_enter;
        b = clip->t_exit;
    }
    const Vec3d p_a = origin + direction * a, p_b = origin + direction * b;
    const bool enters_container = inside && a == inside->lo && a > t_near;
    const bool leaves_container = inside && b == inside->hi && b < t_far;
    // Where f keeps one sign along the segment only the container's boundary can be surface (where f < 0).
    const auto without_crossing = [&](bool inside_throughout) -> std::optional<Hit> {
        if (!inside_throughout) return std::nullopt;
        if (enters_container) return Hit{a, container_.normal(p_a)};
        if (leaves_container) return Hit{b, container_.normal(p_b)};
        return std::nullopt;
    };
    // Most segments through a cell miss the surface: the cell's linear model settles most of them without a run
    // of the tape; of the rest, those that keep their sign are mostly settled by the model's slope over the cell
    // and the values at the ends (the search's mean-value test, which these would come to after a failed bound).
    const LinearCellBound* model = index < cells_.size() ? &cell_bounds_[index] : nullptr;
    Interval range = model ? model->over_segment(p_a, p_b) : Interval::unbounded();
    if (range.excludes_zero()) return without_crossing(range.hi < 0);
    const ImplicitField& field = field_of(index);
    const double g_a = field.value(p_a), g_b = field.value(p_b);
    if (model && (g_a < 0) == (g_b < 0)) {
        const Interval slope = model->slope_along(direction);
        if (slope.excludes_zero() || crossing_search_detail::keeps_sign(b - a, g_a, g_b, slope))
            return without_crossing(g_a < 0);
    }
    // The search's first two questions (the bound over the whole segment, then the slope) from one run.
    IntervalBox segment = IntervalBox::point(p_a);
    segment.extend(p_b);
    const FieldRanges ranges = field.value_and_slope_range(segment, direction);
    range = ranges.value;
    ++work.search.interval_bounds;
    if (range.lo >= 0) return std::nullopt;  // outside throughout, as the search would find
    if (range.hi < 0) return without_crossing(true);
    // The ray enters the container where the function's solid meets its boundary.
    if (enters_container && g_a < 0) return Hit{a, container_.normal(p_a)};
    std::optional<Hit> hit;
    search<precision>(field, origin, direction, a, b, g_a, g_b, ranges, work, [&](const Crossing& crossing) {
        if constexpr (precision == CrossingPrecision::Bracketed) {
            undecided = !crossing.settles_occlusion(t_near, t_far);
            if (!undecided) hit = Hit{crossing.t, {}};
            return false;
        } else {
            if (!(crossing.t > t_near && crossing.t < t_far)) return true;
            hit = Hit{crossing.t, surface_normal(origin + direction * crossing.t, direction)};
            return false;
        }
    });
    if (hit) return hit;
    // A ray from inside leaves through the container's boundary.
    if (leaves_container && g_b < 0) return Hit{b, container_.normal(p_b)};
    return std::nullopt;
}

void IsosurfaceShape::bounds_callback(const RTCBoundsFunctionArguments* args) {
    const auto* self = static_cast<const IsosurfaceShape*>(args->geometryUserPtr);
    const IntervalBox& cell = self->cells_[args->primID];
    user_geometry::store_bounds(args->bounds_o, cell.lower(), cell.upper());
}

void IsosurfaceShape::intersect_callback(const RTCIntersectFunctionNArguments* args) {
    const auto* self = static_cast<const IsosurfaceShape*>(args->geometryUserPtr);
    Vec3d normal;
    user_geometry::intersect_rays(
        args, self->counter_slot_,
        [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) -> std::optional<double> {
            IsosurfaceWork work;
            const auto hit = self->first_hit(args->primID, origin, direction, t_near, t_far, work);
            self->record_work(work);
            if (!hit || !(float(hit->t) < t_far)) return std::nullopt;
            normal = hit->normal;
            return hit->t;
        },
        [&](unsigned i, const Vec3d&, const Vec3d&, double t) { user_geometry::store_hit(args, i, float(t), normal); });
}

void IsosurfaceShape::occluded_callback(const RTCOccludedFunctionNArguments* args) {
    const auto* self = static_cast<const IsosurfaceShape*>(args->geometryUserPtr);
    user_geometry::occlude_rays(args, self->counter_slot_,
                                [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) {
                                    IsosurfaceWork work;
                                    const bool hit = self->occludes(args->primID, origin, direction, t_near, t_far, work);
                                    self->record_work(work);
                                    return hit;
                                });
}

void IsosurfaceShape::inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                                   std::vector<InsideSpan>& spans, QueryScratch& scratch) const {
    const std::optional<Interval> inside = container_.clip(origin, direction, t_min, t_max);
    if (!inside) return;
    const QueryScratch::Level level(scratch);
    auto& found = level.get<std::vector<Crossing>>();
    found.clear();
    IsosurfaceWork work;
    const double g_a = field_->value(origin + direction * inside->lo);
    const double g_b = field_->value(origin + direction * inside->hi);
    search(*field_, origin, direction, inside->lo, inside->hi, g_a, g_b, std::nullopt, work,
           [&](const Crossing& crossing) {
               found.push_back(crossing);
               return true;
           });
    record_work(work);
    const std::size_t first = spans.size();
    append_spans_from_crossings(
        std::span<const Crossing>(found), g_a < 0, inside->lo, inside->hi,
        [&](const Crossing& c) { return BoundaryPoint{c.t, surface_normal(origin + direction * c.t, direction), 0, 0}; },
        spans);
    // Ends cut where the ray crosses the container's boundary (not the query's range) lie on the surface.
    const auto on_container = [&](BoundaryPoint& end) {
        end = BoundaryPoint{end.t, container_.normal(origin + direction * end.t), 0, 0};
    };
    for (std::size_t i = first; i < spans.size(); ++i) {
        if (!spans[i].enter.on_surface() && spans[i].enter.t > t_min) on_container(spans[i].enter);
        if (!spans[i].exit.on_surface() && spans[i].exit.t < t_max) on_container(spans[i].exit);
    }
}

}  // namespace isotrace
