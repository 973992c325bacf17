#include "geometry/sweep/vertex_binding.h"

#include <cmath>
#include <stdexcept>

#include "geometry/sweep/sweep_surface.h"

namespace isotrace {

Vec3d bound_position(const SweepSurface& sweep, const VertexBinding& b) {
    const double r = sweep.radius(b.theta, b.t);
    const double rho = b.d < 0 && b.radius > 0 ? r * (b.radius + b.d) / b.radius : r + b.d;
    return sweep.place({rho * std::cos(b.theta), rho * std::sin(b.theta), 0}, b.t);
}

SweepBinder::SweepBinder(const SweepSurface& sweep, int samples_per_key) : sweep_(sweep) {
    if (samples_per_key < 2 || samples_per_key > 4096)
        throw std::invalid_argument("samples_per_key: must be in [2, 4096]");
    const std::vector<double>& keys = sweep.key_parameters();
    t_.reserve(sample_count(keys.size(), samples_per_key));
    for (std::size_t k = 0; k + 1 < keys.size(); ++k)
        for (int i = 0; i < samples_per_key; ++i) t_.push_back(keys[k] + (keys[k + 1] - keys[k]) * i / samples_per_key);
    t_.push_back(1);
    for (double t : t_) {
        centre_.push_back(sweep.centre(t));
        normal_.push_back(sweep.normal(t));
    }
}

double SweepBinder::plane_distance(const Vec3d& v, double t) const { return dot(v - sweep_.centre(t), sweep_.normal(t)); }

VertexBinding SweepBinder::binding_at(const Vec3d& v, double t) const {
    const Vec3d local = sweep_.orientation(t).rotate_back(v - sweep_.centre(t));
    VertexBinding b;
    b.t = t;
    b.theta = std::atan2(local.y, local.x);
    b.radius = sweep_.radius(b.theta, t);
    b.d = std::hypot(local.x, local.y) - b.radius;
    return b;
}

std::vector<VertexBinding> SweepBinder::all_roots(const Vec3d& v) const {
    std::vector<VertexBinding> roots;
    // A point on an end plane, up to rounding, is bound to that end section: with an exact test it could fall
    // just beyond it and take a far section instead (or none), and jump when the sweep is edited.
    const double end_tolerance = kEndPlaneTolerance * sweep_.size();
    double previous = dot(v - centre_[0], normal_[0]);
    if (std::abs(previous) <= end_tolerance) {
        roots.push_back(binding_at(v, t_[0]));
        previous = 0;
    }
    for (std::size_t i = 1; i < t_.size(); ++i) {
        double current = dot(v - centre_[i], normal_[i]);
        if (i + 1 == t_.size() && std::abs(current) <= end_tolerance) current = 0;
        if (current == 0) {
            roots.push_back(binding_at(v, t_[i]));
        } else if (previous != 0 && (previous < 0) != (current < 0)) {
            // Illinois regula falsi on the exact function: bracketed, superlinear, bounded.
            double a = t_[i - 1], b = t_[i], fa = previous, fb = current;
            int side = 0;
            for (int iteration = 0; iteration < 100 && b - a > 1e-15; ++iteration) {
                const double c = std::clamp(b - fb * (b - a) / (fb - fa), a, b);
                const double fc = plane_distance(v, c);
                if (fc == 0) {
                    a = b = c;
                    break;
                }
                if ((fc < 0) == (fb < 0)) {
                    b = c;
                    fb = fc;
                    if (side == 1) fa /= 2;
                    side = 1;
                } else {
                    a = c;
                    fa = fc;
                    if (side == -1) fb /= 2;
                    side = -1;
                }
            }
            roots.push_back(binding_at(v, std::abs(fa) < std::abs(fb) ? a : b));
        }
        previous = current;
    }
    return roots;
}

std::optional<VertexBinding> SweepBinder::bind(const Vec3d& v) const {
    std::optional<VertexBinding> best;
    for (const VertexBinding& root : all_roots(v)) {
        if (!best) {
            best = root;
            continue;
        }
        const bool inside = root.d <= 0, best_inside = best->d <= 0;
        if (inside != best_inside ? inside : std::abs(root.d) < std::abs(best->d)) best = root;
    }
    return best;
}

}  // namespace isotrace
