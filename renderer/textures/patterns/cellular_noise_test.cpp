#include "renderer/textures/patterns/cellular_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "renderer/textures/patterns/pattern_test_support.h"

namespace isotrace {
namespace {

constexpr CellularOutput kOutputs[] = {CellularOutput::F1, CellularOutput::F2, CellularOutput::F2MinusF1,
                                       CellularOutput::CellValue};

TEST(CellularNoise, F1IsAtMostF2AndTheirDifferenceIsF2MinusF1) {
    for (const float jitter : {0.0f, 0.5f, 1.0f}) {
        for (const Vec3f& p : random_points(20000, 50)) {
            const float f1 = cellular(p, 4, jitter, CellularOutput::F1, 0);
            const float f2 = cellular(p, 4, jitter, CellularOutput::F2, 0);
            ASSERT_GE(f1, 0.0f);
            ASSERT_LE(f1, f2);
            ASSERT_LE(f1, std::sqrt(3.0f));
            ASSERT_LE(f2, std::sqrt(6.0f));
            ASSERT_FLOAT_EQ(cellular(p, 4, jitter, CellularOutput::F2MinusF1, 0), f2 - f1);
        }
    }
}

// Without jitter the feature points are the cell centres.
TEST(CellularNoise, RegularGridKnownValues) {
    EXPECT_EQ(cellular({2.5f, -3.5f, 0.5f}, 1, 0, CellularOutput::F1, 0), 0.0f);
    EXPECT_FLOAT_EQ(cellular({2.5f, -3.5f, 0.5f}, 1, 0, CellularOutput::F2, 0), 1.0f);
    EXPECT_FLOAT_EQ(cellular({0.25f, 0.5f, 0.5f}, 1, 0, CellularOutput::F1, 0), 0.25f);
    EXPECT_FLOAT_EQ(cellular({0.25f, 0.5f, 0.5f}, 1, 0, CellularOutput::F2, 0), 0.75f);
    EXPECT_FLOAT_EQ(cellular({0, 0, 0}, 1, 0, CellularOutput::F1, 0), std::sqrt(3.0f) / 2);
}

// At a feature point F1 is 0 and CellValue is its cell's value, and so it stays over a ball of half F2 around it
// (every point there is nearer to it than to any other feature point): constant over the Voronoi cell, also where
// the ball crosses lattice cell faces.
TEST(CellularNoise, FeaturePointsAndTheirCells) {
    std::mt19937 random(3);
    std::uniform_int_distribution<std::int32_t> cells(-100, 100);
    std::uniform_real_distribution<float> unit(-1, 1);
    for (const float jitter : {0.3f, 1.0f}) {
        for (int trial = 0; trial < 300; ++trial) {
            const std::array<std::int32_t, 3> cell{cells(random), cells(random), cells(random)};
            const Vec3f feature = cellular_feature_point(cell, 11, jitter);
            EXPECT_NEAR(cellular(feature, 11, jitter, CellularOutput::F1, 0), 0.0f, 1e-5f);
            const float value = cellular_cell_value(cell, 11);
            EXPECT_EQ(cellular(feature, 11, jitter, CellularOutput::CellValue, 0), value);
            const float radius = 0.49f * cellular(feature, 11, jitter, CellularOutput::F2, 0);
            for (int i = 0; i < 50; ++i) {
                Vec3f offset{unit(random), unit(random), unit(random)};
                if (dot(offset, offset) > 1) continue;
                ASSERT_EQ(cellular(feature + offset * radius, 11, jitter, CellularOutput::CellValue, 0), value);
            }
        }
    }
}

TEST(CellularNoise, CellValuesAreUniformInUnitInterval) {
    const Moments m = moments(random_points(100000, 100),
                              [](const Vec3f& p) { return cellular(p, 2, 1, CellularOutput::CellValue, 0); });
    EXPECT_GE(m.minimum, 0.0);
    EXPECT_LT(m.maximum, 1.0);
    EXPECT_NEAR(m.mean, 0.5, 0.01);
    EXPECT_NEAR(m.standard_deviation, std::sqrt(1.0 / 12), 0.01);
}

// The means a wide footprint gives are the measured means over space, at every node of the table and between.
TEST(CellularNoise, WideFootprintGivesTheMeanOverSpace) {
    const auto points = random_points(100000, 200);
    for (const float jitter : {0.0f, 0.0625f, 0.125f, 0.25f, 0.3f, 0.375f, 0.5f, 0.6f, 0.625f, 0.75f, 0.875f, 0.9f, 1.0f}) {
        for (const CellularOutput output : kOutputs) {
            const Moments m = moments(points, [&](const Vec3f& p) { return cellular(p, 5, jitter, output, 0); });
            const float mean = cellular_mean(output, jitter);
            EXPECT_NEAR(m.mean, mean, 0.003) << jitter << ' ' << int(output);
            EXPECT_EQ(cellular({0.2f, 7.1f, -3.3f}, 5, jitter, output, 1), mean);
            EXPECT_EQ(cellular({0.2f, 7.1f, -3.3f}, 5, jitter, output, 1e30f), mean);
        }
    }
}

TEST(CellularNoise, FootprintFadeIsSmooth) {
    for (const Vec3f& p : random_points(20, 10)) {
        for (const CellularOutput output : kOutputs) {
            const auto at = [&](float footprint) { return cellular(p, 1, 1, output, footprint); };
            EXPECT_LT(largest_footprint_step(at, 1.2f), 1e-3f);
        }
    }
}

TEST(CellularNoise, SeedsGiveUncorrelatedFields) {
    const auto points = random_points(50000, 100);
    for (const CellularOutput output : kOutputs) {
        const double r = correlation(
            points, [&](const Vec3f& p) { return cellular(p, 0, 1, output, 0); },
            [&](const Vec3f& p) { return cellular(p, 1, 1, output, 0); });
        EXPECT_LT(std::abs(r), 0.03) << int(output);
    }
}

TEST(CellularNoise, NonFiniteInputsGiveValuesInRange) {
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN(), kInfinity = std::numeric_limits<float>::infinity();
    for (const CellularOutput output : kOutputs) {
        for (const float value : {cellular({kNaN, kInfinity, -kInfinity}, 1, 1, output, 0),
                                  cellular({0.5f, 1.5f, 2.5f}, 1, kNaN, output, kNaN),
                                  cellular({0.5f, 1.5f, 2.5f}, 1, kInfinity, output, -1)}) {
            EXPECT_GE(value, 0.0f) << int(output);
            EXPECT_LE(value, std::sqrt(6.0f)) << int(output);
        }
    }
}

}  // namespace
}  // namespace isotrace
