#pragma once
// Analytic fields for the isosurface tests, each with interval bounds of its value and of its slope along a
// direction (written out by hand, as the expression tape computes them), and a float64 brute-force oracle of a
// ray's first surface point.
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/isosurface/isosurface_shape.h"

namespace isotrace::isosurface_test {

inline Interval norm(const Interval& x, const Interval& y, const Interval& z) {
    return sqrt_of_non_negative(square(x) + square(y) + square(z));
}
// The slope of a 1-Lipschitz field along d.
inline Interval lipschitz_slope(const Vec3d& d) { return {-length(d), length(d)}; }

// |p| − R.
class SphereField : public ImplicitField {
public:
    explicit SphereField(double radius) : radius_(radius) {}
    double value(const Vec3d& p) const override { return length(p) - radius_; }
    Vec3d gradient(const Vec3d& p) const override { return safe_normalize(p, Vec3d{0, 0, 1}); }
    FieldBox bounds() const override { return {Vec3d{-1, -1, -1} * radius_, Vec3d{1, 1, 1} * radius_}; }
    bool may_reach_surface(const Vec3d& c, double r) const override { return std::abs(value(c)) <= r; }
    Interval value_range(const IntervalBox& b) const override { return norm(b.x, b.y, b.z) + (-radius_); }
    // (p·d)/|p| where |p| is bounded away from 0.
    Interval slope_range(const IntervalBox& b, const Vec3d& d) const override {
        const Interval n = norm(b.x, b.y, b.z);
        if (!(n.lo > 0)) return lipschitz_slope(d);
        const Interval along = b.x * d.x + b.y * d.y + b.z * d.z;
        return along * Interval{1 / n.hi, 1 / n.lo};
    }

private:
    double radius_;
};

// The torus of radii (major, minor) around z: √((√(x²+y²) − R)² + z²) − r.
class TorusField : public ImplicitField {
public:
    TorusField(double major, double minor) : major_(major), minor_(minor) {}
    double value(const Vec3d& p) const override {
        const double q = std::hypot(p.x, p.y) - major_;
        return std::hypot(q, p.z) - minor_;
    }
    Vec3d gradient(const Vec3d& p) const override {
        const double ring = std::hypot(p.x, p.y);
        const Vec3d on_circle = ring > 0 ? Vec3d{p.x, p.y, 0} * (major_ / ring) : Vec3d{major_, 0, 0};
        return safe_normalize(p - on_circle, Vec3d{0, 0, 1});
    }
    FieldBox bounds() const override {
        const double a = major_ + minor_;
        return {{-a, -a, -minor_}, {a, a, minor_}};
    }
    bool may_reach_surface(const Vec3d& c, double r) const override { return std::abs(value(c)) <= r; }
    Interval value_range(const IntervalBox& b) const override {
        const Interval q = sqrt_of_non_negative(square(b.x) + square(b.y)) + (-major_);
        return sqrt_of_non_negative(square(q) + square(b.z)) + (-minor_);
    }
    Interval slope_range(const IntervalBox&, const Vec3d& d) const override { return lipschitz_slope(d); }

private:
    double major_, minor_;
};

// n·p − c, n unit.
class PlaneField : public ImplicitField {
public:
    PlaneField(const Vec3d& normal, double offset) : normal_(normal), offset_(offset) {}
    double value(const Vec3d& p) const override { return dot(normal_, p) - offset_; }
    Vec3d gradient(const Vec3d&) const override { return normal_; }
    FieldBox bounds() const override { return {Vec3d{-1e3, -1e3, -1e3}, Vec3d{1e3, 1e3, 1e3}}; }
    bool may_reach_surface(const Vec3d& c, double r) const override { return std::abs(value(c)) <= r; }
    Interval value_range(const IntervalBox& b) const override {
        return b.x * normal_.x + b.y * normal_.y + b.z * normal_.z + (-offset_);
    }
    Interval slope_range(const IntervalBox&, const Vec3d& d) const override { return Interval::point(dot(normal_, d)); }

private:
    Vec3d normal_;
    double offset_;
};

// The gyroid sin kx cos ky + sin ky cos kz + sin kz cos kx.
class GyroidField : public ImplicitField {
public:
    explicit GyroidField(double frequency) : k_(frequency) {}
    double value(const Vec3d& p) const override {
        const Vec3d q = p * k_;
        return std::sin(q.x) * std::cos(q.y) + std::sin(q.y) * std::cos(q.z) + std::sin(q.z) * std::cos(q.x);
    }
    Vec3d gradient(const Vec3d& p) const override {
        const Vec3d q = p * k_;
        const double sx = std::sin(q.x), cx = std::cos(q.x), sy = std::sin(q.y), cy = std::cos(q.y),
                     sz = std::sin(q.z), cz = std::cos(q.z);
        return Vec3d{cx * cy - sz * sx, -sx * sy + cy * cz, -sy * sz + cz * cx} * k_;
    }
    FieldBox bounds() const override { return {Vec3d{-1e3, -1e3, -1e3}, Vec3d{1e3, 1e3, 1e3}}; }
    bool may_reach_surface(const Vec3d&, double) const override { return true; }
    Interval value_range(const IntervalBox& b) const override {
        const Trig t = trig(b);
        return t.sx * t.cy + t.sy * t.cz + t.sz * t.cx;
    }
    Interval slope_range(const IntervalBox& b, const Vec3d& d) const override {
        const Trig t = trig(b);
        const Interval gx = t.cx * t.cy - t.sz * t.sx, gy = t.cy * t.cz - t.sx * t.sy, gz = t.cz * t.cx - t.sy * t.sz;
        return (gx * d.x + gy * d.y + gz * d.z) * k_;
    }

private:
    struct Trig {
        Interval sx, cx, sy, cy, sz, cz;
    };
    Trig trig(const IntervalBox& b) const {
        const Interval x = b.x * k_, y = b.y * k_, z = b.z * k_;
        return {sin_range(x), cos_range(x), sin_range(y), cos_range(y), sin_range(z), cos_range(z)};
    }
    double k_;
};

// A unit sphere with a spike along +x: a rod of radius `width` from the centre out to x = length,
// min(|p| − 1, max(√(y²+z²) − w, x − L, −x)).
class SpikedSphereField : public ImplicitField {
public:
    SpikedSphereField(double width, double spike_length) : width_(width), length_(spike_length) {}
    double value(const Vec3d& p) const override {
        const double rod = std::max({std::hypot(p.y, p.z) - width_, p.x - length_, -p.x});
        return std::min(length(p) - 1, rod);
    }
    Vec3d gradient(const Vec3d& p) const override {
        const double sphere = length(p) - 1, radial = std::hypot(p.y, p.z) - width_;
        if (sphere <= std::max({radial, p.x - length_, -p.x})) return safe_normalize(p, Vec3d{1, 0, 0});
        if (radial >= p.x - length_ && radial >= -p.x) return safe_normalize(Vec3d{0, p.y, p.z}, Vec3d{0, 1, 0});
        return p.x - length_ >= -p.x ? Vec3d{1, 0, 0} : Vec3d{-1, 0, 0};
    }
    FieldBox bounds() const override { return {{-1, -1, -1}, {length_, 1, 1}}; }
    bool may_reach_surface(const Vec3d& c, double r) const override { return std::abs(value(c)) <= r; }
    Interval value_range(const IntervalBox& b) const override {
        const Interval sphere = norm(b.x, b.y, b.z) + (-1.0);
        const Interval rod =
            max(max(sqrt_of_non_negative(square(b.y) + square(b.z)) + (-width_), b.x + (-length_)), b.x * -1.0);
        return min(sphere, rod);
    }
    Interval slope_range(const IntervalBox&, const Vec3d& d) const override { return lipschitz_slope(d); }

private:
    double width_, length_;
};

// Thin sheets inside the unit ball: max(sin(k·x) + level, |p| − 1), with level just below 1, so the solid is
// slabs about (1 − level)·√2/k thick and 2π/k apart.
class SineShellField : public ImplicitField {
public:
    SineShellField(double frequency, double level) : k_(frequency), level_(level) {}
    double value(const Vec3d& p) const override { return std::max(std::sin(k_ * p.x) + level_, length(p) - 1); }
    Vec3d gradient(const Vec3d& p) const override {
        if (std::sin(k_ * p.x) + level_ >= length(p) - 1) return {k_ * std::cos(k_ * p.x), 0, 0};
        return safe_normalize(p, Vec3d{1, 0, 0});
    }
    FieldBox bounds() const override { return {{-1, -1, -1}, {1, 1, 1}}; }
    bool may_reach_surface(const Vec3d&, double) const override { return true; }
    Interval value_range(const IntervalBox& b) const override {
        return max(sin_range(b.x * k_) + level_, norm(b.x, b.y, b.z) + (-1.0));
    }
    Interval slope_range(const IntervalBox& b, const Vec3d& d) const override {
        return hull(cos_range(b.x * k_) * (k_ * d.x), lipschitz_slope(d));
    }

private:
    double k_, level_;
};

// An isosurface of `field` in `container` with the default octree.
inline std::unique_ptr<IsosurfaceShape> isosurface(std::shared_ptr<const ImplicitField> field, const Container& container,
                                                   IsosurfaceSettings settings = {}) {
    MemoryBudget memory;
    std::vector<IntervalBox> cells = surface_cells(*field, container, settings.octree, memory);
    return std::make_unique<IsosurfaceShape>(std::move(field), container, std::move(cells), settings);
}

inline Container unit_box(double half) { return Container::box(Vec3d{-1, -1, -1} * half, Vec3d{1, 1, 1} * half); }

// The first t where the ray enters or leaves the solid {f < 0} ∩ container, by sampling f every `step` (every
// `fine_step` inside `fine_windows`, sorted stretches of t where thin features may lie) and bisecting the first
// sign change to the last bit; nothing when no sample changes sign.
struct Window {
    double lo, hi;
};
inline std::optional<double> oracle_first_crossing(const ImplicitField& field, const Container& container,
                                                   const Vec3d& o, const Vec3d& d, double step,
                                                   const std::vector<Window>& fine_windows, double fine_step) {
    const auto clip = container.clip(o, d, 0, INFINITY);
    if (!clip) return std::nullopt;
    const auto g = [&](double t) { return field.value(o + d * t); };
    double t = clip->lo, g_t = g(t);
    if (g_t < 0 && clip->lo > 0) return clip->lo;
    std::size_t window = 0;
    while (t < clip->hi) {
        while (window < fine_windows.size() && fine_windows[window].hi < t) ++window;
        double next = t + step;
        if (window < fine_windows.size()) {
            if (fine_windows[window].lo <= t) next = t + fine_step;
            else next = std::min(next, fine_windows[window].lo);
        }
        next = std::min(clip->hi, next);
        const double g_next = g(next);
        if ((g_t < 0) != (g_next < 0)) {
            double lo = t, hi = next;
            for (int i = 0; i < 200 && hi - lo > 4e-16 * std::abs(hi); ++i) {
                const double mid = 0.5 * (lo + hi);
                ((g(mid) < 0) == (g_t < 0) ? lo : hi) = mid;
            }
            return 0.5 * (lo + hi);
        }
        t = next;
        g_t = g_next;
    }
    if (g_t < 0) return clip->hi;
    return std::nullopt;
}

}  // namespace isotrace::isosurface_test
