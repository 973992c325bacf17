#pragma once
// Ray-sphere intersection in double precision with the cancellation-free discriminant of Haines et al.
// ("Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems, 2019). The direction need not
// be unit length (instanced rays arrive unnormalised).
#include <cmath>
#include <optional>

#include "geometry/polynomial/quadratic_roots.h"
#include "renderer/math/vec3.h"

namespace isotrace {

struct SphereRoots {
    double t0, t1;  // t0 <= t1
};

inline std::optional<SphereRoots> intersect_sphere(const Vec3d& origin, const Vec3d& direction, const Vec3d& centre,
                                                   double radius) {
    const Vec3d f = origin - centre;
    const double a = dot(direction, direction);
    const double half_b = dot(f, direction);
    // |f - (f.d/a) d|^2 is the squared distance from the centre to the line, computed without cancellation.
    const Vec3d to_line = f - direction * (half_b / a);
    const double quarter_discriminant = a * (radius * radius - dot(to_line, to_line));
    const QuadraticRoots roots = quadratic_roots_with_discriminant(a, 2 * half_b, dot(f, f) - radius * radius,
                                                                   4 * quarter_discriminant);
    if (roots.count == 0) return std::nullopt;
    return SphereRoots{roots.roots[0], roots.roots[roots.count - 1]};
}

}  // namespace isotrace
