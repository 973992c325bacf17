// A CSG's first surface point: bit for bit the first surface end of its full span combination, and a difference
// that takes its first operand's entry without asking a subtracted operand that certainly cannot reach it.
#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "geometry/csg/csg_test_support.h"

namespace isotrace::csg_test {
namespace {

void expect_same(const std::optional<BoundaryPoint>& actual, const std::optional<BoundaryPoint>& expected,
                 const std::string& what) {
    ASSERT_EQ(actual.has_value(), expected.has_value()) << what;
    if (!actual) return;
    EXPECT_EQ(actual->t, expected->t) << what;
    EXPECT_EQ(actual->normal, expected->normal) << what;
    EXPECT_EQ(actual->primitive, expected->primitive) << what;
    EXPECT_EQ(actual->part, expected->part) << what;
}

TEST(CsgFirstSurfacePoint, IsTheFullCombinationsFirstSurfaceEndBitForBit) {
    std::vector<std::unique_ptr<CsgShape>> trees;
    trees.push_back(csg(CsgOperation::Difference, child(sphere({0, 0, 0}, 1)), child(sphere({0.6, 0, 0}, 0.7))));
    trees.push_back(csg(CsgOperation::Difference, child(box({0, 0, 0}, {1, 0.8, 0.6})), child(sphere({0, 0, 0.6}, 0.5)),
                        child(box({-1, 0, 0}, {0.3, 0.3, 2}))));
    trees.push_back(csg(CsgOperation::Difference,
                        child(csg(CsgOperation::Union, child(sphere({0, 0, 0}, 1)), child(box({1, 0, 0}, {0.5, 0.2, 0.2})))),
                        child(sphere({0, 0.5, 0}, 0.8))));
    // Surfaces that coincide: the subtracted box shares a face with the first.
    trees.push_back(csg(CsgOperation::Difference, child(box({0, 0, 0}, {1, 1, 1})), child(box({1, 0, 0}, {0.5, 0.5, 0.5}))));
    trees.push_back(csg(CsgOperation::Intersection, child(sphere({0, 0, 0}, 1)), child(box({0.5, 0, 0}, {1, 1, 1}))));
    trees.push_back(csg(CsgOperation::Union, child(sphere({0, 0, 0}, 1)), child(sphere({1.2, 0, 0}, 0.5))));
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-2.5, 2.5), unit(-1, 1), near(0, 1);
    for (std::size_t k = 0; k < trees.size(); ++k)
        for (int i = 0; i < 4000; ++i) {
            const Vec3d origin(coordinate(random), coordinate(random), coordinate(random));
            // Some rays aimed at surface points of the subtracted operands' far sides.
            const Vec3d direction = i % 4 == 0 ? Vec3d(0.6, 0, 0.1 * unit(random)) - origin * 0.3
                                               : Vec3d(unit(random), unit(random), unit(random));
            const double t_near = i % 3 == 0 ? near(random) : 0;
            QueryScratch scratch;
            const auto actual = trees[k]->first_surface_point(origin, direction, t_near, 1e30, scratch);
            const auto expected = trees[k]->Solid::first_surface_point(origin, direction, t_near, 1e30, scratch);
            expect_same(actual, expected, "tree " + std::to_string(k) + " ray " + std::to_string(i));
        }
}

TEST(CsgFirstSurfacePoint, ADifferenceSkipsSubtractedOperandsThatCannotReachTheEntry) {
    for (const bool claims_outside : {true, false}) {
        auto ball = std::make_unique<CountingBall>(Vec3d(0, 0, 3), 0.5, claims_outside);
        const CountingBall& counting = *ball;
        const auto tree = csg(CsgOperation::Difference, child(sphere({0, 0, 0}, 1)), child(std::move(ball)));
        QueryScratch scratch;
        const auto hit = tree->first_surface_point({-3, 0, 0}, {1, 0, 0}, 0, 1e30, scratch);
        ASSERT_TRUE(hit);
        EXPECT_DOUBLE_EQ(hit->t, 2);
        EXPECT_EQ(counting.queries, claims_outside ? 0 : 1);
    }
}

TEST(CsgFirstSurfacePoint, AnEntryInsideASubtractedOperandIsCombinedInFull) {
    // The ray enters the first ball where the second has taken it away: the surface is the second's far side.
    const auto tree = csg(CsgOperation::Difference, child(sphere({0, 0, 0}, 1)), child(sphere({-1, 0, 0}, 0.5)));
    QueryScratch scratch;
    const auto hit = tree->first_surface_point({-3, 0, 0}, {1, 0, 0}, 0, 1e30, scratch);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2.5, 1e-12);
    EXPECT_NEAR(hit->normal.x, -1, 1e-12);  // the cavity's wall faces the ray
    EXPECT_EQ(hit->part, 1u);
}

}  // namespace
}  // namespace isotrace::csg_test
