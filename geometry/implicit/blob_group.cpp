#include "geometry/implicit/blob_group.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "geometry/implicit/blob_ray_cache.h"
#include "geometry/implicit/metacube_ray_slices.h"

namespace isotrace {
namespace {

// Can the segment o + t·d, t in [a, b], reach the element's support? Tested against the sphere around it
// (centre, R + |half-size|): a few multiplications, a cheap rejection before exact slicing.
inline bool segment_may_meet(const Metacube& element, const Vec3d& origin, const Vec3d& direction, double a, double b) {
    const Vec3d to_centre = element.skeleton().centre - origin;
    const double t = std::clamp(dot(to_centre, direction) / dot(direction, direction), a, b);
    const Vec3d& half_size = element.skeleton().half_size;
    const double half_size2 = dot(half_size, half_size);  // 0 for metaballs: no square root needed
    const double reach = element.radius() + (half_size2 > 0 ? std::sqrt(half_size2) : 0.0);
    const Vec3d gap = to_centre - direction * t;
    return dot(gap, gap) <= reach * reach * (1 + 1e-9);
}

std::atomic<std::uint64_t> g_next_identity{1};
thread_local FieldAlongRay t_field;
thread_local std::vector<FieldCrossing> t_crossings;

}  // namespace

BlobGroup::BlobGroup(std::vector<Metacube> elements, std::unique_ptr<const FieldFunction> kernel, double threshold)
    : elements_(std::move(elements)), kernel_(std::move(kernel)), threshold_(threshold), identity_(g_next_identity++) {
    validate_threshold(threshold_);
    build_index();
}

void BlobGroup::build_index() {
    std::vector<WorldBounds> supports(elements_.size());
    for (std::size_t i = 0; i < elements_.size(); ++i) supports[i] = elements_[i].support_bounds();
    bvh_.build(supports);
}

void BlobGroup::bake(const Transform& similarity, double scale) {
    for (Metacube& element : elements_) {
        OrientedBox box = element.skeleton();
        box.centre = similarity.point(box.centre);
        for (Vec3d& axis : box.axes) axis = normalize(similarity.vector(axis));
        box.half_size = box.half_size * scale;
        element = Metacube(box, element.radius() * scale, element.weight());
    }
    identity_ = g_next_identity++;
    build_index();
}

std::size_t BlobGroup::memory_bytes() const {
    return sizeof(*this) + elements_.capacity() * sizeof(Metacube) + bvh_.memory_bytes();
}

double BlobGroup::field(const Vec3d& point) const {
    double sum = 0;
    bvh_.for_each_containing(point, [&](std::uint32_t j) { sum += elements_[j].field(*kernel_, point); });
    return sum;
}

Vec3d BlobGroup::gradient(const Vec3d& point) const {
    Vec3d sum(0, 0, 0);
    bvh_.for_each_containing(point, [&](std::uint32_t j) { sum += elements_[j].field_gradient(*kernel_, point); });
    return sum;
}

Vec3d BlobGroup::normal(const Vec3d& point) const {
    const Vec3d g = gradient(point);
    const double len = length(g);
    if (len > 0 && std::isfinite(len)) return -g / len;
    // Only hard cubes (step fields) meet here: take the face of the nearest hard-cube boundary.
    double best = std::numeric_limits<double>::infinity();
    Vec3d result(0, 0, 1);
    const auto consider = [&](const Metacube& element) {
        if (!element.is_hard_cube()) return;
        const OrientedBox& box = element.skeleton();
        const Vec3d p = box.to_local(point);
        for (int axis = 0; axis < 3; ++axis) {
            const double gap = std::abs(std::abs(p[axis]) - box.half_size[axis]);
            if (gap < best) {
                best = gap;
                Vec3d local(0, 0, 0);
                local[axis] = p[axis] >= 0 ? 1 : -1;
                result = box.to_world_vector(local);
            }
        }
    };
    bvh_.for_each_containing(point, [&](std::uint32_t j) { consider(elements_[j]); });
    return result;
}

std::optional<double> BlobGroup::first_crossing(std::size_t index, const Vec3d& origin, const Vec3d& direction,
                                                double t_min, double t_max, BlobQueryWork& work) const {
    BlobRayCache& cache = BlobRayCache::for_this_thread();
    cache.begin(*this, origin, direction, t_min);
    const MetacubeRaySlices* own = cache.slices(std::uint32_t(index));
    if (!own) return std::nullopt;
    double a = std::max(own->t_in(), t_min), b = std::min(own->t_out(), t_max);
    if (!(a < b)) return std::nullopt;

    // Leave out what earlier queries of this ray settled: a settled stretch at the start moves a (and tells the
    // field's sign there), one at the end moves b (and a sign change onto it is a crossing at the new b).
    int sign_before_a = 0;
    if (const auto settled = cache.settled_at(a)) {
        if (settled->hi >= b) return std::nullopt;
        a = settled->hi;
        sign_before_a = settled->sign;
    }
    std::optional<BlobRayCache::Settled> settled_end = cache.settled_before(b);
    if (settled_end && settled_end->lo > a) {
        b = settled_end->lo;
    } else {
        settled_end.reset();
    }

    FieldAlongRay& field = t_field;
    field.reset(*kernel_, threshold_, a, b);
    field.add(std::uint32_t(index), elements_[index], *own);
    bvh_.for_each_near_segment(origin, direction, a, b, [&](std::uint32_t j) {
        if (j == index || !segment_may_meet(elements_[j], origin, direction, a, b)) return;
        if (const MetacubeRaySlices* slices = cache.slices(j)) field.add(j, elements_[j], *slices);
    });
    std::vector<FieldCrossing>& found = t_crossings;
    found.clear();
    const FieldAlongRay::Stop stop = field.crossings(t_min, t_max, sign_before_a, 1, found, work);
    if (stop.complete) cache.settle(a, stop.t_end, stop.sign_before_end);
    if (!found.empty()) return found.front().t;
    if (settled_end && stop.complete && stop.sign_before_end != settled_end->sign && b > t_min && b < t_max) {
        ++work.roots;
        return b;
    }
    return std::nullopt;
}

int BlobGroup::crossings(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                         std::vector<FieldCrossing>& out, BlobQueryWork& work) const {
    // Per-thread buffers: CSG asks this for every ray that meets its bounds. (Embree's element queries and this
    // never run inside one another, so sharing t_field is safe.)
    thread_local std::vector<std::uint32_t> near;
    thread_local std::vector<MetacubeRaySlices> slices;
    near.clear();
    slices.clear();
    bvh_.for_each_near_segment(origin, direction, t_min, t_max, [&](std::uint32_t i) {
        if (segment_may_meet(elements_[i], origin, direction, t_min, t_max)) near.push_back(i);
    });
    slices.reserve(near.size());  // FieldAlongRay keeps pointers to them: no reallocation below
    FieldAlongRay& field = t_field;
    field.reset(*kernel_, threshold_, t_min, t_max);
    for (std::uint32_t i : near)
        if (auto s = MetacubeRaySlices::slice(elements_[i], origin, direction)) {
            slices.push_back(*s);
            field.add(i, elements_[i], slices.back());
        }
    const int sign_at_start = field.value(t_min) > 0 ? 1 : -1;
    field.crossings(t_min, t_max, sign_at_start, std::numeric_limits<std::size_t>::max(), out, work);
    return sign_at_start;
}

}  // namespace isotrace
