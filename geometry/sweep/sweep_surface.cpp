#include "geometry/sweep/sweep_surface.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "geometry/curves/curve_interpolation.h"
#include "geometry/curves/shape_preserving_curve.h"

namespace isotrace {
namespace {

[[noreturn]] void fail(std::size_t key, const std::string& field, const std::string& problem) {
    throw std::invalid_argument("key_sections[" + std::to_string(key) + "]" + (field.empty() ? "" : "." + field) +
                                ": " + problem);
}

std::string number(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

std::vector<KeySection> checked(std::vector<KeySection> keys) {
    if (keys.size() < 2)
        throw std::invalid_argument("key_sections: a sweep needs at least 2 key sections, got " +
                                    std::to_string(keys.size()));
    if (keys.size() > kMaxInterpolatedPoints)
        throw std::invalid_argument("key_sections: at most " + std::to_string(kMaxInterpolatedPoints) +
                                    " key sections, got " + std::to_string(keys.size()));
    const std::size_t m = keys.front().radii.size();
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const KeySection& key = keys[k];
        if (!is_finite(key.centre)) fail(k, "center", "not finite");
        if (!key.orientation.is_finite()) fail(k, "orientation", "not finite");
        if (std::abs(key.orientation.norm() - 1) > 1e-6)
            fail(k, "orientation", "not a unit quaternion (|q| = " + number(key.orientation.norm()) + ")");
        if (key.radii.size() != m)
            fail(k, "radii", "has " + std::to_string(key.radii.size()) + " values, key section 0 has " + std::to_string(m));
        if (m < 3 || m > kMaxInterpolatedPoints)
            fail(k, "radii", "needs 3 to " + std::to_string(kMaxInterpolatedPoints) + " values, got " + std::to_string(m));
        for (std::size_t j = 0; j < m; ++j)
            if (!(key.radii[j] > 0) || !std::isfinite(key.radii[j]))
                fail(k, "radii[" + std::to_string(j) + "]", "must be finite and > 0, got " + number(key.radii[j]));
        if (k > 0 && key.centre == keys[k - 1].centre) fail(k, "center", "coincides with the previous key section's");
        // Sections whose planes face each other make the sweep turn back on itself: every vertex between them
        // would have two sections and the deformation would fold.
        if (k > 0 && dot(key.orientation.axis_z(), keys[k - 1].orientation.axis_z()) < 0)
            fail(k, "normal", "points against key section " + std::to_string(k - 1) +
                                  "'s normal (more than 90° from it): the sweep would turn back on itself");
    }
    return keys;
}

std::vector<Vec3d> centres_of(const std::vector<KeySection>& keys) {
    std::vector<Vec3d> centres;
    for (const KeySection& key : keys) centres.push_back(key.centre);
    return centres;
}

// Each orientation on the same side of the 4-sphere as the one before (q and −q are the same rotation).
std::vector<Quaternion> consistent_orientations(const std::vector<KeySection>& keys) {
    std::vector<Quaternion> q;
    for (const KeySection& key : keys) {
        Quaternion o = normalize(key.orientation);
        if (!q.empty() && dot(q.back(), o) < 0) o = -1.0 * o;
        q.push_back(o);
    }
    return q;
}

std::vector<std::vector<double>> radii_of(const std::vector<KeySection>& keys) {
    std::vector<std::vector<double>> radii;
    for (const KeySection& key : keys) radii.push_back(key.radii);
    return radii;
}

}  // namespace

SweepSurface::SweepSurface(std::vector<KeySection> keys, std::vector<double> parameters, SweepSpline spline)
    : keys_(checked(std::move(keys))),
      parameters_(parameters.empty() ? chord_length_parameters(centres_of(keys_)) : std::move(parameters)),
      spline_(spline),
      centre_(spline == SweepSpline::cubic ? interpolate_curve(centres_of(keys_), parameters_, 3)
                                           : shape_preserving_curve(centres_of(keys_), parameters_)),
      orientation_(interpolate_curve(consistent_orientations(keys_), parameters_, 2)),
      radius_(radii_of(keys_), parameters_, spline == SweepSpline::shape_preserving) {
    // The |Q| guard, on a sampling fine enough for a quadratic between keys.
    const int samples = 64 * int(keys_.size());
    for (int i = 0; i <= samples; ++i) {
        const double t = double(i) / samples;
        const double norm = orientation_(t).norm();
        if (!(norm >= kMinOrientationNorm)) {
            std::size_t k = 1;
            while (k + 1 < parameters_.size() && parameters_[k] < t) ++k;
            fail(k, "orientation", "the orientation curve nearly vanishes between key sections " + std::to_string(k - 1) +
                                       " and " + std::to_string(k) + " (|Q| = " + number(norm) +
                                       "): they are almost half a turn apart; insert a key section between them");
        }
    }
    Vec3d low(INFINITY, INFINITY, INFINITY), high = -low;
    double largest_radius = 0;
    for (const KeySection& key : keys_) {
        low = min(low, key.centre);
        high = max(high, key.centre);
        for (double r : key.radii) largest_radius = std::max(largest_radius, r);
    }
    size_ = length(high - low) + 2 * largest_radius;
}

Vec3d SweepSurface::angular_velocity(double t) const {
    const Quaternion raw = orientation_(t), velocity = orientation_.first(t);
    const double norm = raw.norm();
    const Quaternion q = (1 / norm) * raw;
    const Quaternion q_velocity = (1 / norm) * (velocity - dot(q, velocity) * q);
    return 2.0 * (q.conjugate() * q_velocity).vector();
}

Vec3d SweepSurface::point(double theta, double t) const {
    const double r = radius(theta, t);
    return place({r * std::cos(theta), r * std::sin(theta), 0}, t);
}

}  // namespace isotrace
