#include "geometry/sweep/sweep_volume.h"

#include <array>
#include <cmath>
#include <numbers>

#include "geometry/sweep/sweep_surface.h"

namespace isotrace {
namespace {

// Five-point Gauss–Legendre on [0, 1]: exact for polynomials up to degree 9.
constexpr std::array<double, 5> kNodes{0.046910077030668, 0.230765344947158, 0.5, 0.769234655052842,
                                       0.953089922969332};
constexpr std::array<double, 5> kWeights{0.118463442528095, 0.239314335249683, 0.284444444444444,
                                         0.239314335249683, 0.118463442528095};

template <class Integrand>
double integrate(int intervals, double length, Integrand f) {
    double sum = 0;
    const double h = length / intervals;
    for (int i = 0; i < intervals; ++i)
        for (std::size_t q = 0; q < kNodes.size(); ++q) sum += kWeights[q] * h * f((i + kNodes[q]) * h);
    return sum;
}

double volume(const SweepSurface& sweep, int intervals, bool with_moments) {
    return integrate(intervals, 1.0, [&](double t) {
        const SectionIntegrals s = section_integrals(sweep, t);
        const Quaternion q = sweep.orientation(t);
        double rate = s.area * dot(q.axis_z(), sweep.centre_velocity(t));
        if (with_moments) {
            const Vec3d omega = sweep.angular_velocity(t);
            rate += omega.x * s.moment_y - omega.y * s.moment_x;
        }
        return rate;
    });
}

}  // namespace

SectionIntegrals section_integrals(const SweepSurface& sweep, double t) {
    SectionIntegrals s;
    const int m = sweep.radius_samples();
    // Per knot interval of r in θ (r is a cubic there), several sub-pieces for the trigonometric factors.
    const int pieces = 4 * m;
    const double h = 2 * std::numbers::pi / pieces;
    for (int i = 0; i < pieces; ++i)
        for (std::size_t q = 0; q < kNodes.size(); ++q) {
            const double theta = (i + kNodes[q]) * h;
            const double r = sweep.radius(theta, t), w = kWeights[q] * h;
            s.area += w * r * r / 2;
            s.moment_x += w * r * r * r * std::cos(theta) / 3;
            s.moment_y += w * r * r * r * std::sin(theta) / 3;
        }
    return s;
}

double paper_volume(const SweepSurface& sweep, int intervals) { return volume(sweep, intervals, false); }
double sweep_volume(const SweepSurface& sweep, int intervals) { return volume(sweep, intervals, true); }

}  // namespace isotrace
