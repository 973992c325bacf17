#include "geometry/implicit/blob_group_shape.h"

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
    const std::string name = type_name() + "[" + (object_name().empty() ? "unnamed" : object_name()) + "]";
    target_ = {&group_, counters::geometry_type_slot(type_name(), true), register_blob_work(type_name(), name)};
}

RTCGeometry BlobGroupShape::create_geometry(RTCDevice device) {
    register_counters();
    const BlobCellQueries& queries = group_.queries();
    return user_geometry::create<bounds_callback>(device, &target_, group_.cells().surface_cell_count(),
                                                  queries.intersect, queries.occluded);
}

void BlobGroupShape::bounds_callback(const RTCBoundsFunctionArguments* args) {
    const auto* target = static_cast<const BlobRayTarget*>(args->geometryUserPtr);
    const BlobCells::Cell& cell = target->group->cells().cells()[args->primID];
    user_geometry::store_bounds(args->bounds_o, cell.lower, cell.upper);
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

void BlobGroupShape::inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                                  std::vector<InsideSpan>& spans, QueryScratch&) const {
    std::vector<FieldCrossing> crossings;
    BlobQueryWork work;
    const int sign_at_start = group_.crossings(origin, direction, t_min, t_max, crossings, work);
    count_blob_work(target_.work_slots, work);
    append_spans_from_crossings(
        std::span<const FieldCrossing>(crossings), sign_at_start > 0, t_min, t_max,
        [&](const FieldCrossing& c) {
            const Vec3d point = origin + direction * c.t;
            return BoundaryPoint{c.t, group_.normal(point), c.element, largest_part(point)};
        },
        spans);
}

}  // namespace isotrace
