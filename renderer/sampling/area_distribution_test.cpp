// The area-proportional primitive choice: primitives are picked in proportion to their areas (never one of zero
// or non-finite area), the reused number is uniform on [0, 1) and independent of the pick (chi-square over a
// joint histogram), and the total is the sum the density refers to.
#include "renderer/sampling/area_distribution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "renderer/sampling/independent_sampler.h"
#include "tests/support/chi_square.h"

namespace isotrace {
namespace {

const std::vector<double> kAreas = {2.5, 0, 7, 0.5, std::numeric_limits<double>::infinity(), 1, 4};
constexpr double kFiniteTotal = 15;

TEST(AreaDistribution, PicksFollowTheAreasAndTheReusedNumberIsUniformWithinEachPick) {
    const AreaDistribution distribution(kAreas);
    EXPECT_DOUBLE_EQ(distribution.total(), kFiniteTotal);
    const IndependentSampler sampler(5);
    constexpr int kReusedBins = 8;
    constexpr std::uint32_t kSamples = 300000;
    std::vector<double> observed(kAreas.size() * kReusedBins, 0), expected;
    for (const double area : kAreas) {
        const double share = std::isfinite(area) ? area / kFiniteTotal : 0;
        for (int bin = 0; bin < kReusedBins; ++bin) expected.push_back(kSamples * share / kReusedBins);
    }
    for (std::uint32_t i = 0; i < kSamples; ++i) {
        const AreaDistribution::Pick pick = distribution.pick(sampler.sample({i, 0, 0}, 0));
        ASSERT_LT(pick.index, kAreas.size());
        ASSERT_GE(pick.reused_u, 0.0f);
        ASSERT_LT(pick.reused_u, 1.0f);
        observed[pick.index * kReusedBins + std::size_t(pick.reused_u * kReusedBins)] += 1;
    }
    // Zero-area primitives expect nothing, so one pick of them gives p = 0.
    EXPECT_GT(test_support::chi_square_test(observed, expected).p_value, 0.01);
}

TEST(AreaDistribution, TheReusedNumberIsWhereUFellInsideThePicksShare) {
    // Equal areas: primitive k owns [k/4, (k+1)/4), and u = (k + f)/4 maps to f.
    const std::vector<double> equal = {1, 1, 1, 1};
    const AreaDistribution distribution(equal);
    const AreaDistribution::Pick pick = distribution.pick(0.5625f);  // (2 + 0.25) / 4
    EXPECT_EQ(pick.index, 2u);
    EXPECT_FLOAT_EQ(pick.reused_u, 0.25f);
    EXPECT_LT(distribution.pick(0x1.fffffep-1f).reused_u, 1.0f);
}

TEST(AreaDistribution, NoPrimitivesOrNoAreaGiveAZeroTotal) {
    EXPECT_EQ(AreaDistribution().total(), 0);
    EXPECT_EQ(AreaDistribution(std::vector<double>{}).total(), 0);
    const std::vector<double> degenerate = {0, std::numeric_limits<double>::quiet_NaN()};
    EXPECT_EQ(AreaDistribution(degenerate).total(), 0);
}

// A triangle with edges of 1e30 (a tube of radius 1e30) has a finite area in double that float cannot hold: it
// made Distribution1D throw, before the scene could refuse the shape at its position.
TEST(AreaDistribution, AreasBeyondFloatsRangeAreNeverPicked) {
    const AreaDistribution distribution(std::vector<double>{1, 1e60, 3});
    EXPECT_DOUBLE_EQ(distribution.total(), 4);
    for (float u : {0.0f, 0.25f, 0.5f, 0.999f}) EXPECT_NE(distribution.pick(u).index, 1u) << u;
}

}  // namespace
}  // namespace isotrace
