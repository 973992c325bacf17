// The implicit field of a blob group for the polygonisers: f = T − Σ wᵢ·fᵢ (negative inside), gradient −∇Σ; where
// a hard cube's step makes the surface, the gradient is along that face's normal instead (a step has no gradient).
//
// value_range sums each element's range over the box: the kernel is non-increasing in dist², so wᵢ·fᵢ lies between
// its values at the box's farthest and nearest squared distances. slope_range sums each element's slope
// 2wᵢ·f'(dist²)·(offset·d): f' lies between its values at those two distances (f is convex in dist²), and for a
// metaball offset·d = (p − c)·d is an interval of the box; a metacube's slope is bounded by its Lipschitz constant,
// a hard cube's (a step) not at all.
//
// may_reach_surface bounds the sum over the ball by Lipschitz constants: element i changes by at most
// |wᵢ|·2·|f'(0)|/Rᵢ per unit length (f is non-increasing and convex in r², so |df/dr²| ≤ |f'(0)|/R², and
// |∇dist²| = 2·dist ≤ 2R inside the support). Elements whose support misses the ball contribute nothing there.
#include <algorithm>
#include <cmath>

#include "geometry/field/box_index.h"
#include "geometry/implicit/blob_group_shape.h"

namespace isotrace {
namespace {

std::vector<FieldBox> support_boxes(const BlobGroup& group) {
    std::vector<FieldBox> boxes;
    for (const Metacube& element : group.elements()) {
        const WorldBounds b = element.support_bounds();
        boxes.push_back({b.lower, b.upper});
    }
    return boxes;
}

class BlobGroupField final : public ImplicitField {
public:
    explicit BlobGroupField(const BlobGroup& group)
        : group_(group), supports_boxes_(support_boxes(group)), supports_(supports_boxes_) {
        for (const Metacube& element : group.elements())
            slopes_.push_back(element.is_hard_cube()
                                  ? INFINITY
                                  : std::abs(element.weight()) * 2 * std::abs(group.kernel().unit_derivative(0)) /
                                        element.radius());
        for (const FieldBox& support : supports_boxes_) bounds_.extend(support);
        for (const Metacube& element : group.elements()) has_hard_cubes_ = has_hard_cubes_ || element.is_hard_cube();
        hair_ = 1e-6 * length(bounds_.extent());
    }

    double value(const Vec3d& p) const override { return group_.threshold() - group_.field(p); }
    // One list for the block: the elements whose support reaches the points' box, ascending.
    void values(std::span<const Vec3d> points, std::span<double> out) const override {
        FieldBox box = FieldBox::none();
        for (const Vec3d& p : points) box.extend(p);
        std::vector<std::uint32_t> listed;
        supports_.for_each_near(box.centre(), 0.5 * length(box.extent()) + hair_, [&](std::uint32_t i) {
            listed.push_back(i);
            return true;
        });
        std::sort(listed.begin(), listed.end());
        group_.fields(listed, points, out);
        for (double& v : out.first(points.size())) v = group_.threshold() - v;
    }
    Vec3d gradient(const Vec3d& p) const override {
        const Vec3d smooth = -group_.gradient(p);
        if (!has_hard_cubes_) return smooth;
        std::optional<BlobGroup::HardCubeFace> face = group_.nearest_hard_cube_face(p);
        if (!face) {
            // A point rounded just outside every support (a crossing on the outer face of a lone hard cube) is in
            // no cell: look for the cubes within a hair of it.
            std::vector<std::uint32_t> near;
            supports_.for_each_near(p, hair_, [&](std::uint32_t i) {
                near.push_back(i);
                return true;
            });
            face = group_.nearest_hard_cube_face_from(near, p);
        }
        if (!face) return smooth;
        // The step of the nearest hard cube's face decides the sign there when f differs in sign with the cube
        // and without it: the face is the surface, and its normal the gradient's direction (as the ray tracer's
        // normal), away from the cube for a positive weight. Its length, |f|/gap, makes |f|/|∇f| the distance to
        // the face; the floors keep it finite and non-zero on the face.
        const Metacube& cube = group_.elements()[face->element];
        const double sum = group_.field(p);
        const double without = cube.distance_squared(p) == 0 ? sum - cube.weight() : sum;
        const double threshold = group_.threshold();
        if ((without < threshold) == (without + cube.weight() < threshold)) return smooth;
        const double f = threshold - sum;
        const double length = (std::abs(f) + 1e-12 * threshold) / std::max(face->gap, 1e-12 * (1 + max_component(abs(p))));
        return face->normal * (cube.weight() > 0 ? length : -length);
    }
    FieldBox bounds() const override { return bounds_; }
    bool may_reach_surface(const Vec3d& centre, double radius) const override {
        double slope = 0;
        bool any = false;
        supports_.for_each_near(centre, radius, [&](std::uint32_t i) {
            any = true;
            slope += slopes_[i];
            return std::isfinite(slope);  // a hard cube's step: no bound, stop looking
        });
        if (!any) return false;  // the field is 0 < T all over the ball
        return !(std::abs(value(centre)) > slope * radius);
    }

    Interval value_range(const IntervalBox& box) const override {
        const WorldBounds bounds{box.lower(), box.upper()};
        Interval sum{0, 0};
        for_each_element_meeting(box, [&](const Metacube& element, std::uint32_t) {
            const double near2 = element.nearest_squared_distance(bounds), far2 = element.farthest_squared_distance(bounds);
            Interval own;
            if (element.is_hard_cube()) own = near2 > 0 ? Interval{0, 0} : (far2 == 0 ? Interval{1, 1} : Interval{0, 1});
            else own = {group_.kernel().value(far2, element.radius()), group_.kernel().value(near2, element.radius())};
            sum = sum + own * element.weight();
            return true;
        });
        return {group_.threshold() - sum.hi, group_.threshold() - sum.lo};
    }
    Interval slope_range(const IntervalBox& box, const Vec3d& direction) const override {
        const WorldBounds bounds{box.lower(), box.upper()};
        Interval sum{0, 0};
        bool bounded = true;
        for_each_element_meeting(box, [&](const Metacube& element, std::uint32_t i) {
            if (element.is_metaball()) {
                const double near2 = element.nearest_squared_distance(bounds);
                const double far2 = element.farthest_squared_distance(bounds);
                const Interval derivative{group_.kernel().derivative(near2, element.radius()),
                                          group_.kernel().derivative(far2, element.radius())};
                const Vec3d& c = element.centre();
                const Interval along =
                    (box.x + (-c.x)) * direction.x + (box.y + (-c.y)) * direction.y + (box.z + (-c.z)) * direction.z;
                sum = sum + derivative * along * (2 * element.weight());
            } else {
                const double reach = slopes_[i] * length(direction);
                bounded = std::isfinite(reach);
                sum = sum + Interval{-reach, reach};
            }
            return bounded;
        });
        if (!bounded) return Interval::unbounded();
        return {-sum.hi, -sum.lo};
    }

private:
    // Calls visit(element, index) for every element whose support may meet `box`; stops when visit returns false.
    template <class Visit>
    void for_each_element_meeting(const IntervalBox& box, Visit&& visit) const {
        const Vec3d centre = (box.lower() + box.upper()) * 0.5;
        supports_.for_each_near(centre, 0.5 * length(box.upper() - box.lower()),
                                [&](std::uint32_t i) { return visit(group_.elements()[i], i); });
    }

    const BlobGroup& group_;
    std::vector<FieldBox> supports_boxes_;
    BoxIndex supports_;
    std::vector<double> slopes_;  // per element, the Lipschitz constant of wᵢ·fᵢ (infinite for hard cubes)
    FieldBox bounds_ = FieldBox::none();
    bool has_hard_cubes_ = false;
    double hair_ = 0;  // how far off a hard cube's support a point may be rounded and still see its faces
};

}  // namespace

std::unique_ptr<ImplicitField> BlobGroupShape::implicit_field() const { return std::make_unique<BlobGroupField>(group()); }

}  // namespace isotrace
