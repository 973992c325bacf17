#pragma once
// Ray-sphere intersection in double precision with the cancellation-free discriminant of Haines et al.
// ("Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems, 2019). The direction need not
// be unit length (instanced rays arrive unnormalised).
#include <cmath>
#include <optional>

#include "renderer/math/vec3.h"

namespace isotrace {

struct SphereRoots {
    double t0, t1;  // t0 <= t1
};

inline std::optional<SphereRoots> intersect_sphere(const Vec3d& origin, const Vec3d& direction, const Vec3d& centre,
                                                   double radius) {
    const Vec3d f = origin - centre;
    const double a = dot(direction, direction);
    const double b = -dot(f, direction);  // half of the usual -b
    // |f - (f.d/a) d|^2 is the squared distance from the centre to the line, computed without cancellation.
    const Vec3d to_line = f + direction * (b / a);
    const double discriminant = a * (radius * radius - dot(to_line, to_line));
    if (discriminant < 0) return std::nullopt;
    const double root = std::sqrt(discriminant);
    const double c = dot(f, f) - radius * radius;
    const double q = b + std::copysign(root, b);
    double t0 = c / q, t1 = q / a;
    if (q == 0) t0 = t1 = 0;  // origin at the centre's projection and on the sphere
    if (t0 > t1) std::swap(t0, t1);
    return SphereRoots{t0, t1};
}

}  // namespace isotrace
