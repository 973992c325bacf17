#pragma once
// Uniform sampling of the solid angle a rectangle subtends at a point, after Ureña, Fajardo and King, "An
// Area-Preserving Parametrization for Spherical Rectangles": the directions towards the rectangle are drawn with
// density 1/Ω (Ω the solid angle), each as the rectangle's point it looks at. Computed in double.
#include <array>
#include <optional>

#include "renderer/math/vec3.h"

namespace isotrace {

class SphericalRectangle {
public:
    // Below this solid angle (steradians) the parametrisation is not built (make() says nullopt): its angles
    // would be differences of nearly equal numbers, and sampling by area is then as good.
    static constexpr double kMinSolidAngle = 1e-4;

    // The rectangle corner + x·edge_x + y·edge_y (x, y in [0, 1]; perpendicular edges) as seen from `reference`;
    // nullopt when it subtends less than kMinSolidAngle (also when the reference lies in its plane).
    static std::optional<SphericalRectangle> make(const Vec3d& reference, const Vec3d& corner, const Vec3d& edge_x,
                                                  const Vec3d& edge_y);

    double solid_angle() const { return solid_angle_; }
    // The rectangle's (x, y) in [0, 1]² of the direction that u in [0, 1)² maps to, uniformly by solid angle.
    std::array<double, 2> sample(std::array<double, 2> u) const;

private:
    SphericalRectangle() = default;

    // The rectangle in the local frame: x in [x0, x1], y in [y0, y1] at depth z0 < 0 below the reference.
    double x0_ = 0, x1_ = 0, y0_ = 0, y1_ = 0, z0_ = 0;
    double b0_ = 0, b1_ = 0, k_ = 0;  // the paper's constants of the u warp
    double solid_angle_ = 0;
};

}  // namespace isotrace
