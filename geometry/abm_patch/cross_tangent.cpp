#include "geometry/abm_patch/cross_tangent.h"

#include <algorithm>

namespace isotrace {

CrossTangent::CrossTangent(std::shared_ptr<const SpaceCurve> curve, bool reversed,
                           std::shared_ptr<const BSplineCurve<Vec3d>> normal, double facing, BSplineCurve<double> reach)
    : curve_(std::move(curve)), reversed_(reversed), normal_(std::move(normal)), facing_(facing), reach_(std::move(reach)) {}

Vec3d side_direction(const SpaceCurve& curve, bool reversed, double along) {
    const double t = reversed ? 1 - along : along, sign = reversed ? -1 : 1;
    const Vec3d derivative = curve.value_and_tangent(t).second;
    if (length(derivative) > 0) return sign * normalize(derivative);
    constexpr double step = 1e-6;
    const Vec3d chord = curve(std::min(t + step, 1.0)) - curve(std::max(t - step, 0.0));
    return length(chord) > 0 ? sign * normalize(chord) : Vec3d{};
}

Vec3d inward_across(const Vec3d& normal, const Vec3d& tangent, const Vec3d& fallback) {
    const Vec3d across = normal - dot(normal, tangent) * tangent;
    if (!(length(tangent) > 0) || !(length(across) > 1e-9 * length(normal))) return fallback;
    // T × inward = front normal for a loop running counter-clockwise seen from the front, so inward = N × T.
    return normalize(cross(across, tangent));
}

Vec3d CrossTangent::operator()(double along) const {
    const double t = reversed_ ? 1 - along : along;
    const Vec3d inward = inward_across(facing_ * (*normal_)(t), side_direction(*curve_, reversed_, along), Vec3d{});
    return reach_(along) * inward;
}

std::pair<Vec3d, Vec3d> CrossTangent::value_and_derivative(double along) const {
    constexpr double h = 1e-6;
    const double before = std::max(along - h, 0.0), after = std::min(along + h, 1.0);
    return {(*this)(along), (1 / (after - before)) * ((*this)(after) - (*this)(before))};
}

}  // namespace isotrace
