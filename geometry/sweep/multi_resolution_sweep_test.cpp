// Multi-resolution sweeps: unedited levels reproduce the base sweep, and a fine edit survives a later coarse
// edit (the paper's Fig. 6), measured on deformed points.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "geometry/sweep/multi_resolution_sweep.h"
#include "geometry/sweep/sweep_deformer.h"
#include "geometry/sweep/sweep_test_support.h"

namespace isotrace {
namespace {

std::vector<Vec3d> points_inside_bent_tube(std::size_t count) {
    const SweepSurface sweep(sweep_test::bent_tube());
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(0, 1), angle(-3.14, 3.14);
    std::vector<Vec3d> points;
    for (std::size_t i = 0; i < count; ++i) {
        const double theta = angle(random), t = unit(random);
        points.push_back(bound_position(sweep, {theta, t, -sweep.radius(theta, t) * unit(random)}));
    }
    return points;
}

TEST(MultiResolutionSweep, UneditedLevelsReproduceTheBaseSweep) {
    const MultiResolutionSweep sweep(sweep_test::bent_tube(), 3);
    EXPECT_EQ(sweep.key_count(1), 5);
    EXPECT_EQ(sweep.key_count(2), 9);
    EXPECT_EQ(sweep.key_count(3), 17);
    const SweepSurface base = sweep.surface(1), fine = sweep.finest();
    double worst = 0;
    for (double t = 0; t <= 1; t += 0.01)
        for (double theta = -3; theta < 3.2; theta += 0.5) worst = std::max(worst, length(fine.point(theta, t) - base.point(theta, t)));
    EXPECT_LT(worst, 0.01 * base.size());  // re-interpolation through samples of the coarse sweep
}

TEST(MultiResolutionSweep, FineDetailSurvivesACoarseEdit) {
    const std::vector<Vec3d> points = points_inside_bent_tube(6000);
    MultiResolutionSweep sweep(sweep_test::bent_tube(), 3);
    const SweepDeformer deformer(sweep.finest(), points, SweepDeformer::Mode::global);
    ASSERT_EQ(deformer.statistics().bound, points.size());

    // Level-1 edit alone: turn key 2 by 25° (keys 3 and 4 follow).
    KeyEdit coarse_edit;
    coarse_edit.rotate = Quaternion::from_axis_angle({1, 0, 0}, 25);
    MultiResolutionSweep coarse_only = sweep;
    coarse_only.edit(1, 2, coarse_edit);
    const std::vector<Vec3d> after_coarse_only = deformer.deform(coarse_only.finest());

    // Level-3 detail first: push key 12 (near t = 0.7) sideways and widen it, then the same level-1 edit.
    KeyEdit detail;
    detail.translate = {0.15, 0, 0};
    detail.radius_offset = 0.05;
    sweep.edit(3, 12, detail);
    const std::vector<Vec3d> after_detail = deformer.deform(sweep.finest());
    sweep.edit(1, 2, coarse_edit);
    const std::vector<Vec3d> after_both = deformer.deform(sweep.finest());

    // The detail displacement before the coarse edit and its displacement on top of the coarse edit.
    double detail_before = 0, detail_after = 0;
    std::size_t peak = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double before = length(after_detail[i] - points[i]);
        if (before > detail_before) {
            detail_before = before;
            peak = i;
        }
    }
    detail_after = length(after_both[peak] - after_coarse_only[peak]);
    EXPECT_GT(detail_before, 0.1);
    EXPECT_NEAR(detail_after / detail_before, 1, 0.05) << detail_before << " " << detail_after;
    // Far from the detail (near t = 0) the detail changes nothing.
    for (std::size_t i = 0; i < points.size(); ++i)
        if (deformer.bindings()[i]->t < 0.15) {
            EXPECT_LT(length(after_both[i] - after_coarse_only[i]), 1e-3);
        }
}

TEST(MultiResolutionSweep, RejectsBadLevelsAndKeys) {
    EXPECT_THROW(MultiResolutionSweep(sweep_test::bent_tube(), 0), std::invalid_argument);
    EXPECT_THROW(MultiResolutionSweep(sweep_test::bent_tube(), MultiResolutionSweep::kMaxLevels + 1), std::invalid_argument);
    MultiResolutionSweep sweep(sweep_test::bent_tube(), 2);
    EXPECT_THROW(sweep.edit(3, 0, {}), std::invalid_argument);
    EXPECT_THROW(sweep.edit(2, 9, {}), std::invalid_argument);
    EXPECT_THROW(sweep.surface(0), std::invalid_argument);
}

}  // namespace
}  // namespace isotrace
