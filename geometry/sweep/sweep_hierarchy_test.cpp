// Hierarchies of sweeps: forward deformation keeps loop-bound key sections on the parent, independent parts
// leave gaps, backward deformation reaches its targets (or reports the residual), and rule 3 keeps volume ratios.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "geometry/sweep/sweep_fold.h"
#include "geometry/sweep/sweep_hierarchy.h"
#include "geometry/sweep/sweep_test_support.h"
#include "geometry/sweep/sweep_volume.h"

namespace isotrace {
namespace {

using sweep_test::constant_radii;

// A teapot-like tree: a vertical body of radius 1, a handle arching from its side (both ends on the body's
// surface), a spout leaving the other side.
struct Teapot {
    SweepHierarchy tree;
    int body, handle, spout;
    std::vector<KeySection> handle_keys;
};

Teapot make_teapot(bool preserve_volume) {
    Teapot pot{SweepHierarchy(preserve_volume), 0, 0, 0, {}};
    pot.body = pot.tree.add_root("body", sweep_test::cylinder(1, 2, 5));
    const Quaternion out = Quaternion::from_axis_angle({0, 1, 0}, -90);  // normal along −x
    pot.handle_keys = {{{-1, 0, 1.6}, out, constant_radii(0.12)},
                       {{-1.5, 0, 1.55}, Quaternion::from_axis_angle({0, 1, 0}, -135), constant_radii(0.12)},
                       {{-1.7, 0, 1.0}, Quaternion::from_axis_angle({0, 1, 0}, 180), constant_radii(0.12)},
                       {{-1.5, 0, 0.45}, Quaternion::from_axis_angle({0, 1, 0}, 135), constant_radii(0.12)},
                       {{-1, 0, 0.4}, Quaternion::from_axis_angle({0, 1, 0}, 90), constant_radii(0.12)}};
    pot.handle = pot.tree.add_child("handle", pot.handle_keys, pot.body, Attachment::loop);
    const Quaternion spout_out = Quaternion::from_axis_angle({0, 1, 0}, 60);
    std::vector<KeySection> spout{{{1, 0, 0.8}, spout_out, constant_radii(0.2)},
                                  {{1.5, 0, 1.1}, spout_out, constant_radii(0.15)},
                                  {{2.0, 0, 1.4}, spout_out, constant_radii(0.1)}};
    pot.spout = pot.tree.add_child("spout", spout, pot.body, Attachment::branch);
    return pot;
}

std::vector<KeySection> edited_body(const SweepSurface& body) {
    std::vector<KeySection> keys = body.keys();
    for (KeySection& key : keys) key.centre = key.centre + Vec3d(0.3, 0.1, 0.2);
    for (std::size_t k = 1; k < 4; ++k)
        for (double& r : keys[k].radii) r *= 1.25;
    keys[4].orientation = Quaternion::from_axis_angle({1, 0, 0}, 15);
    return keys;
}

// How far a point lies from the surface of `sweep`, measured in its section (|d| of its binding).
double off_surface(const SweepSurface& sweep, const Vec3d& p) {
    const auto binding = SweepBinder(sweep).bind(p);
    return binding ? std::abs(binding->d) : INFINITY;
}

TEST(SweepHierarchy, BodyEditKeepsLoopEndsOnTheBodyAndMovesTheSpout) {
    Teapot pot = make_teapot(false);
    ASSERT_LT(off_surface(pot.tree.surface(pot.body), pot.handle_keys[0].centre), 1e-9);
    const Vec3d spout_tip_before = pot.tree.surface(pot.spout).keys()[2].centre;
    pot.tree.set_keys(pot.body, edited_body(pot.tree.surface(pot.body)));
    const SweepSurface& body = pot.tree.surface(pot.body);
    const SweepSurface& handle = pot.tree.surface(pot.handle);
    EXPECT_LT(off_surface(body, handle.keys()[0].centre), 1e-8);  // residual of the loop's ends
    EXPECT_LT(off_surface(body, handle.keys()[4].centre), 1e-8);
    for (std::size_t k = 0; k < 5; ++k) {  // every loop key keeps its binding to the body (eq. 11)
        const auto b = SweepBinder(body).bind(handle.keys()[k].centre);
        ASSERT_TRUE(b);
        EXPECT_NEAR(b->t, pot.tree.bindings(pot.handle)[k].position.t, 1e-8);
        EXPECT_NEAR(b->d, pot.tree.bindings(pot.handle)[k].position.d, 1e-8);
    }
    // The spout's base follows the widened body, and its tip moves with it.
    EXPECT_LT(off_surface(body, pot.tree.surface(pot.spout).keys()[0].centre), 1e-8);
    EXPECT_GT(length(pot.tree.surface(pot.spout).keys()[2].centre - spout_tip_before), 0.2);
}

TEST(SweepHierarchy, PartsDeformedIndependentlyLeaveGaps) {
    // The same body edit without the hierarchy: the handle stays where it was and its ends leave the body (Fig. 8).
    Teapot pot = make_teapot(false);
    const SweepSurface independent_body(edited_body(pot.tree.surface(pot.body)));
    const SweepSurface independent_handle(pot.handle_keys);
    const double gap_top = off_surface(independent_body, independent_handle.keys()[0].centre);
    const double gap_bottom = off_surface(independent_body, independent_handle.keys()[4].centre);
    EXPECT_GT(std::max(gap_top, gap_bottom), 0.1);
    pot.tree.set_keys(pot.body, edited_body(pot.tree.surface(pot.body)));
    EXPECT_LT(off_surface(pot.tree.surface(pot.body), pot.tree.surface(pot.handle).keys()[0].centre), 1e-8);
}

TEST(SweepHierarchy, VolumeRatiosAreKeptUnderRuleThree) {
    Teapot pot = make_teapot(true);
    auto ratio = [&](int child) { return sweep_volume(pot.tree.surface(child)) / sweep_volume(pot.tree.surface(pot.body)); };
    const double handle_before = ratio(pot.handle), spout_before = ratio(pot.spout);
    const double body_before = sweep_volume(pot.tree.surface(pot.body));
    pot.tree.set_keys(pot.body, edited_body(pot.tree.surface(pot.body)));
    EXPECT_GT(sweep_volume(pot.tree.surface(pot.body)) / body_before, 1.2);  // the body really grew
    EXPECT_NEAR(ratio(pot.handle) / handle_before, 1, 0.01);
    EXPECT_NEAR(ratio(pot.spout) / spout_before, 1, 0.01);
    // Without rule 3 the handle keeps its radii, so its share shrinks.
    Teapot plain = make_teapot(false);
    plain.tree.set_keys(plain.body, edited_body(plain.tree.surface(plain.body)));
    EXPECT_LT(sweep_volume(plain.tree.surface(plain.handle)) / sweep_volume(plain.tree.surface(plain.body)), 0.9 * handle_before);
}

TEST(SweepHierarchy, AChildEditCarriesItsParentUnderRuleThree) {
    Teapot pot = make_teapot(true);
    auto volume = [&](int node) { return sweep_volume(pot.tree.surface(node)); };
    const double body_before = volume(pot.body), spout_before = volume(pot.spout), handle_before = volume(pot.handle);
    std::vector<KeySection> spout = pot.tree.surface(pot.spout).keys();
    for (KeySection& key : spout)
        for (double& r : key.radii) r *= 1.4;  // about doubles the spout's volume
    pot.tree.set_keys(pot.spout, spout);
    const double growth = volume(pot.spout) / spout_before;
    EXPECT_GT(growth, 1.8);
    EXPECT_NEAR(volume(pot.body) / body_before / growth, 1, 0.01);    // the body follows the spout
    EXPECT_NEAR(volume(pot.handle) / handle_before / growth, 1, 0.01);  // and the handle the body
    // The handle's ends are still on the grown body.
    EXPECT_LT(off_surface(pot.tree.surface(pot.body), pot.tree.surface(pot.handle).keys()[0].centre), 1e-8);
}

TEST(SweepHierarchy, PullingTheHandleDeformsTheBody) {
    Teapot pot = make_teapot(false);
    const Vec3d target = pot.handle_keys[2].centre + Vec3d(-0.1, 0, 0.25);
    const BackwardResult result = pot.tree.pull(pot.handle, {{2, target}});
    EXPECT_TRUE(result.converged);
    EXPECT_LE(result.residual, SweepHierarchy::kBackwardTolerance * pot.tree.surface(pot.body).size());
    EXPECT_GE(result.iterations, 1);
    EXPECT_LT(length(pot.tree.surface(pot.handle).keys()[2].centre - target), 1e-5);
    // The body changed (the handle's middle is bound to the body's middle section), and the handle's ends are
    // still on it.
    const SweepSurface original_body(sweep_test::cylinder(1, 2, 5));
    double body_change = 0;
    for (double theta = -3; theta < 3.2; theta += 0.5)
        body_change = std::max(body_change, length(pot.tree.surface(pot.body).point(theta, 0.5) - original_body.point(theta, 0.5)));
    EXPECT_GT(body_change, 0.05);
    EXPECT_LT(off_surface(pot.tree.surface(pot.body), pot.tree.surface(pot.handle).keys()[0].centre), 1e-8);
}

TEST(SweepHierarchy, UnreachableTargetReportsItsResidual) {
    Teapot pot = make_teapot(false);
    // One key section asked to be at two places 0.4 apart: the best is half-way, 0.2 from each target.
    const Vec3d middle = pot.handle_keys[2].centre;
    const BackwardResult result = pot.tree.pull(pot.handle, {{2, middle + Vec3d(0, 0.2, 0)}, {2, middle - Vec3d(0, 0.2, 0)}}, 20);
    EXPECT_FALSE(result.converged);
    EXPECT_NEAR(result.residual, 0.2, 1e-3);
    EXPECT_LE(result.iterations, 20);
    EXPECT_THROW(pot.tree.set_keys(pot.handle, pot.handle_keys), std::invalid_argument);
    EXPECT_THROW(pot.tree.pull(pot.spout, {{0, {0, 0, 0}}}), std::invalid_argument);
    EXPECT_THROW(pot.tree.pull(pot.handle, {{7, {0, 0, 0}}}), std::invalid_argument);
}

TEST(SweepHierarchy, APullBeyondTheParentsReachStopsAndSaysWhy) {
    Teapot pot = make_teapot(false);
    const SweepSurface body_before = pot.tree.surface(pot.body);
    const BackwardResult far = pot.tree.pull(pot.handle, {{2, pot.handle_keys[2].centre + Vec3d(0, 0, 1000)}}, 200);
    EXPECT_FALSE(far.converged);
    EXPECT_GT(far.residual, 900);
    EXPECT_NE(far.limit.find("the body sweep would stretch or shrink more than 2×"), std::string::npos) << far.limit;
    EXPECT_LE(sweep_stretch(body_before, pot.tree.surface(pot.body)), SweepHierarchy::kMaxPullStretch);
    EXPECT_EQ(sweep_fold(pot.tree.surface(pot.body)), "");
}

TEST(SweepHierarchy, AReachablePullKeepsTheParentsSectionsInOrder) {
    Teapot pot = make_teapot(false);
    const BackwardResult result = pot.tree.pull(pot.handle, {{2, pot.handle_keys[2].centre + Vec3d(0, 0, 0.5)}});
    EXPECT_TRUE(result.converged);
    EXPECT_EQ(result.limit, "");
    EXPECT_EQ(sweep_fold(pot.tree.surface(pot.body)), "");
}

TEST(SweepHierarchy, KeySectionOutsideTheParentIsAnError) {
    SweepHierarchy tree;
    const int body = tree.add_root("body", sweep_test::cylinder(1, 2, 4));
    std::vector<KeySection> above{{{0, 0, 3}, Quaternion::identity(), constant_radii(0.1)},
                                  {{0, 0, 4}, Quaternion::identity(), constant_radii(0.1)}};
    try {
        tree.add_child("lid", above, body, Attachment::branch);
        ADD_FAILURE();
    } catch (const std::invalid_argument& error) {
        EXPECT_STREQ(error.what(), "lid.key_sections[0]: its centre lies on no cross-section plane of the parent sweep");
    }
}

}  // namespace
}  // namespace isotrace
