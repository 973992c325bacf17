#include "geometry/implicit/blob_group.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/implicit/blob_cell_queries.h"
#include "geometry/implicit/field_kernels.h"
#include "geometry/implicit/sphere_prefilter.h"
#include "geometry/implicit/surface_region.h"

namespace isotrace {

BlobGroup::BlobGroup(std::vector<Metacube> elements, std::unique_ptr<const FieldFunction> kernel, double threshold)
    : elements_(std::move(elements)), kernel_(std::move(kernel)), queries_(&blob_cell_queries()),
      threshold_(threshold) {
    validate_threshold(threshold_);
    const std::optional<std::size_t> index = field_kernel_index(kernel_->name());
    if (!index) throw std::invalid_argument("field: unknown field function \"" + std::string(kernel_->name()) + "\"");
    kernel_index_ = *index;
    build_index();
}

void BlobGroup::build_index() {
    spheres_.resize(elements_.size());
    centre_bound_ = 0;
    metaballs_only_ = std::all_of(elements_.begin(), elements_.end(),
                                  [](const Metacube& element) { return element.is_metaball(); });
    for (std::size_t i = 0; i < elements_.size(); ++i) {
        spheres_[i] = BoundingSphere::of(elements_[i]);
        const BoundingSphere& s = spheres_[i];
        centre_bound_ = std::max(centre_bound_, length(Vec3d(s.centre[0], s.centre[1], s.centre[2])));
    }
    // MetaballMarch's case: metaballs alone under a kernel that is one polynomial piece of degree ≤ 3 in r²/R².
    const std::span<const FieldPiece> pieces = kernel_->unit_pieces();
    metaball_march_ = metaballs_only_ && pieces.size() == 1 && pieces[0].is_polynomial && pieces[0].degree <= 3;
    cells_.build(elements_);
    cells_.restrict_to_surface([&](const WorldBounds& box, std::span<const std::uint32_t> ids) {
        if (metaball_march_) return metaball_surface_region(box, ids, elements_, kernel_->unit_pieces()[0], threshold_);
        return with_kernel(kernel_index_, *kernel_, [&](const auto& kernel) {
            return surface_region(box, ids, elements_, kernel, threshold_);
        });
    });
}

void BlobGroup::bake(const Transform& similarity, double scale) {
    for (Metacube& element : elements_) {
        OrientedBox box = element.skeleton();
        box.centre = similarity.point(box.centre);
        for (Vec3d& axis : box.axes) axis = normalize(similarity.vector(axis));
        box.half_size = box.half_size * scale;
        element = Metacube(box, element.radius() * scale, element.weight());
    }
    build_index();
}

std::size_t BlobGroup::memory_bytes() const {
    return sizeof(*this) + elements_.capacity() * sizeof(Metacube) + spheres_.capacity() * sizeof(BoundingSphere) +
           cells_.memory_bytes();
}

std::optional<FieldCrossing> BlobGroup::first_crossing(const Vec3d& origin, const Vec3d& direction, double t_min,
                                                       double t_max, BlobQueryWork& work) const {
    std::optional<FieldCrossing> found;
    cells_.walk(origin, direction, t_min, t_max, [&](std::uint32_t cell, double, double) {
        if (const auto hit = queries_->first_hit_in_cell(*this, cell, origin, direction, t_min, t_max, work))
            found = hit->crossing;
        return !found;
    });
    return found;
}

int BlobGroup::crossings(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                         std::vector<FieldCrossing>& out, BlobQueryWork& work) const {
    const int sign_at_start = field(origin + direction * t_min) > threshold_ ? 1 : -1;
    const std::size_t first = out.size();
    cells_.walk(origin, direction, t_min, t_max, [&](std::uint32_t cell, double, double) {
        queries_->crossings_in_cell(*this, cell, origin, direction, t_min, t_max, out, first, work);
        return true;
    });
    return sign_at_start;
}

template <class Visit>
void BlobGroup::for_each_reaching(std::span<const std::uint32_t> listed, const Vec3d& point, Visit&& visit) const {
    // The float test rejects most listed elements four at a time; the exact test decides for the rest.
    for_each_near(listed, spheres_, PointNearSpheres(point, centre_bound_), [&](std::uint32_t j) {
        if (spheres_[j].may_contain(point)) visit(elements_[j]);
    });
}

double BlobGroup::field(const Vec3d& point) const {
    return with_kernel(kernel_index_, *kernel_, [&](const auto& kernel) {
        double sum = 0;
        for_each_reaching(cells_.elements_near(point), point,
                          [&](const Metacube& element) { sum += element.field(kernel, point); });
        return sum;
    });
}

void BlobGroup::fields(std::span<const std::uint32_t> listed, std::span<const Vec3d> points,
                       std::span<double> sums) const {
    std::fill(sums.begin(), sums.end(), 0.0);
    Vec3d lower = points.empty() ? Vec3d{} : points[0], upper = lower;
    for (const Vec3d& p : points) {
        lower = min(lower, p);
        upper = max(upper, p);
    }
    std::vector<std::uint32_t> reached(points.size());
    with_kernel(kernel_index_, *kernel_, [&](const auto& kernel) {
        // A term is 0 outside the element's support, so adding only those inside it gives field()'s sums (whose
        // list is the point's cell's: the same elements reach the point, in the same ascending order). An element
        // whose sphere misses the points' box reaches none of them; of the others, the points it may reach are
        // gathered first without branches (about a third of a block's points are), then only those are
        // evaluated. Local copies: nothing the loops write can change them.
        for (std::uint32_t j : listed) {
            const BoundingSphere sphere = spheres_[j];
            if (!sphere.may_meet(lower, upper)) continue;
            std::size_t count = 0;
            for (std::size_t i = 0; i < points.size(); ++i) {
                reached[count] = std::uint32_t(i);
                count += sphere.may_contain(points[i]);
            }
            const Metacube element = elements_[j];
            for (std::size_t k = 0; k < count; ++k) sums[reached[k]] += element.field(kernel, points[reached[k]]);
        }
    });
}

void BlobGroup::for_each_term(std::span<const std::uint32_t> listed, const Vec3d& point,
                              const std::function<void(std::uint32_t element, double term)>& visit) const {
    with_kernel(kernel_index_, *kernel_, [&](const auto& kernel) {
        for_each_reaching(listed, point, [&](const Metacube& element) {
            visit(std::uint32_t(&element - elements_.data()), element.field(kernel, point));
        });
    });
}

Vec3d BlobGroup::gradient(const Vec3d& point) const { return gradient_from(cells_.elements_near(point), point); }

Vec3d BlobGroup::gradient_from(std::span<const std::uint32_t> near, const Vec3d& point) const {
    return with_kernel(kernel_index_, *kernel_, [&](const auto& kernel) {
        Vec3d sum(0, 0, 0);
        for_each_reaching(near, point, [&](const Metacube& element) { sum += element.field_gradient(kernel, point); });
        return sum;
    });
}

Vec3d BlobGroup::normal(const Vec3d& point) const { return normal_from(cells_.elements_near(point), point); }

Vec3d BlobGroup::normal_in_cell(std::uint32_t cell, const Vec3d& point) const {
    return normal_from(cells_.elements_of(cell), point);
}

Vec3d BlobGroup::normal_from(std::span<const std::uint32_t> near, const Vec3d& point) const {
    if (const std::optional<Vec3d> normal = outward_normal(gradient_from(near, point)))
        return *normal;
    // Only hard cubes (step fields) meet here: take the face of the nearest hard-cube boundary.
    const std::optional<HardCubeFace> face = nearest_hard_cube_face_from(near, point);
    return face ? face->normal : Vec3d(0, 0, 1);
}

std::optional<BlobGroup::HardCubeFace> BlobGroup::nearest_hard_cube_face(const Vec3d& point) const {
    return nearest_hard_cube_face_from(cells_.elements_near(point), point);
}

std::optional<BlobGroup::HardCubeFace> BlobGroup::nearest_hard_cube_face_from(std::span<const std::uint32_t> near,
                                                                               const Vec3d& point) const {
    std::optional<HardCubeFace> nearest;
    for (std::uint32_t j : near) {
        const Metacube& element = elements_[j];
        if (!element.is_hard_cube()) continue;
        const OrientedBox box = element.skeleton();
        const Vec3d p = box.to_local(point);
        for (int axis = 0; axis < 3; ++axis) {
            const double gap = std::abs(std::abs(p[axis]) - box.half_size[axis]);
            if (nearest && !(gap < nearest->gap)) continue;
            Vec3d local(0, 0, 0);
            local[axis] = p[axis] >= 0 ? 1 : -1;
            nearest = HardCubeFace{j, box.to_world_vector(local), gap};
        }
    }
    return nearest;
}

}  // namespace isotrace
