#include "geometry/implicit/blob_group_shape.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "geometry/csg/inside_span_list.h"
#include "renderer/core/render_counters.h"
#include "renderer/embree/user_geometry.h"

namespace isotrace {

BlobGroupShape::BlobGroupShape(BlobGroup group, BlobMaterials materials)
    : group_(std::move(group)), materials_(std::move(materials)) {
    if (!materials_.empty() && materials_.element_parts().size() != group_.elements().size())
        throw std::invalid_argument("a blob group's element materials must list one part per element");
}

Bounds3f BlobGroupShape::bounds() const {
    Bounds3f b;
    for (const Metacube& element : group_.elements()) {
        const WorldBounds support = element.support_bounds();
        b.extend(Vec3f(support.lower));
        b.extend(Vec3f(support.upper));
    }
    return b;
}

void BlobGroupShape::register_counters() {
    counter_slot_ = counters::geometry_type_slot(type_name(), true);
    static constexpr const char* kWorkNames[] = {
        ".cell_queries",      ".cell_queries_bounded", ".candidates",      ".elements_joined", ".pieces",
        ".pieces_skipped_by_bounds", ".polynomial_solves", ".lipschitz_searches", ".root_iterations", ".roots"};
    const std::string group = type_name() + "[" + (object_name().empty() ? "unnamed" : object_name()) + "]";
    for (std::size_t k = 0; k < work_slots_.size(); ++k)
        work_slots_[k] = counters::named_counter_slot(group + kWorkNames[k],
                                                      counters::named_counter_slot(type_name() + kWorkNames[k]));
}

void BlobGroupShape::count_work(const BlobQueryWork& work) const {
    if (work.queries == 0) return;
    const std::array<std::uint64_t, 10> amounts{work.queries,        work.queries_bounded,    work.candidates,
                                                work.joined,         work.pieces,             work.skipped_pieces,
                                                work.polynomial_solves, work.lipschitz_searches, work.root_iterations,
                                                work.roots};
    counters::add_to_named(work_slots_, amounts);
}

RTCGeometry BlobGroupShape::create_geometry(RTCDevice device) {
    register_counters();
    return user_geometry::create<bounds_callback>(device, this, group_.cells().surface_cell_count(),
                                                  intersect_callback, occluded_callback);
}

void BlobGroupShape::bounds_callback(const RTCBoundsFunctionArguments* args) {
    const auto* self = static_cast<const BlobGroupShape*>(args->geometryUserPtr);
    const BlobCells::Cell& cell = self->group_.cells().cells()[args->primID];
    user_geometry::store_bounds(args->bounds_o, cell.lower, cell.upper);
}

std::optional<CellHit> BlobGroupShape::first_hit(std::uint32_t cell, const Vec3d& origin, const Vec3d& direction,
                                                 double t_near, float t_far) const {
    BlobQueryWork work;
    const auto hit = group_.first_crossing_in_cell(cell, origin, direction, t_near, t_far, work);
    count_work(work);
    return hit;
}

bool BlobGroupShape::occludes(std::uint32_t cell, const Vec3d& origin, const Vec3d& direction, double t_near,
                              float t_far) const {
    BlobQueryWork work;
    const bool occluded = group_.occluded_in_cell(cell, origin, direction, t_near, t_far, work);
    count_work(work);
    return occluded;
}

LocalShading BlobGroupShape::shading(const RTCHit& hit, const Vec3f&, const Vec3d& point) const {
    // The intersect callback stored the normal of the hit point; a zero one means −∇F vanishes there (a hard cube's
    // face), whose normal the cell's hard cubes give.
    const Vec3f stored(hit.Ng_x, hit.Ng_y, hit.Ng_z);
    const Vec3f normal = stored != Vec3f(0, 0, 0) ? stored : Vec3f(group_.normal_in_cell(hit.primID, point));
    LocalShading shading{.geometric_normal = normal, .normal = normal};
    if (!materials_.empty()) {
        shading.blend = materials_.blend(group_, group_.cells().elements_of(hit.primID), point);
        shading.part = shading.blend.part[0];
    }
    return shading;
}

std::uint32_t BlobGroupShape::largest_part(const Vec3d& point) const {
    return materials_.empty() ? 0 : materials_.blend(group_, group_.cells().elements_near(point), point).part[0];
}

std::optional<double> BlobGroupShape::field_value(const Vec3d& point) const {
    return group_.field(point) - group_.threshold();
}

Vec3d BlobGroupShape::field_gradient(const Vec3d& point) const { return group_.gradient(point); }

void BlobGroupShape::intersect_callback(const RTCIntersectFunctionNArguments* args) {
    const auto* self = static_cast<const BlobGroupShape*>(args->geometryUserPtr);
    std::optional<Vec3d> normal;  // of the hit first_hit just found, for record
    user_geometry::intersect_rays(
        args, self->counter_slot_,
        [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) -> std::optional<double> {
            const auto hit = self->first_hit(args->primID, origin, direction, t_near, t_far);
            if (!hit || !(float(hit->crossing.t) < t_far)) return std::nullopt;
            normal = hit->normal;
            return hit->crossing.t;
        },
        [&](unsigned i, const Vec3d&, const Vec3d&, double t) {
            user_geometry::store_hit(args, i, float(t), normal.value_or(Vec3d(0, 0, 0)));
        });
}

void BlobGroupShape::occluded_callback(const RTCOccludedFunctionNArguments* args) {
    const auto* self = static_cast<const BlobGroupShape*>(args->geometryUserPtr);
    user_geometry::occlude_rays(args, self->counter_slot_,
                                [&](const Vec3d& origin, const Vec3d& direction, double t_near, float t_far) {
                                    return self->occludes(args->primID, origin, direction, t_near, t_far);
                                });
}

void BlobGroupShape::inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                                  std::vector<InsideSpan>& spans, QueryScratch&) const {
    std::vector<FieldCrossing> crossings;
    BlobQueryWork work;
    const int sign_at_start = group_.crossings(origin, direction, t_min, t_max, crossings, work);
    count_work(work);
    append_spans_from_crossings(
        std::span<const FieldCrossing>(crossings), sign_at_start > 0, t_min, t_max,
        [&](const FieldCrossing& c) {
            const Vec3d point = origin + direction * c.t;
            return BoundaryPoint{c.t, group_.normal(point), c.element, largest_part(point)};
        },
        spans);
}

}  // namespace isotrace
