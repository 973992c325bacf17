// Volumes: eq. (3) against closed forms and mesh volumes, and the general form on the offset-disc torus where
// eq. (3) misses the first-moment term by φ·A·e (Pappus).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/mesh/mesh_closedness.h"
#include "geometry/mesh/mesh_test_support.h"
#include "geometry/sweep/sweep_surface.h"
#include "geometry/sweep/sweep_tessellation.h"
#include "geometry/sweep/sweep_test_support.h"
#include "geometry/sweep/sweep_volume.h"

namespace isotrace {
namespace {

constexpr double kPi = std::numbers::pi;
using mesh_test::signed_volume;

TEST(SweepVolume, CylinderHasItsClosedFormVolume) {
    const SweepSurface sweep(sweep_test::cylinder(0.5, 2, 4));
    const double exact = kPi * 0.25 * 2;
    EXPECT_NEAR(paper_volume(sweep), exact, 1e-12);
    EXPECT_NEAR(sweep_volume(sweep), exact, 1e-12);
    const SectionIntegrals s = section_integrals(sweep, 0.3);
    EXPECT_NEAR(s.area, kPi * 0.25, 1e-13);
    EXPECT_NEAR(s.moment_x, 0, 1e-13);
    EXPECT_NEAR(s.moment_y, 0, 1e-13);
}

// The volume of the closed tessellation extrapolated to zero cell size (Richardson: the error of inscribed
// polygons falls as h²), so that a coarse, fast tessellation gives a precise reference.
double extrapolated_mesh_volume(const SweepSurface& sweep, int theta_steps, int t_steps) {
    const TriangleMeshData coarse = tessellate(sweep, {theta_steps, t_steps, true});
    const TriangleMeshData fine = tessellate(sweep, {2 * theta_steps, 2 * t_steps, true});
    EXPECT_EQ(closed_mesh_problem(fine), "");
    return (4 * signed_volume(fine) - signed_volume(coarse)) / 3;
}

TEST(SweepVolume, StraightTwistedSweepMatchesItsMeshVolume) {
    // Straight axis, changing non-circular sections, turning about the axis: no moment term (ω ∥ N).
    std::vector<KeySection> keys;
    for (int k = 0; k < 5; ++k) {
        std::vector<double> radii;
        for (int j = 0; j < 12; ++j) radii.push_back(0.4 + 0.1 * k + 0.15 * std::cos(4 * kPi * j / 12));
        keys.push_back({{0, 0, 0.5 * k * (1 + 0.1 * k)}, Quaternion::from_axis_angle({0, 0, 1}, 20.0 * k), radii});
    }
    const SweepSurface sweep(keys);
    const double mesh_volume = extrapolated_mesh_volume(sweep, 128, 128);
    EXPECT_NEAR(paper_volume(sweep) / mesh_volume, 1, 1e-5);
    EXPECT_NEAR(sweep_volume(sweep), paper_volume(sweep), 1e-9 * mesh_volume);
}

TEST(SweepVolume, OffsetDiscTorusNeedsTheFirstMomentTerm) {
    // A disc of radius a whose centre is offset by e from C(t), swept three quarters round a ring of radius 2.
    const double a = 0.5, e = 0.3, ring = 2, turn = 1.5 * kPi;
    const SweepSurface sweep(sweep_test::ring(ring, 270, 13, sweep_test::offset_circle_radii(a, e, 64)));
    const double mesh_volume = extrapolated_mesh_volume(sweep, 128, 256);
    const double general = sweep_volume(sweep), paper = paper_volume(sweep);
    EXPECT_NEAR(general / mesh_volume, 1, 1e-5);
    const double pappus_gap = turn * kPi * a * a * e;  // φ·A·e
    EXPECT_NEAR((general - paper) / pappus_gap, 1, 0.01);
    EXPECT_GT(std::abs(paper / mesh_volume - 1), 0.1);
    // And Pappus for the whole: V ≈ φ·(ring + e)·A (C only approximates the circle).
    EXPECT_NEAR(general / (turn * (ring + e) * kPi * a * a), 1, 2e-3);
}

}  // namespace
}  // namespace isotrace
