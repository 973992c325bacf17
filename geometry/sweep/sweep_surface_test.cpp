// Sweep surfaces: interpolation of the key sections, relative key sections, frames, and rejected input.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geometry/sweep/sweep_surface.h"
#include "geometry/sweep/sweep_test_support.h"

namespace isotrace {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(SweepSurface, CylinderIsExact) {
    const SweepSurface sweep(sweep_test::cylinder(0.5, 2, 5));
    for (double t = 0; t <= 1; t += 0.05)
        for (double theta = -3; theta < 3.2; theta += 0.37) {
            const Vec3d p = sweep.point(theta, t);
            EXPECT_NEAR(std::hypot(p.x, p.y), 0.5, 1e-13);
            EXPECT_NEAR(p.z, 2 * t, 1e-13);
            EXPECT_NEAR(std::atan2(p.y, p.x), std::remainder(theta, 2 * kPi), 1e-12);
        }
}

TEST(SweepSurface, InterpolatesEveryKeySection) {
    std::vector<KeySection> keys = sweep_test::bent_tube();
    keys[2].orientation = -1.0 * keys[2].orientation;  // the same rotation: the sign is made consistent
    const SweepSurface sweep(keys);
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const double t = sweep.key_parameters()[k];
        EXPECT_NEAR(length(sweep.centre(t) - keys[k].centre), 0, 1e-13);
        EXPECT_NEAR(std::abs(dot(sweep.orientation(t), keys[k].orientation)), 1, 1e-13);
        for (std::size_t j = 0; j < keys[k].radii.size(); ++j)
            EXPECT_NEAR(sweep.radius(2 * kPi * double(j) / double(keys[k].radii.size()), t), keys[k].radii[j], 1e-13);
    }
    // No flip between keys 1 and 3: the orientation curve's norm stays near 1.
    for (double t = 0; t <= 1; t += 0.01) EXPECT_GT(std::abs(dot(sweep.orientation(t), keys[1].orientation)), 0.9);
}

TEST(SweepSurface, RadiusIsPeriodicAndSmoothInTheta) {
    const SweepSurface sweep(sweep_test::bent_tube());
    const double e = 1e-6;
    for (double t : {0.1, 0.5, 0.9}) {
        EXPECT_NEAR(sweep.radius(0, t), sweep.radius(2 * kPi, t), 1e-14);
        const double slope_before = (sweep.radius(0, t) - sweep.radius(-e, t)) / e;
        const double slope_after = (sweep.radius(e, t) - sweep.radius(0, t)) / e;
        EXPECT_NEAR(slope_before, slope_after, 1e-4);
    }
}

TEST(SweepSurface, AngularVelocityMatchesFiniteDifferencesOfTheFrame) {
    const SweepSurface sweep(sweep_test::ring(2, 200, 7, sweep_test::constant_radii(0.3)));
    const double h = 1e-6;
    for (double t : {0.1, 0.45, 0.8}) {
        const Quaternion q = sweep.orientation(t);
        const Vec3d omega = sweep.angular_velocity(t);
        // R′·e_x = R·(ω × e_x): compare in world space.
        const Vec3d x_rate = (sweep.orientation(t + h).axis_x() - sweep.orientation(t - h).axis_x()) / (2 * h);
        const Vec3d expected = q.rotate(cross(omega, Vec3d(1, 0, 0)));
        EXPECT_NEAR(length(x_rate - expected), 0, 1e-6 * length(omega));
        // A ring of 200° turns the section about its local y axis (the ring's axis, −z) by 200° in total.
        EXPECT_NEAR(omega.x, 0, 0.02 * length(omega));
        EXPECT_NEAR(omega.z, 0, 0.02 * length(omega));
    }
}

TEST(SweepSurface, RelativeKeySectionsCarryTheFollowingKeysAlong) {
    const std::vector<KeySection> keys = sweep_test::bent_tube();
    std::vector<RelativeKeySection> relative = to_relative(keys);
    const std::vector<KeySection> back = to_absolute(relative);
    for (std::size_t k = 0; k < keys.size(); ++k) {
        EXPECT_NEAR(length(back[k].centre - keys[k].centre), 0, 1e-14);
        EXPECT_NEAR(dot(back[k].orientation, keys[k].orientation), 1, 1e-14);
    }
    // Turning key 2 by 30° about its x axis turns keys 3 and 4 rigidly about key 2's centre (Fig. 2).
    const Quaternion turn = Quaternion::from_axis_angle(keys[2].orientation.axis_x(), 30);
    relative[2].rotation = relative[2].rotation * Quaternion::from_axis_angle({1, 0, 0}, 30);
    const std::vector<KeySection> edited = to_absolute(relative);
    EXPECT_NEAR(length(edited[1].centre - keys[1].centre), 0, 1e-14);
    EXPECT_NEAR(length(edited[2].centre - keys[2].centre), 0, 1e-14);
    for (std::size_t k = 3; k < keys.size(); ++k) {
        const Vec3d expected = keys[2].centre + turn.rotate(keys[k].centre - keys[2].centre);
        EXPECT_NEAR(length(edited[k].centre - expected), 0, 1e-13);
        EXPECT_NEAR(std::abs(dot(edited[k].orientation, turn * keys[k].orientation)), 1, 1e-13);
    }
}

TEST(SweepSurface, ShapePreservingSplineDoesNotNarrowNextToWidenedKeys) {
    // Widening the middle of a cylinder: the cubic's radii dip below the unedited ones next to the widened keys
    // (a teapot's bottom shrinks when its belly is widened); the shape-preserving spline's stay at or above them.
    std::vector<KeySection> keys = sweep_test::cylinder(1, 6, 7);
    for (std::size_t k : {3u, 4u})
        for (double& r : keys[k].radii) r *= 1.3;
    auto narrowest = [&](SweepSpline spline) {
        const SweepSurface sweep(keys, {}, spline);
        double low = INFINITY;
        for (int i = 0; i <= 600; ++i) low = std::min(low, sweep.radius(0.3, i / 600.0));
        return low;
    };
    EXPECT_LT(narrowest(SweepSpline::cubic), 0.99);
    EXPECT_GE(narrowest(SweepSpline::shape_preserving), 1 - 1e-12);
    const SweepSurface sweep(keys, {}, SweepSpline::shape_preserving);
    for (const KeySection& key : keys) {  // still through every key section
        const double t = sweep.key_parameters()[std::size_t(&key - keys.data())];
        EXPECT_LT(length(sweep.centre(t) - key.centre), 1e-12);
        EXPECT_NEAR(sweep.radius(0.3, t), key.radii[0], 1e-12);
    }
}

TEST(SweepSurface, RejectsBadKeySections) {
    auto expect_error = [](std::vector<KeySection> keys, const std::string& fragment) {
        try {
            SweepSurface sweep(std::move(keys));
            ADD_FAILURE() << "no error; expected " << fragment;
        } catch (const std::invalid_argument& error) {
            EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
        }
    };
    std::vector<KeySection> keys = sweep_test::cylinder(1, 2);
    expect_error({keys[0]}, "at least 2 key sections");
    auto bad = keys;
    bad[1].radii[3] = 0;
    expect_error(bad, "key_sections[1].radii[3]: must be finite and > 0");
    bad = keys;
    bad[2].radii[0] = NAN;
    expect_error(bad, "key_sections[2].radii[0]");
    bad = keys;
    bad[1].orientation = {NAN, 0, 0, 0};
    expect_error(bad, "key_sections[1].orientation: not finite");
    bad = keys;
    bad[1].orientation = {2, 0, 0, 0};
    expect_error(bad, "key_sections[1].orientation: not a unit quaternion (|q| = 2)");
    bad = keys;
    bad[3].radii.pop_back();
    expect_error(bad, "key_sections[3].radii: has 15 values");
    bad = keys;
    bad[2].centre = bad[1].centre;
    expect_error(bad, "key_sections[2].center: coincides");
    bad = keys;
    bad[2].orientation = Quaternion::from_axis_angle({1, 0, 0}, 120);
    expect_error(bad, "key_sections[2].normal: points against key section 1's normal");
    // Signs made consistent keep |Q| near 1 for evenly spaced keys; very uneven spacing makes the quadratic
    // overshoot through the origin of R⁴: here twists about the (shared) normal (found by a random search).
    const double z[] = {0, 0.8210, 0.9925, 1}, twist[] = {0, 131.4, 248.4, 387.8};
    bad = keys;
    for (std::size_t k = 0; k < 4; ++k) bad[k] = {{0, 0, z[k]}, Quaternion::from_axis_angle({0, 0, 1}, twist[k]), bad[k].radii};
    expect_error(bad, "almost half a turn apart");
}

}  // namespace
}  // namespace isotrace
