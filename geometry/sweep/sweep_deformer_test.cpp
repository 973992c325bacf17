// Binding and deformation: identity, rigid motions, the binding round trip and its stability under small
// edits, the root choice, local weights and unbound points.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "geometry/sweep/sweep_deformer.h"
#include "geometry/sweep/sweep_surface.h"
#include "geometry/sweep/sweep_test_support.h"

namespace isotrace {
namespace {

// Points scattered around and inside the bent tube (some beyond its ends).
std::vector<Vec3d> scattered_points(std::size_t count) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> xy(-0.9, 1.6), z(-0.5, 4.5);
    std::vector<Vec3d> points;
    for (std::size_t i = 0; i < count; ++i) points.push_back({xy(random), xy(random) - 0.35, z(random)});
    return points;
}

std::vector<KeySection> moved_rigidly(std::vector<KeySection> keys, const Quaternion& rotation, const Vec3d& shift) {
    for (KeySection& key : keys) {
        key.centre = rotation.rotate(key.centre) + shift;
        key.orientation = rotation * key.orientation;
    }
    return keys;
}

TEST(SweepDeformer, UneditedSweepLeavesEveryPointInPlace) {
    const SweepSurface sweep(sweep_test::bent_tube());
    const std::vector<Vec3d> points = scattered_points(4000);
    const SweepDeformer deformer(sweep, points, SweepDeformer::Mode::global);
    EXPECT_GT(deformer.statistics().bound, 2000u);
    EXPECT_GT(deformer.statistics().unbound(), 100u);  // beyond the ends
    const std::vector<Vec3d> moved = deformer.deform(sweep);
    double worst = 0;
    for (std::size_t i = 0; i < points.size(); ++i) worst = std::max(worst, length(moved[i] - points[i]));
    EXPECT_LT(worst, 1e-6 * sweep.size());
}

TEST(SweepDeformer, RigidMotionOfAllKeysMovesBoundPointsRigidly) {
    const SweepSurface sweep(sweep_test::bent_tube());
    const std::vector<Vec3d> points = scattered_points(3000);
    const SweepDeformer deformer(sweep, points, SweepDeformer::Mode::global);
    const Quaternion rotation = Quaternion::from_axis_angle({1, 2, -0.5}, 73);
    const Vec3d shift(0.4, -1.2, 2.5);
    const std::vector<Vec3d> moved = deformer.deform(SweepSurface(moved_rigidly(sweep.keys(), rotation, shift)));
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3d expected = deformer.bindings()[i] ? rotation.rotate(points[i]) + shift : points[i];
        ASSERT_LT(length(moved[i] - expected), 1e-6 * sweep.size()) << i;
    }
}

TEST(SweepDeformer, BindingRoundTrip) {
    const SweepSurface sweep(sweep_test::bent_tube());
    const SweepBinder binder(sweep);
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> unit(0, 1), angle(-3.1, 3.1), depth(-0.9, 0.2);
    for (int i = 0; i < 500; ++i) {
        VertexBinding b{angle(random), 0.02 + 0.96 * unit(random), 0};
        b.d = depth(random) * sweep.radius(b.theta, b.t);  // from near the axis to a little outside
        const std::optional<VertexBinding> back = binder.bind(bound_position(sweep, b));
        ASSERT_TRUE(back);
        EXPECT_NEAR(back->t, b.t, 1e-9);
        EXPECT_NEAR(back->theta, b.theta, 1e-9);
        EXPECT_NEAR(back->d, b.d, 1e-9);
    }
}

TEST(SweepDeformer, SmallEditsKeepEveryPointOnItsBranch) {
    // A strongly bent ring: points outside it lie on several section planes, so the root choice matters.
    const std::vector<KeySection> keys = sweep_test::ring(1, 240, 9, sweep_test::constant_radii(0.35));
    const SweepSurface sweep(keys);
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> coordinate(-1.6, 1.6);
    std::vector<Vec3d> points;
    for (int i = 0; i < 3000; ++i) points.push_back({coordinate(random), coordinate(random), 0.5 * coordinate(random)});
    const SweepDeformer deformer(sweep, points, SweepDeformer::Mode::global);
    for (double degrees : {1.0, 2.0}) {
        std::vector<RelativeKeySection> relative = to_relative(keys);
        relative[4].rotation = relative[4].rotation * Quaternion::from_axis_angle({1, 0, 0}, degrees);
        for (double& r : relative[5].radii) r *= 1 + degrees / 100;
        const SweepSurface edited(to_absolute(relative));
        const std::vector<Vec3d> moved = deformer.deform(edited);
        const SweepBinder rebinder(edited);
        std::size_t compared = 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const auto& before = deformer.bindings()[i];
            if (!before || before->d > 0) continue;  // inside points: their section is unique
            const auto after = rebinder.bind(moved[i]);
            ASSERT_TRUE(after) << i;
            EXPECT_NEAR(after->t, before->t, 1e-6) << i;
            // Inside points keep their share of the section's radius.
            EXPECT_NEAR(1 + after->d / after->radius, 1 + before->d / before->radius, 1e-6) << i;
            ++compared;
        }
        EXPECT_GT(compared, 200u);
    }
}

TEST(SweepDeformer, WideningASectionScalesWhatIsInsideIt) {
    // A thin plate through the axis of a cylinder: widened sections must spread it, not tear it at the axis.
    const SweepSurface sweep(sweep_test::cylinder(1, 3));
    const std::vector<Vec3d> points = {{-0.01, 0, 1.5}, {0.01, 0, 1.5}, {0.5, 0, 1.5}, {1.5, 0, 1.5}};
    const SweepDeformer deformer(sweep, points, SweepDeformer::Mode::global);
    const std::vector<Vec3d> moved = deformer.deform(SweepSurface(sweep_test::cylinder(2, 3)));
    EXPECT_NEAR(length(moved[1] - moved[0]), 0.04, 1e-9);  // twice as far apart, not 2 + 0.02
    EXPECT_NEAR(moved[2].x, 1.0, 1e-9);                    // half way out stays half way out
    EXPECT_NEAR(moved[3].x, 2.5, 1e-9);                    // outside: keeps its distance from the surface
}

TEST(SweepDeformer, PointsOnAnEndPlaneBindToThatEnd) {
    const SweepSurface sweep(sweep_test::cylinder(0.5, 2));
    const SweepBinder binder(sweep);
    for (const double z : {-1e-12, 0.0, 1e-12}) {
        const auto start = binder.bind({0.2, 0.1, z});
        ASSERT_TRUE(start) << z;
        EXPECT_NEAR(start->t, 0, 1e-9);
        const auto end = binder.bind({0.2, 0.1, 2 + z});
        ASSERT_TRUE(end) << z;
        EXPECT_NEAR(end->t, 1, 1e-9);
    }
    EXPECT_FALSE(binder.bind({0.2, 0.1, -1e-6}));  // beyond the end, not on it
}

TEST(SweepDeformer, ChoosesTheContainingSectionThenTheNearestSurface) {
    const SweepSurface sweep(sweep_test::ring(1, 240, 9, sweep_test::constant_radii(0.35)));
    const SweepBinder binder(sweep);
    // Inside the tube at 30°: three section planes pass through this point (the ring's planes all contain the
    // z axis); only the section at 30° contains it.
    const double phi = std::numbers::pi / 6;
    const Vec3d inside(1.1 * std::cos(phi), 1.1 * std::sin(phi), 0.05);
    const std::vector<VertexBinding> roots = binder.all_roots(inside);
    ASSERT_GE(roots.size(), 2u);
    const auto chosen = binder.bind(inside);
    ASSERT_TRUE(chosen);
    EXPECT_LE(chosen->d, 0);
    EXPECT_NEAR(length(sweep.centre(chosen->t) - Vec3d(std::cos(phi), std::sin(phi), 0)), 0, 0.01);
    // Outside every section: the nearest surface wins.
    const Vec3d outside(-1.5 * std::cos(phi), -1.5 * std::sin(phi), 0);  // outside the tube, on two section planes
    for (const VertexBinding& root : binder.all_roots(outside)) EXPECT_GE(std::abs(root.d), std::abs(binder.bind(outside)->d));
}

TEST(SweepDeformer, LocalWeightsFallFromTheAxisToTheSurface) {
    const SweepSurface sweep(sweep_test::cylinder(1, 2, 4));
    const std::vector<Vec3d> points{{0, 0, 1}, {0.5, 0, 1}, {0, -0.999, 1}, {1.5, 0, 1}, {0, 0, 3}};
    const SweepDeformer deformer(sweep, points, SweepDeformer::Mode::local);
    EXPECT_NEAR(deformer.weights()[0], 1, 1e-12);    // on the axis: f(0) = 1
    EXPECT_NEAR(deformer.weights()[1], 0.5, 1e-12);  // the default cubic is symmetric about u = ½
    EXPECT_LT(deformer.weights()[2], 1e-5);          // just inside the surface
    EXPECT_EQ(deformer.weights()[3], 0);             // outside: not moved in local mode
    EXPECT_FALSE(deformer.bindings()[4]);            // beyond the end: unbound
    EXPECT_EQ(deformer.statistics().bound, 4u);
    EXPECT_EQ(deformer.statistics().inside, 3u);
    EXPECT_EQ(deformer.statistics().weighted, 3u);  // the point just inside has a tiny weight
    // Lifting all keys by 1 lifts the axis point fully, the half-way point by half, the outer one not at all.
    std::vector<KeySection> lifted = sweep.keys();
    for (KeySection& key : lifted) key.centre.z += 1;
    const std::vector<Vec3d> moved = deformer.deform(SweepSurface(lifted));
    EXPECT_NEAR(moved[0].z, 2, 1e-12);
    EXPECT_NEAR(moved[1].z, 1.5, 1e-12);
    EXPECT_EQ(moved[3].z, 1);
    EXPECT_EQ(moved[4].z, 3);
}

TEST(SweepDeformer, WeightCurveRejectsValuesOutsideTheUnitInterval) {
    EXPECT_THROW(WeightCurve({1, 1.2, 0}), std::invalid_argument);
    EXPECT_THROW(WeightCurve({1, NAN, 0}), std::invalid_argument);
    EXPECT_THROW(WeightCurve({1}), std::invalid_argument);
    const WeightCurve linear({1, 0}, 1);
    EXPECT_NEAR(linear(0.25), 0.75, 1e-15);
    try {
        WeightCurve({1, 0.5, -0.1});
    } catch (const std::invalid_argument& error) {
        EXPECT_STREQ(error.what(), "weight_curve[2]: control value -0.1 is outside [0, 1]");
    }
}

}  // namespace
}  // namespace isotrace
