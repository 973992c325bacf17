// What gradient and simplex noise share: range, statistics, continuity, independent seeds, safe inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <ostream>

#include "renderer/textures/patterns/fractal_noise.h"
#include "renderer/textures/patterns/pattern_test_support.h"

namespace isotrace {
namespace {

struct NoiseCase {
    NoiseBasis basis;
    double spread_low, spread_high;  // the stated bounds on the standard deviation
};

void PrintTo(const NoiseCase& noise_case, std::ostream* out) {
    *out << (noise_case.basis == NoiseBasis::Gradient ? "gradient" : "simplex") << " noise";
}

class NoiseBasisTest : public testing::TestWithParam<NoiseCase> {
protected:
    float noise(const Vec3f& p, std::uint32_t seed) const { return basis_noise(GetParam().basis, p, seed); }
};

// The scale makes ±1 the field's extreme: never beyond it, and not far short of it.
TEST_P(NoiseBasisTest, SpansMinusOneToOne) {
    const Moments m = moments(random_points(400000, 50), [&](const Vec3f& p) { return noise(p, 9); });
    EXPECT_GE(m.minimum, -1.0);
    EXPECT_LE(m.maximum, 1.0);
    EXPECT_GT(m.maximum, 0.8);
    EXPECT_LT(m.minimum, -0.8);
}

TEST_P(NoiseBasisTest, HasMeanZeroAndStatedSpread) {
    const Moments m = moments(random_points(200000, 100), [&](const Vec3f& p) { return noise(p, 2); });
    EXPECT_NEAR(m.mean, 0.0, 0.005);
    EXPECT_GT(m.standard_deviation, GetParam().spread_low);
    EXPECT_LT(m.standard_deviation, GetParam().spread_high);
}

// Small steps give small changes everywhere, also where a step crosses from one cell or simplex to the next.
TEST_P(NoiseBasisTest, IsContinuous) {
    constexpr float kStep = 1e-3f;
    float largest = 0;
    for (const Vec3f& p : random_points(200000, 20)) {
        const Vec3f step{kStep / 2, -kStep / 3, kStep / 4};
        largest = std::max(largest, std::abs(noise(p + step, 5) - noise(p, 5)));
    }
    EXPECT_LT(largest, 1e-2f);
}

TEST_P(NoiseBasisTest, SeedsGiveUncorrelatedFields) {
    const auto points = random_points(100000, 100);
    for (const std::uint32_t other : {1u, 2u, 1000u}) {
        const double r = correlation(
            points, [&](const Vec3f& p) { return noise(p, 0); }, [&](const Vec3f& p) { return noise(p, other); });
        EXPECT_LT(std::abs(r), 0.02) << other;
    }
}

TEST_P(NoiseBasisTest, NonFiniteOrHugeCoordinatesGiveFiniteValues) {
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN(), kInfinity = std::numeric_limits<float>::infinity();
    for (const Vec3f& p : {Vec3f(kNaN, 0.5f, 0.5f), Vec3f(kInfinity, -kInfinity, 0.3f), Vec3f(3e38f, -3e38f, 1e9f),
                           Vec3f(3e38f, 3e38f, 3e38f)}) {
        const float value = noise(p, 1);
        EXPECT_TRUE(std::isfinite(value));
        EXPECT_LE(std::abs(value), 1.0f);
    }
}

INSTANTIATE_TEST_SUITE_P(Bases, NoiseBasisTest,
                         testing::Values(NoiseCase{NoiseBasis::Gradient, 0.23, 0.29},
                                         NoiseCase{NoiseBasis::Simplex, 0.36, 0.42}),
                         [](const testing::TestParamInfo<NoiseCase>& info) {
                             return info.param.basis == NoiseBasis::Gradient ? "Gradient" : "Simplex";
                         });

}  // namespace
}  // namespace isotrace
