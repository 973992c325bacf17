// The cell-by-cell bounds of gradient noise against dense sampling of the texture's noise: every sampled value,
// and every finite-difference directional derivative, lies in the bounds over random boxes of several sizes; the
// bounds at a point are the texture's value; and on small boxes they are far inside the Lipschitz bound.
#include "geometry/expression/gradient_noise_bounds.h"

#include <gtest/gtest.h>

#include <random>

#include "geometry/expression/random_box_test_support.h"
#include "renderer/textures/patterns/gradient_noise.h"

namespace isotrace {
namespace {

constexpr double kLipschitz = 10.8;  // expression_noise's bound of |∇n|

double noise(const Vec3d& p, std::uint32_t seed) { return gradient_noise(Vec3f(p), seed); }

TEST(GradientNoiseBounds, HoldEverySampledValueAndSlope) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> unit(-1, 1);
    int bounded = 0;
    for (const double size : {0.01, 0.1, 0.5, 1.5}) {
        for (int trial = 0; trial < 300; ++trial) {
            const IntervalBox box = random_box(random, 40, size);
            const std::uint32_t seed = static_cast<std::uint32_t>(trial % 5);
            const std::optional<NoiseBoxBounds> bounds = gradient_noise_bounds(box, seed);
            if (!bounds) continue;
            ++bounded;
            for (int sample = 0; sample < 100; ++sample) {
                const Vec3d p = random_point(random, box);
                const double v = noise(p, seed);
                // The texture's float evaluation is within 10⁻⁶ of the formula.
                ASSERT_GE(v, bounds->value.lo - 1e-6) << size;
                ASSERT_LE(v, bounds->value.hi + 1e-6) << size;
                // A central difference along a random direction, both points inside the box: the derivative's
                // mean over the step, so within its bounds, up to the float noise's rounding over the step.
                const Vec3d d = normalize(Vec3d{unit(random), unit(random), unit(random)});
                const double h = 1e-3;
                const Vec3d ahead = p + d * h, behind = p - d * h;
                if (!box.contains(ahead) || !box.contains(behind)) continue;
                const double slope = (noise(ahead, seed) - noise(behind, seed)) / (2 * h);
                Interval bound = Interval::point(0);
                for (int k = 0; k < 3; ++k) bound = bound + bounds->gradient[k] * d[k];
                ASSERT_GE(slope, bound.lo - 1e-3) << size;
                ASSERT_LE(slope, bound.hi + 1e-3) << size;
            }
        }
    }
    EXPECT_GT(bounded, 600);  // the boxes up to half a cell wide always meet few enough cells
}

TEST(GradientNoiseBounds, AtAPointAreTheTexturesValue) {
    std::mt19937_64 random(12);
    for (int trial = 0; trial < 1000; ++trial) {
        const Vec3d p = random_point(random, {{-40, 40}, {-40, 40}, {-40, 40}});
        const Vec3d pf(Vec3f{p});  // the texture samples at the float point
        const std::optional<NoiseBoxBounds> bounds = gradient_noise_bounds(IntervalBox::point(pf), 3);
        ASSERT_TRUE(bounds);
        EXPECT_NEAR(bounds->value.lo, noise(pf, 3), 1e-6);
        EXPECT_NEAR(bounds->value.hi, noise(pf, 3), 1e-6);
    }
}

TEST(GradientNoiseBounds, AreFarTighterThanTheLipschitzBoundOnSmallBoxes) {
    std::mt19937_64 random(13);
    double bound_width = 0, lipschitz_width = 0;
    for (int trial = 0; trial < 500; ++trial) {
        const IntervalBox box = random_box(random, 40, 0.05);
        const std::optional<NoiseBoxBounds> bounds = gradient_noise_bounds(box, 1);
        ASSERT_TRUE(bounds);
        const double half_diagonal = 0.5 * length(box.upper() - box.lower());
        bound_width += bounds->value.width();
        lipschitz_width += 2 * kLipschitz * half_diagonal;
        // Each partial derivative's bound is within the Lipschitz bound too, and far from it on average.
        for (int k = 0; k < 3; ++k) EXPECT_LE(bounds->gradient[k].magnitude().hi, kLipschitz);
    }
    EXPECT_LT(bound_width, 0.25 * lipschitz_width);
}

TEST(GradientNoiseBounds, DeclineBoxesMeetingManyCells) {
    EXPECT_TRUE(gradient_noise_bounds({{0.5, 3.5}, {0.5, 1.5}, {0.2, 0.3}}, 0));  // 4 × 2 cells: 8, bounded
    EXPECT_FALSE(gradient_noise_bounds({{0.5, 4.5}, {0.5, 1.5}, {0.2, 0.3}}, 0));  // 5 × 2: 10
    EXPECT_FALSE(gradient_noise_bounds({{0, 1}, {0, 1}, {0, 1e30}}, 0));
}

// The value alone at a point is the point box's value bit for bit, on and off the lattice's planes.
TEST(GradientNoiseBounds, TheValueAtAPointIsThePointBoxsValue) {
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> unit(-40, 40);
    for (int trial = 0; trial < 2000; ++trial) {
        Vec3d p{unit(random), unit(random), unit(random)};
        if (trial % 4 == 0) p.x = std::round(p.x);  // on a cell's face
        if (trial % 8 == 0) p = {std::round(p.x), std::round(p.y), std::round(p.z)};  // a lattice point
        const std::uint32_t seed = static_cast<std::uint32_t>(trial % 7);
        const std::optional<Interval> value = gradient_noise_value_at(p, seed);
        const std::optional<NoiseBoxBounds> bounds = gradient_noise_bounds(IntervalBox::point(p), seed);
        ASSERT_TRUE(value && bounds);
        ASSERT_TRUE(value->lo == bounds->value.lo && value->hi == bounds->value.hi) << trial;
    }
    EXPECT_FALSE(gradient_noise_value_at({0x1p23, 0, 0}, 1));  // beyond the limits, as the box form
    EXPECT_FALSE(gradient_noise_bounds(IntervalBox::point({0x1p23, 0, 0}), 1));
}

// The texture's float gradient of the formula against the bounds' double evaluation of it at a point (an interval
// of width zero up to rounding): equal to float precision.
TEST(GradientNoiseBounds, AtAPointTheGradientIsTheTexturesFormulaGradient) {
    std::mt19937_64 random(8);
    std::uniform_real_distribution<double> unit(-30, 30);
    for (int trial = 0; trial < 1000; ++trial) {
        const Vec3f p{float(unit(random)), float(unit(random)), float(unit(random))};
        const std::uint32_t seed = static_cast<std::uint32_t>(trial % 4);
        const Vec3f g = gradient_noise_gradient(p, seed);
        const std::optional<NoiseBoxBounds> bounds = gradient_noise_bounds(IntervalBox::point(Vec3d(p)), seed);
        ASSERT_TRUE(bounds);
        for (int k = 0; k < 3; ++k) {
            ASSERT_LE(bounds->gradient[k].width(), 1e-12);
            ASSERT_NEAR(g[k], bounds->gradient[k].lo, 2e-5) << trial << " axis " << k;
        }
    }
}

}  // namespace
}  // namespace isotrace
