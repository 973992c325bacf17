// The implicit field of a capped frustum: its exact signed distance, after Quílez's capped-cone distance (the
// nearer of the closest points on a cap and on the side, in the half plane of the axis and the point), for the
// polygonisers and for isosurfaces that use it as a term.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/cone/exact_distance_field.h"
#include "geometry/cone/frustum_shape.h"

namespace isotrace {
namespace {

class FrustumField final : public ExactDistanceField {
public:
    explicit FrustumField(const Frustum& frustum) : f_(frustum) {}

    double value(const Vec3d& p) const override { return nearest(p).distance; }
    Vec3d gradient(const Vec3d& p) const override { return nearest(p).gradient; }
    FieldBox bounds() const override {
        FieldBox box;
        frustum_bounds(f_, box.lower, box.upper);
        return box;
    }

private:
    struct Nearest {
        double distance;
        Vec3d gradient;
    };

    // In the half plane (ρ, y) of the point, y measured from the frustum's middle: the offset from the nearest point
    // of the caps' outline, ca, and of the side's segment, cb; the shorter is the distance, negative inside.
    Nearest nearest(const Vec3d& p) const {
        const Vec3d q = f_.local_point(p);
        const double rho = std::hypot(q.x, q.y), half = 0.5 * f_.height, y = q.z - half;
        const double cap_radius = y < 0 ? f_.base_radius : f_.top_radius;
        const double ca_x = rho - std::min(rho, cap_radius), ca_y = std::abs(y) - half;
        // The side runs from (r₀, −h/2) to (r₁, h/2): k2 is its direction.
        const double k2_x = f_.top_radius - f_.base_radius, k2_y = f_.height;
        const double along = std::clamp(((f_.top_radius - rho) * k2_x + (half - y) * k2_y) / (k2_x * k2_x + k2_y * k2_y), 0.0, 1.0);
        const double cb_x = rho - f_.top_radius + k2_x * along, cb_y = y - half + k2_y * along;
        const double sign = cb_x < 0 && ca_y < 0 ? -1.0 : 1.0;
        const double ca2 = ca_x * ca_x + ca_y * ca_y, cb2 = cb_x * cb_x + cb_y * cb_y;
        // The offset in the half plane, mapped back: ρ along the radial direction, y along the axis.
        const Vec3d radial = rho > 0 ? f_.world_vector({q.x / rho, q.y / rho, 0}) : f_.reference;
        double g_rho, g_y, length2;
        if (ca2 < cb2) {
            g_rho = ca_x, g_y = y < 0 ? -ca_y : ca_y, length2 = ca2;
        } else {
            g_rho = cb_x, g_y = cb_y, length2 = cb2;
        }
        const double distance = sign * std::sqrt(length2);
        if (!(length2 > 0)) {  // on the surface: the normal of the part
            const FrustumPart part = ca2 < cb2 ? (y < 0 ? FrustumPart::Base : FrustumPart::Top) : FrustumPart::Side;
            return {distance, frustum_normal(f_, part, p)};
        }
        const double scale = sign / std::sqrt(length2);
        return {distance, (radial * g_rho + f_.axis * g_y) * scale};
    }

    Frustum f_;
};

}  // namespace

std::unique_ptr<ImplicitField> FrustumShape::implicit_field() const {
    if (!frustum_.caps) throw std::invalid_argument(solid_problem());
    return std::make_unique<FrustumField>(frustum_);
}

}  // namespace isotrace
