// Expression fields against known answers: the values and gradients of a sphere, a torus and a gyroid; every
// function's gradient against central differences; and the guarantees of the interval evaluators, checked by dense
// sampling: every value over a random box lies in the value's interval, every difference quotient along a
// direction in the slope's interval.
#include "geometry/expression/expression_field.h"

#include <gtest/gtest.h>

#include "geometry/expression/expression_compiler.h"
#include "geometry/expression/random_box_test_support.h"

#include <cmath>
#include <numbers>
#include <random>
#include <thread>

namespace isotrace {
namespace {

std::shared_ptr<const ExpressionField> compiled(const std::string& text, const ExpressionNames& names = {}) {
    return compile_expression({text, {"scene.json", 3, 20}, "objects[0].shape.function"}, names);
}

TEST(ExpressionField, SphereTorusAndGyroidHaveTheirKnownValuesAndGradients) {
    const auto sphere = compiled("length(p) - 1");
    EXPECT_DOUBLE_EQ(sphere->value({3, 4, 0}), 4);
    EXPECT_DOUBLE_EQ(sphere->value({0, 0, 1}), 0);
    const Vec3d g = sphere->gradient({3, 4, 0});
    EXPECT_NEAR(g.x, 0.6, 1e-15);
    EXPECT_NEAR(g.y, 0.8, 1e-15);
    EXPECT_EQ(g.z, 0);

    // A torus of radii R = 1, r = 0.25 around the z axis.
    const auto torus = compiled("length(vec(length(vec(x, y, 0)) - 1, z, 0)) - 0.25");
    EXPECT_NEAR(torus->value({1.25, 0, 0}), 0, 1e-15);
    EXPECT_NEAR(torus->value({0, 1, 0.25}), 0, 1e-15);
    EXPECT_NEAR(torus->value({0, 0, 0}), 0.75, 1e-15);
    const Vec3d t = torus->gradient({0, 1, 0.25});
    EXPECT_NEAR(t.x, 0, 1e-12);
    EXPECT_NEAR(t.y, 0, 1e-12);
    EXPECT_NEAR(t.z, 1, 1e-12);

    const auto gyroid = compiled("sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)");
    const Vec3d q{0.3, -1.1, 2.4};
    EXPECT_NEAR(gyroid->value(q), std::sin(q.x) * std::cos(q.y) + std::sin(q.y) * std::cos(q.z) +
                                      std::sin(q.z) * std::cos(q.x), 1e-15);
    EXPECT_NEAR(gyroid->value({0, 0, 0}), 0, 0);
    const Vec3d gg = gyroid->gradient(q);
    EXPECT_NEAR(gg.x, std::cos(q.x) * std::cos(q.y) - std::sin(q.z) * std::sin(q.x), 1e-14);
}

TEST(ExpressionField, OperatorsFollowPrecedenceAndAssociativity) {
    EXPECT_DOUBLE_EQ(compiled("2^3^2")->value({}), 512);      // right-associative
    EXPECT_DOUBLE_EQ(compiled("-2^2")->value({}), -4);        // minus binds looser than ^
    EXPECT_DOUBLE_EQ(compiled("2^-1")->value({}), 0.5);
    EXPECT_DOUBLE_EQ(compiled("1 + 2 * 3 - 4 / 2")->value({}), 5);
    EXPECT_DOUBLE_EQ(compiled("(1 + 2) * 3")->value({}), 9);
    EXPECT_DOUBLE_EQ(compiled("x - y - z")->value({1, 2, 3}), -4);
    EXPECT_DOUBLE_EQ(compiled("x / y / z")->value({8, 2, 2}), 2);
    EXPECT_DOUBLE_EQ(compiled("(p * 2 + vec(1, 0, 0)).x")->value({3, 0, 0}), 7);
    EXPECT_DOUBLE_EQ(compiled("dot(p, vec(1, 2, 3))")->value({1, 1, 1}), 6);
    EXPECT_DOUBLE_EQ(compiled("max(x, y, z, 0.5)")->value({0.1, 0.2, 0.3}), 0.5);
    EXPECT_DOUBLE_EQ(compiled("min(x, y, z)")->value({0.1, 0.2, -0.3}), -0.3);
    EXPECT_DOUBLE_EQ(compiled("length(max(abs(p) - vec(1, 2, 3), 0))")->value({2, 0, 0}), 1);  // a box
    EXPECT_DOUBLE_EQ(compiled("clamp(x, -1, 1)")->value({3, 0, 0}), 1);
    EXPECT_DOUBLE_EQ(compiled("mix(2, 4, x)")->value({0.25, 0, 0}), 2.5);
    EXPECT_DOUBLE_EQ(compiled("pi")->value({}), std::numbers::pi);
    EXPECT_DOUBLE_EQ(compiled("e")->value({}), std::numbers::e);
    EXPECT_DOUBLE_EQ(compiled("x^2.5")->value({4, 0, 0}), 32);
    EXPECT_DOUBLE_EQ(compiled("atan2(y, x)")->value({-1, 0, 0}), std::numbers::pi);
}

TEST(ExpressionField, SmoothMinimumIsPolynomialAndEqualsMinFarFromTheSeam) {
    const auto blend = compiled("smin(x, y, 0.5)");
    EXPECT_DOUBLE_EQ(blend->value({0, 1, 0}), 0);            // |a − b| ≥ r: the plain minimum
    EXPECT_DOUBLE_EQ(blend->value({0.2, 0.2, 0}), 0.2 - 0.125);  // a = b: min − r/4
    EXPECT_DOUBLE_EQ(compiled("smax(x, y, 0.5)")->value({0.2, 0.2, 0}), 0.2 + 0.125);
    EXPECT_DOUBLE_EQ(compiled("sdiff(x, y, 0.5)")->value({0.2, -0.2, 0}), 0.2 + 0.125);
    EXPECT_DOUBLE_EQ(compiled("smin(x, y, 0)")->value({0.2, 0.1, 0}), 0.1);
}

TEST(ExpressionField, DomainRulesGiveFiniteValuesAndNeverNaN) {
    EXPECT_EQ(compiled("sqrt(x)")->value({-4, 0, 0}), 0);
    EXPECT_EQ(compiled("log(x)")->value({-1, 0, 0}), std::log(std::numeric_limits<double>::min()));
    EXPECT_EQ(compiled("log(x)")->value({0, 0, 0}), std::log(std::numeric_limits<double>::min()));
    EXPECT_EQ(compiled("x / y")->value({1, 0, 0}), 0);
    EXPECT_EQ(compiled("x / y")->value({0, 0, 0}), 0);
    EXPECT_EQ(compiled("exp(x)")->value({1000, 0, 0}), std::numeric_limits<double>::max());
    EXPECT_EQ(compiled("exp(x) - exp(x)")->value({1000, 0, 0}), 0);
    EXPECT_EQ(compiled("atan2(y, x)")->value({0, 0, 0}), 0);
    EXPECT_LT(compiled("x^0.5")->value({-4, 0, 0}), 1e-150);  // e^(0.5 ln(tiny))
    const Vec3d g = compiled("sqrt(x) + log(y) + x / z")->gradient({-1, -1, 0});
    EXPECT_TRUE(std::isfinite(g.x) && std::isfinite(g.y) && std::isfinite(g.z));
    const Interval range = compiled("x / y")->value_range({{1, 2}, {-1, 1}, {0, 0}});
    EXPECT_TRUE(range.contains(0));
    EXPECT_FALSE(std::isnan(range.lo) || std::isnan(range.hi));
    EXPECT_FALSE(std::isnan(compiled("exp(x) - exp(x)")->value_range({{0, 1000}, {0, 0}, {0, 0}}).lo));
    EXPECT_TRUE(compiled("exp(x)")->value_range({{1000, 1001}, {0, 0}, {0, 0}}).contains(compiled("exp(x)")->value({1000, 0, 0})));
}

TEST(ExpressionField, ParametersAreConstantsAndCommonSubexpressionsAreShared) {
    ExpressionNames names;
    names.parameters["r"] = 0.3;
    EXPECT_DOUBLE_EQ(compiled("length(p) - r", names)->value({1, 0, 0}), 0.7);
    // length(p) twice is one computation; constants fold away.
    EXPECT_EQ(compiled("length(p) + length(p)")->tape_length(), compiled("length(p)")->tape_length() + 1);
    EXPECT_EQ(compiled("x + 2 * 3 * pi")->tape_length(), 3);
    EXPECT_EQ(compiled("fbm(p, 3) + fbm(p, 3)")->tape_length(), compiled("fbm(p, 3)")->tape_length() + 1);
    EXPECT_EQ(compiled("fbm(p, 3) + fbm(p, 4)")->tape_length(), compiled("fbm(p, 3)")->tape_length() + 2);
}

TEST(ExpressionField, AddingZeroAndMultiplyingByOneFoldAway) {
    EXPECT_EQ(compiled("x + 0")->tape_length(), 1);
    EXPECT_EQ(compiled("0 + x*1 - 0")->tape_length(), 1);
    EXPECT_EQ(compiled("1*x/1")->tape_length(), 1);
    EXPECT_EQ(compiled("length(p - vec(0, 0.35, 0))")->tape_length(), compiled("length(vec(x, y - 0.35, z))")->tape_length());
    EXPECT_DOUBLE_EQ(compiled("0 - x")->value({2, 0, 0}), -2);  // not an identity
}

TEST(ExpressionField, SineAndCosineOfOneArgumentArePairedAndConstantsComeFirst) {
    const ExpressionNames names;
    const ExpressionTape tape = compile_expression_text("cos(2*x) + y*sin(2*x) - sin(z)", &names).tape;
    ASSERT_EQ(tape.constants, 1u);
    EXPECT_EQ(tape.code[0].op, Op::Constant);
    int pairs = 0;
    for (std::size_t i = 0; i + 1 < tape.code.size(); ++i) {
        if (tape.code[i].op != Op::SinCos) continue;
        ++pairs;
        EXPECT_EQ(tape.code[i + 1].op, Op::Cos);
        EXPECT_EQ(tape.code[i + 1].a, tape.code[i].a);
    }
    EXPECT_EQ(pairs, 1);  // sin(z) has no cosine beside it
    // The pair's values are sin's and cos's own, bit for bit.
    const auto field = compiled("cos(2*x) + y*sin(2*x) - sin(z)");
    const Vec3d p{0.7, -1.3, 2.9};
    EXPECT_EQ(field->value(p), std::cos(2 * p.x) + p.y * std::sin(2 * p.x) - std::sin(p.z));
}

TEST(ExpressionField, NarrowIntervalsOfSineAndCosineHoldEveryValueAndAreNearlyExact) {
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> unit(0, 1);
    const auto sine = compiled("sin(x)"), cosine = compiled("cos(x)");
    for (int trial = 0; trial < 2000; ++trial) {
        const double lo = -60 + 120 * unit(random), width = (trial % 2 ? 0.5 : 1e-6) * unit(random);
        const Interval angle{lo, lo + width};
        const IntervalBox box{angle, {0, 0}, {0, 0}};
        const Interval s = sine->value_range(box), c = cosine->value_range(box);
        for (int sample = 0; sample <= 50; ++sample) {
            const double t = sample == 50 ? angle.hi : angle.lo + width * sample / 50;
            ASSERT_TRUE(s.contains(std::sin(t)) && c.contains(std::cos(t))) << "[" << angle.lo << ", " << angle.hi << "]";
        }
        // Within the Taylor remainder r²/2 (and the rounding slack) of the exact ranges at either end.
        const double excess = 0.125 * width * width + 1e-14;
        EXPECT_LE(s.width(), sin_range(angle).width() + 2 * excess);
        EXPECT_LE(c.width(), cos_range(angle).width() + 2 * excess);
    }
}

TEST(ExpressionField, FieldTermsAreCalledAtTheirArgumentAndTheirBoundsCarryOver) {
    const auto ball = compiled("length(p) - 1");
    ExpressionNames names;
    names.fields["ball"] = ball;
    const auto squashed = compiled("ball(vec(x, 2 * y, z)) + 0.5", names);
    EXPECT_DOUBLE_EQ(squashed->value({0, 1, 0}), 1.5);
    const Vec3d g = squashed->gradient({0, 1, 0});
    EXPECT_DOUBLE_EQ(g.y, 2);
    const IntervalBox box{{-0.1, 0.1}, {0.9, 1.1}, {-0.1, 0.1}};
    const Interval slope = squashed->slope_range(box, {0, 1, 0});
    EXPECT_TRUE(slope.contains(2));
    EXPECT_TRUE(squashed->value_range(box).contains(1.5));
    EXPECT_EQ(expression_field_terms({"ball(p) + smin(ball(2*p), other(p), 0.1)", {}, ""}),
              (std::vector<std::string>{"ball", "other"}));
}

// Each function and operator on its own, over random points and boxes.
const char* const kFunctionCases[] = {
    "x + y", "x - y", "x * y", "x / y", "-x", "x^2", "x^3", "x^-2", "x^0.7", "(y^2 + 0.5)^x", "sqrt(x)", "exp(x)", "log(x)",
    "sin(3*x)", "cos(3*x)", "tan(x)", "atan(x)", "atan2(y, x)", "abs(x)", "min(x, y)", "max(x, y, z)",
    "clamp(x, -0.5, 0.5)", "mix(x, y, z)", "smin(x, y, 0.4)", "smax(x, y, 0.4)", "sdiff(x, y, 0.4)",
    "length(p) - 1", "dot(p, vec(1, -2, 3))", "sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)",
    "smin(length(p) - 1, length(max(abs(p - vec(1, 0, 0)) - 0.5, 0)), 0.3)", "x*y*z - sqrt(abs(x*y)) / (1 + z^2)",
};

// The gradient, and the value and slope along a direction from their own evaluator.
TEST(ExpressionField, GradientsMatchCentralDifferencesAndSlopesTheGradient) {
    std::mt19937_64 random(1);
    std::uniform_real_distribution<double> coordinate(-2, 2);
    for (const char* text : kFunctionCases) {
        const auto field = compiled(text);
        for (int sample = 0; sample < 200; ++sample) {
            const Vec3d p{coordinate(random), coordinate(random), coordinate(random)};
            const Vec3d g = field->gradient(p);
            const Vec3d direction{coordinate(random), coordinate(random), coordinate(random)};
            const FieldSlope at = field->value_and_slope(p, direction);
            EXPECT_EQ(at.value, field->value(p)) << text;
            EXPECT_NEAR(at.derivative, dot(g, direction), 1e-12 * (1 + std::abs(dot(g, direction)))) << text;
            for (int k = 0; k < 3; ++k) {
                constexpr double h = 1e-6;
                Vec3d ahead = p, behind = p;
                ahead[k] += h;
                behind[k] -= h;
                const double difference = (field->value(ahead) - field->value(behind)) / (2 * h);
                // Away from kinks and poles the two agree; a kink or a pole within h shows as a large mismatch
                // in both one-sided quotients, which we skip.
                const double left = (field->value(p) - field->value(behind)) / h;
                const double right = (field->value(ahead) - field->value(p)) / h;
                if (std::abs(left - right) > 1e-3 * (1 + std::abs(difference))) continue;
                EXPECT_NEAR(g[k], difference, 1e-5 * (1 + std::abs(difference))) << text << " at " << p.x << ", " << p.y
                                                                                  << ", " << p.z << " axis " << k;
            }
        }
    }
}

TEST(ExpressionField, IntervalsHoldEverySampledValueAndSlope) {
    std::mt19937_64 random(2);
    std::uniform_real_distribution<double> unit(0, 1);
    for (const char* text : kFunctionCases) {
        const auto field = compiled(text);
        for (int trial = 0; trial < 60; ++trial) {
            IntervalBox box;
            const double size = trial < 30 ? 0.05 : 2.0;
            for (int k = 0; k < 3; ++k) {
                const double lo = -2 + 4 * unit(random);
                box[k] = {lo, lo + size * unit(random)};
            }
            const Vec3d direction = normalize(Vec3d{unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5});
            const Interval range = field->value_range(box);
            const Interval slope = field->slope_range(box, direction);
            // One run for both gives the two bit for bit, as does the default of a field without its own.
            for (const FieldRanges& both : {field->value_and_slope_range(box, direction),
                                            field->ImplicitField::value_and_slope_range(box, direction)}) {
                ASSERT_TRUE(both.value.lo == range.lo && both.value.hi == range.hi) << text;
                ASSERT_TRUE(both.slope.lo == slope.lo && both.slope.hi == slope.hi) << text;
            }
            // One run for the three partial derivatives gives the slopes along the axes bit for bit.
            const IntervalBox partials = field->gradient_range(box), axes = field->ImplicitField::gradient_range(box);
            for (int k = 0; k < 3; ++k) ASSERT_TRUE(partials[k].lo == axes[k].lo && partials[k].hi == axes[k].hi) << text;
            ASSERT_FALSE(std::isnan(range.lo) || std::isnan(range.hi) || std::isnan(slope.lo) || std::isnan(slope.hi))
                << text;
            for (int sample = 0; sample < 300; ++sample) {
                const Vec3d p{box.x.lo + box.x.width() * unit(random), box.y.lo + box.y.width() * unit(random),
                              box.z.lo + box.z.width() * unit(random)};
                const double v = field->value(p);
                const double tolerance = 1e-12 * (1 + std::abs(v));
                EXPECT_TRUE(range.lo - tolerance <= v && v <= range.hi + tolerance)
                    << text << ": " << v << " outside [" << range.lo << ", " << range.hi << "]";
                // The derivative along the direction, where the point's neighbourhood stays in the box.
                const Vec3d g = field->gradient(p);
                const double d = dot(g, direction);
                EXPECT_TRUE(slope.lo - 1e-9 * (1 + std::abs(d)) <= d && d <= slope.hi + 1e-9 * (1 + std::abs(d)))
                    << text << ": slope " << d << " outside [" << slope.lo << ", " << slope.hi << "]";
            }
        }
    }
}

// Noises and field terms in the run of the three partial derivatives: each partial as the slope along its axis,
// bit for bit, and every sampled partial derivative inside its interval.
TEST(ExpressionField, TheThreePartialsOfOneRunAreTheSlopesAlongTheAxes) {
    ExpressionNames names;
    names.fields["ball"] = compiled("length(p) - 1");
    const char* const cases[] = {"length(p*vec(1, 1.3, 1)) - 0.62 + 0.15*fbm(2.5*p, 4)", "turbulence(3*p, 3) - 0.4",
                                 "noise(4*vec(x*y, y, z)) + cellular(2*p)", "ball(vec(x, 2 * y, z)) + 0.5",
                                 "ball(vec(x*y, y + z, sin(z))) - x"};
    std::mt19937_64 random(5);
    for (const char* text : cases) {
        const auto field = compiled(text, names);
        for (int trial = 0; trial < 40; ++trial) {
            const IntervalBox box = random_box(random, 1.5, trial < 20 ? 0.03 : 0.6);
            const IntervalBox partials = field->gradient_range(box), axes = field->ImplicitField::gradient_range(box);
            for (int k = 0; k < 3; ++k) {
                ASSERT_TRUE(partials[k].lo == axes[k].lo && partials[k].hi == axes[k].hi) << text << ", partial " << k;
                ASSERT_FALSE(std::isnan(partials[k].lo) || std::isnan(partials[k].hi)) << text;
            }
            for (int sample = 0; sample < 50; ++sample) {
                const Vec3d g = field->gradient(random_point(random, box));  // a noise's: central differences
                for (int k = 0; k < 3; ++k) {
                    const double tolerance = 1e-3 * (1 + std::abs(g[k]));
                    EXPECT_TRUE(partials[k].lo - tolerance <= g[k] && g[k] <= partials[k].hi + tolerance)
                        << text << ": partial " << k << " " << g[k] << " outside [" << partials[k].lo << ", "
                        << partials[k].hi << "]";
                }
            }
        }
    }
}

TEST(ExpressionField, NoSlopeIsClaimedAcrossTheJumpsOfAtan2AndTan) {
    const auto angle = compiled("atan2(y, x)");
    const IntervalBox across{{-2, -1}, {-0.1, 0.1}, {0, 0}};
    EXPECT_FALSE(angle->slope_range(across, {0, 1, 0}).is_finite());
    EXPECT_TRUE(angle->slope_range({{1, 2}, {-0.1, 0.1}, {0, 0}}, {0, 1, 0}).is_finite());
    // tan on [1.4, 3.2] is positive at both ends, with a root at π beyond the pole.
    const Interval tan_slope = compiled("tan(x)")->slope_range({{1.4, 3.2}, {0, 0}, {0, 0}}, {1, 0, 0});
    EXPECT_LT(tan_slope.lo, 0);
    EXPECT_GT(tan_slope.hi, 0);
}

TEST(ExpressionField, MayReachSurfaceExcludesBoxesTheIntervalsClear) {
    const auto sphere = compiled("length(p) - 1");
    EXPECT_FALSE(sphere->may_reach_surface({3, 0, 0}, 0.5));
    EXPECT_TRUE(sphere->may_reach_surface({1, 0, 0}, 0.1));
    EXPECT_FALSE(sphere->may_reach_surface({0, 0, 0}, 0.2));
    const auto bounded = compile_expression({"x", {}, ""}, {}, FieldBox{{-1, -1, -1}, {1, 1, 1}});
    EXPECT_FALSE(bounded->may_reach_surface({0, 5, 0}, 0.5));
    EXPECT_TRUE(bounded->may_reach_surface({0, 0, 0}, 0.5));
}

TEST(ExpressionField, EvaluationIsDeterministicAndSafeToShare) {
    const auto field = compiled("length(p) - 1 + 0.1 * fbm(4 * p) + 0.05 * cellular(3 * p)");
    const Vec3d p{0.3, 0.7, -0.2};
    const double first = field->value(p);
    std::vector<double> results(4);
    std::vector<std::thread> threads;
    for (int i = 0; i < 4; ++i)
        threads.emplace_back([&, i] {
            double v = 0;
            for (int k = 0; k < 1000; ++k) v = field->value(p);
            results[i] = v;
        });
    for (std::thread& t : threads) t.join();
    for (double r : results) EXPECT_EQ(r, first);
    EXPECT_EQ(compiled("length(p) - 1 + 0.1 * fbm(4 * p) + 0.05 * cellular(3 * p)")->value(p), first);
}

}  // namespace
}  // namespace isotrace
