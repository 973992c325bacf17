// The noise terms' bounds against dense sampling: the Lipschitz constants derived in docs/decisions.md are never
// exceeded by a difference quotient of nearby samples (and are within a small factor of the largest one found, so
// that they are not uselessly loose), every sampled value over a random box lies in the term's interval, and the
// terms compute exactly the textures' functions.
#include "geometry/expression/expression_noise.h"

#include <gtest/gtest.h>

#include <random>

#include "geometry/expression/expression_field.h"
#include "geometry/expression/random_box_test_support.h"
#include "renderer/textures/patterns/cellular_noise.h"
#include "renderer/textures/patterns/gradient_noise.h"
#include "renderer/textures/patterns/simplex_noise.h"

namespace isotrace {
namespace {

struct NoiseCase {
    const char* name;
    NoiseTerm term;
};

std::vector<NoiseCase> noise_cases() {
    FractalSettings fractal;
    FractalSettings rough;
    rough.octaves = 3;
    rough.lacunarity = 3;
    rough.gain = 0.8f;
    rough.seed = 7;
    return {{"gradient", make_noise_term(NoiseKind::Gradient, fractal, 0)},
            {"simplex", make_noise_term(NoiseKind::Simplex, fractal, 0)},
            {"fbm", make_noise_term(NoiseKind::Fbm, fractal, 0)},
            {"fbm rough", make_noise_term(NoiseKind::Fbm, rough, 0)},
            {"turbulence", make_noise_term(NoiseKind::Turbulence, fractal, 0)},
            {"cellular", make_noise_term(NoiseKind::Cellular, fractal, 0.5f)}};
}

TEST(ExpressionNoise, DifferenceQuotientsStayUnderTheLipschitzBound) {
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> coordinate(-20, 20), unit(-1, 1);
    for (const NoiseCase& c : noise_cases()) {
        double steepest = 0;
        for (int sample = 0; sample < 200000; ++sample) {
            const Vec3d p{coordinate(random), coordinate(random), coordinate(random)};
            const double h = 1e-3 / std::max(1.0, c.term.lipschitz / 10);
            const Vec3d q = p + normalize(Vec3d{unit(random), unit(random), unit(random)}) * h;
            const double quotient = std::abs(noise_value(c.term, q) - noise_value(c.term, p)) / h;
            steepest = std::max(steepest, quotient);
        }
        // The samples are floats: their rounding (a few 10⁻⁷ at |p| = 20) divided by h may add to a quotient.
        EXPECT_LE(steepest, c.term.lipschitz + 2e-5 / (1e-3 / std::max(1.0, c.term.lipschitz / 10))) << c.name;
        EXPECT_GE(steepest, c.term.lipschitz / 16) << c.name;  // the bound is not hopelessly loose
        std::printf("%-11s steepest sampled slope %.3f, bound %.3f\n", c.name, steepest, c.term.lipschitz);
    }
}

TEST(ExpressionNoise, IntervalsHoldEverySampledValue) {
    std::mt19937_64 random(4);
    for (const NoiseCase& c : noise_cases()) {
        for (int trial = 0; trial < 400; ++trial) {
            const IntervalBox box = random_box(random, 50, trial % 2 == 0 ? 0.02 : 0.3);
            const Interval range = noise_value_range(c.term, box);
            ASSERT_LE(c.term.range.lo, range.lo);
            ASSERT_GE(c.term.range.hi, range.hi);
            for (int sample = 0; sample < 200; ++sample) {
                const double v = noise_value(c.term, random_point(random, box));
                ASSERT_TRUE(range.contains(v)) << c.name << ": " << v << " outside [" << range.lo << ", " << range.hi << "]";
            }
        }
    }
}

// The gradient-noise kinds' slopes from their formulas: every central difference along the motion lies in the
// slope's interval (near the origin, where the float noise's rounding is small against the step).
TEST(ExpressionNoise, SlopeIntervalsHoldEverySampledSlope) {
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> signed_unit(-1, 1);
    for (const NoiseCase& c : noise_cases()) {
        for (int trial = 0; trial < 300; ++trial) {
            const IntervalBox box = random_box(random, 2, trial % 2 == 0 ? 0.02 : 0.3);
            const Vec3d d = normalize(Vec3d{signed_unit(random), signed_unit(random), signed_unit(random)});
            const Interval slope = noise_slope_range(c.term, noise_box_ranges(c.term, box), IntervalBox::point(d));
            ASSERT_LE(slope.magnitude().hi, c.term.lipschitz + 1e-12) << c.name;
            const double h = 1e-3;
            for (int sample = 0; sample < 100; ++sample) {
                const Vec3d p = random_point(random, box);
                if (!box.contains(p + d * h) || !box.contains(p - d * h)) continue;
                const double quotient = (noise_value(c.term, p + d * h) - noise_value(c.term, p - d * h)) / (2 * h);
                ASSERT_GE(quotient, slope.lo - 0.02) << c.name;
                ASSERT_LE(quotient, slope.hi + 0.02) << c.name;
            }
        }
    }
}

// On small boxes the gradient-noise kinds' intervals and slopes are far inside the Lipschitz ones (so the bounds
// cell by cell are in use).
TEST(ExpressionNoise, GradientNoiseKindsAreBoundedFarInsideTheLipschitzBounds) {
    std::mt19937_64 random(6);
    std::uniform_real_distribution<double> unit(0, 1), signed_unit(-1, 1);
    for (const NoiseCase& c : noise_cases()) {
        if (c.term.octaves.empty()) continue;
        double value_width = 0, value_lipschitz = 0, slope_width = 0, slope_lipschitz = 0;
        for (int trial = 0; trial < 200; ++trial) {
            IntervalBox box;
            for (int k = 0; k < 3; ++k) {
                const double lo = -10 + 20 * unit(random);
                box[k] = {lo, lo + 0.01};
            }
            const Vec3d d = normalize(Vec3d{signed_unit(random), signed_unit(random), signed_unit(random)});
            value_width += noise_value_range(c.term, box).width();
            value_lipschitz += 2 * c.term.lipschitz * 0.005 * std::sqrt(3.0);
            slope_width += noise_slope_range(c.term, noise_box_ranges(c.term, box), IntervalBox::point(d)).width();
            slope_lipschitz += 2 * c.term.lipschitz;
        }
        EXPECT_LT(value_width, 0.3 * value_lipschitz) << c.name;
        EXPECT_LT(slope_width, 0.3 * slope_lipschitz) << c.name;
    }
}

TEST(ExpressionNoise, TermsAreTheTexturesFunctions) {
    const Vec3d p{1.3, -2.7, 0.45};
    const Vec3f pf(p);
    EXPECT_EQ(compile_expression({"noise(p, 5)", {}, ""}, {})->value(p), gradient_noise(pf, 5));
    EXPECT_EQ(compile_expression({"simplex(p)", {}, ""}, {})->value(p), simplex_noise(pf, 0));
    FractalSettings settings;
    settings.octaves = 4;
    settings.lacunarity = 2.5f;
    settings.gain = 0.4f;
    settings.seed = 9;
    EXPECT_EQ(compile_expression({"fbm(p, 4, 2.5, 0.4, 9)", {}, ""}, {})->value(p), fbm(pf, FractalOctaves(settings), 0));
    EXPECT_EQ(compile_expression({"turbulence(p)", {}, ""}, {})->value(p), turbulence(pf, FractalOctaves(FractalSettings{}), 0));
    EXPECT_EQ(compile_expression({"cellular(p, 0.25, 3)", {}, ""}, {})->value(p),
              cellular(pf, 3, 0.25f, CellularOutput::F1, 0));
}

TEST(ExpressionNoise, GradientsFollowTheNoise) {
    for (const char* text : {"fbm(2 * p)", "fbm(3 * p, 6, 2.2, 0.6, 4)", "turbulence(2 * p, 4)", "noise(3 * p)",
                             "simplex(2 * p)", "cellular(2 * p)"}) {
        const auto field = compile_expression({text, {}, ""}, {});
        for (const Vec3d p : {Vec3d{0.31, 0.72, -0.15}, Vec3d{-1.7, 0.05, 2.4}, Vec3d{4.1, -3.3, 0.6}}) {
            const Vec3d g = field->gradient(p);
            const double h = 1e-4;
            for (int k = 0; k < 3; ++k) {
                Vec3d ahead = p, behind = p;
                ahead[k] += h;
                behind[k] -= h;
                EXPECT_NEAR(g[k], (field->value(ahead) - field->value(behind)) / (2 * h), 0.02 * (1 + std::abs(g[k])))
                    << text << " axis " << k;
            }
        }
    }
}

}  // namespace
}  // namespace isotrace
