// The implicit field of a set of spheres (their union): the signed distance min over spheres of |p − c| − R,
// exact outside, for the polygonisers.
#include <cmath>
#include <limits>

#include "geometry/sphere/distance_range.h"
#include "geometry/sphere/sphere_shape.h"

namespace isotrace {
namespace {

class SphereField final : public ImplicitField {
public:
    explicit SphereField(const SphereShape& shape) : spheres_(shape.spheres()) {}

    double value(const Vec3d& p) const override { return signed_distance(p, nearest(p)); }
    Vec3d gradient(const Vec3d& p) const override {
        const Vec3d offset = p - spheres_[nearest(p)].centre;
        const double r = length(offset);
        return r > 0 ? offset / r : Vec3d{0, 0, 1};  // any direction at the centre itself
    }
    FieldBox bounds() const override {
        FieldBox box = FieldBox::none();
        for (const Sphere& s : spheres_) box.extend({s.centre - Vec3d{1, 1, 1} * s.radius, s.centre + Vec3d{1, 1, 1} * s.radius});
        return box;
    }
    // The union's surface is part of the spheres' surfaces.
    bool may_reach_surface(const Vec3d& centre, double radius) const override {
        for (std::size_t i = 0; i < spheres_.size(); ++i)
            if (std::abs(signed_distance(centre, i)) <= radius) return true;
        return false;
    }

    Interval value_range(const IntervalBox& box) const override {
        Interval range{INFINITY, INFINITY};
        for (const Sphere& s : spheres_) {
            const Interval own = distance_range(box, s.centre) + (-s.radius);
            range = min(range, own);
        }
        return range;
    }
    // The slope of the nearest sphere's distance is (p − c)·d/|p − c|: of the spheres that may be the nearest
    // over the box (their lower bound below the minimum's upper one), the hull of those slopes.
    Interval slope_range(const IntervalBox& box, const Vec3d& direction) const override {
        const double least_upper = value_range(box).hi;
        Interval slope{INFINITY, -INFINITY};
        for (const Sphere& s : spheres_) {
            const Interval distance = distance_range(box, s.centre);
            if (distance.lo - s.radius > least_upper) continue;
            Interval own{-length(direction), length(direction)};
            if (distance.lo > 0) {
                const Interval along = (box.x + (-s.centre.x)) * direction.x + (box.y + (-s.centre.y)) * direction.y +
                                       (box.z + (-s.centre.z)) * direction.z;
                own = along * Interval{1 / distance.hi, 1 / distance.lo};
            }
            slope = hull(slope, own);
        }
        return slope;
    }

private:
    double signed_distance(const Vec3d& p, std::size_t i) const {
        return length(p - spheres_[i].centre) - spheres_[i].radius;
    }
    std::size_t nearest(const Vec3d& p) const {
        std::size_t best = 0;
        for (std::size_t i = 1; i < spheres_.size(); ++i)
            if (signed_distance(p, i) < signed_distance(p, best)) best = i;
        return best;
    }

    std::vector<Sphere> spheres_;
};

}  // namespace

std::unique_ptr<ImplicitField> SphereShape::implicit_field() const { return std::make_unique<SphereField>(*this); }

}  // namespace isotrace
