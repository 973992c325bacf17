// The five kernels of Table 1 (MetaCube paper): end values, continuity and smoothness at R and at Nishimura's
// R/3, derivatives against finite differences, polynomial coefficients against the values, the monotone/convex
// guarantee root finders rely on, Blinn's truncation, closed-form iso-radii, the factory and validation.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/implicit/blinn_exponential.h"
#include "geometry/implicit/field_function.h"
#include "geometry/implicit/implicit_test_support.h"
#include "geometry/implicit/nishimura_quadratic.h"

namespace isotrace {
namespace {

// Every kernel, with Blinn at a soft, the default and a sharp setting.
std::vector<std::shared_ptr<const FieldFunction>> all_kernels() {
    std::vector<std::shared_ptr<const FieldFunction>> kernels;
    for (std::string_view name : field_function_names())
        kernels.push_back(make_field_function(name, BlinnExponential::kDefaultSharpness));
    kernels.push_back(std::make_shared<BlinnExponential>(0.5));
    kernels.push_back(std::make_shared<BlinnExponential>(20));
    return kernels;
}

bool is_c1_at_support(const FieldFunction& kernel) { return kernel.name() != "blinn"; }

double horner(const FieldPiece& piece, double r2) {
    double value = 0;
    for (int k = piece.degree; k >= 0; --k) value = value * r2 + piece.coefficients[k];
    return value;
}

// w·f(r) = T to 1e-12 relative, plus the effect of rounding r itself (r² = R²·x to a few ulps). That term matters
// only where f vanishes linearly at the cut (Blinn) or the level is tiny: r near R cannot resolve R − r finer.
double iso_tolerance(const FieldFunction& kernel, double unit_r, double weight, double threshold) {
    const double x = unit_r * unit_r;
    return 1e-12 * threshold + weight * std::abs(kernel.unit_derivative(x)) * x * 1e-15;
}

// R = 1.7 everywhere so that a forgotten R shows up.
constexpr double kRadius = 1.7;
constexpr double kRadius2 = kRadius * kRadius;

TEST(FieldFunction, IsOneAtTheSkeletonAndZeroFromTheSupportRadiusOn) {
    for (const auto& kernel : all_kernels()) {
        SCOPED_TRACE(std::string(kernel->name()));
        EXPECT_DOUBLE_EQ(kernel->value(0, kRadius), 1);
        EXPECT_EQ(kernel->value(kRadius2, kRadius), 0);
        EXPECT_EQ(kernel->value(4 * kRadius2, kRadius), 0);
        EXPECT_EQ(kernel->derivative(kRadius2, kRadius), 0);
        EXPECT_EQ(kernel->derivative(4 * kRadius2, kRadius), 0);
    }
}

TEST(FieldFunction, IsContinuousAtTheSupportRadiusAndC1WhereTheKernelIs) {
    for (const auto& kernel : all_kernels()) {
        SCOPED_TRACE(std::string(kernel->name()));
        const double just_inside = kRadius2 * (1 - 1e-9);
        EXPECT_LT(kernel->value(just_inside, kRadius), 1e-7);
        if (is_c1_at_support(*kernel)) {
            EXPECT_LT(std::abs(kernel->derivative(just_inside, kRadius)), 1e-7);
        }
    }
    // Blinn's truncation leaves a kink of a·e^(−a)/(1 − e^(−a)) in df/dx at the cut.
    const BlinnExponential blinn(3);
    EXPECT_NEAR(blinn.unit_derivative(1), -3 * std::exp(-3.0) / (1 - std::exp(-3.0)), 1e-15);
}

TEST(FieldFunction, NishimuraPiecesMeetWithEqualValueAndSlopeAtAThirdOfTheRadius) {
    const NishimuraQuadratic kernel;
    const double x = NishimuraQuadratic::kUnitBreakpoint, h = 1e-12;
    EXPECT_NEAR(kernel.unit_value(x - h), 2.0 / 3, 1e-11);
    EXPECT_NEAR(kernel.unit_value(x + h), 2.0 / 3, 1e-11);
    EXPECT_NEAR(kernel.unit_derivative(x - h), -3, 1e-10);
    EXPECT_NEAR(kernel.unit_derivative(x + h), -3, 1e-10);
    // The table's form in r: 1 − 3(r/R)² inside, 3/2·(1 − r/R)² outside.
    EXPECT_DOUBLE_EQ(kernel.value(0.2 * 0.2 * kRadius2, kRadius), 1 - 3 * 0.04);
    EXPECT_DOUBLE_EQ(kernel.value(0.6 * 0.6 * kRadius2, kRadius), 1.5 * 0.4 * 0.4);
}

TEST(FieldFunction, MatchesTheFormulasOfTable1) {
    const double r = 0.8, s = r / kRadius, r2 = r * r;
    EXPECT_DOUBLE_EQ(make_field_function("kim", 0)->value(r2, kRadius), std::pow(1 - s * s, 3));
    EXPECT_DOUBLE_EQ(make_field_function("murakami", 0)->value(r2, kRadius), std::pow(1 - s * s, 2));
    EXPECT_NEAR(make_field_function("wyvill", 0)->value(r2, kRadius),
                -4.0 / 9 * std::pow(s, 6) + 17.0 / 9 * std::pow(s, 4) - 22.0 / 9 * s * s + 1, 1e-15);
    EXPECT_DOUBLE_EQ(make_field_function("wyvill", 0)->value(0.25 * kRadius2, kRadius), 0.5);
    // Blinn: the truncated, renormalised e^(−a r²/R²).
    const double a = 2.5, raw = std::exp(-a * s * s), cut = std::exp(-a);
    EXPECT_NEAR(make_field_function("blinn", a)->value(r2, kRadius), (raw - cut) / (1 - cut), 1e-15);
}

TEST(FieldFunction, SharpBlinnApproachesTheRawExponential) {
    const BlinnExponential blinn(30);
    for (double x : {0.0, 0.01, 0.1, 0.5, 0.9}) EXPECT_NEAR(blinn.unit_value(x), std::exp(-30 * x), 1e-13);
}

TEST(FieldFunction, DerivativeMatchesFiniteDifferences) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.001, 0.999);
    for (const auto& kernel : all_kernels()) {
        SCOPED_TRACE(std::string(kernel->name()));
        for (int i = 0; i < 200; ++i) {
            const double r2 = unit(rng) * kRadius2, h = 1e-6 * kRadius2;
            if (kernel->name() == "nishimura" &&
                std::abs(r2 - NishimuraQuadratic::kUnitBreakpoint * kRadius2) < 2 * h)
                continue;  // C¹ but not C² there: the central difference is only first-order accurate
            const double numeric = (kernel->value(r2 + h, kRadius) - kernel->value(r2 - h, kRadius)) / (2 * h);
            EXPECT_NEAR(kernel->derivative(r2, kRadius), numeric, 1e-7 * (1 + std::abs(numeric)));
        }
    }
}

TEST(FieldFunction, PolynomialPiecesReproduceTheValues) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    for (const auto& kernel : all_kernels()) {
        SCOPED_TRACE(std::string(kernel->name()));
        const FieldPieces pieces = kernel->pieces(kRadius);
        ASSERT_GE(pieces.count, 1);
        EXPECT_EQ(pieces.span().front().r2_begin, 0);
        EXPECT_DOUBLE_EQ(pieces.span().back().r2_end, kRadius2);
        for (int i = 0; i + 1 < pieces.count; ++i) EXPECT_EQ(pieces.pieces[i].r2_end, pieces.pieces[i + 1].r2_begin);
        for (const FieldPiece& piece : pieces.span()) {
            if (!piece.is_polynomial) continue;
            for (int i = 0; i < 100; ++i) {
                const double r2 = piece.r2_begin + unit(rng) * (piece.r2_end - piece.r2_begin);
                EXPECT_NEAR(horner(piece, r2), kernel->value(r2, kRadius), 1e-14);
            }
        }
    }
}

TEST(FieldFunction, PolynomialFlagsMatchTheKernels) {
    auto polynomial_flags = [](std::string_view name) {
        std::vector<bool> flags;
        // Kept in a variable: span() of the temporary would dangle (AddressSanitizer: stack-use-after-scope).
        const FieldPieces pieces = make_field_function(name, 1)->pieces(1);
        for (const FieldPiece& piece : pieces.span()) flags.push_back(piece.is_polynomial);
        return flags;
    };
    EXPECT_EQ(polynomial_flags("kim"), std::vector<bool>{true});
    EXPECT_EQ(polynomial_flags("wyvill"), std::vector<bool>{true});
    EXPECT_EQ(polynomial_flags("murakami"), std::vector<bool>{true});
    EXPECT_EQ(polynomial_flags("blinn"), std::vector<bool>{false});
    EXPECT_EQ(polynomial_flags("nishimura"), (std::vector<bool>{true, false}));
    EXPECT_DOUBLE_EQ(make_field_function("nishimura", 1)->pieces(3).pieces[0].r2_end, 1);  // (R/3)² with R = 3
}

// The guarantee documented in field_function.h: non-increasing and convex in r², so a piece's values lie between
// its end values and the slope at its start bounds the slope on it.
TEST(FieldFunction, IsNonIncreasingAndConvexInSquaredDistance) {
    for (const auto& kernel : all_kernels()) {
        SCOPED_TRACE(std::string(kernel->name()));
        double previous_value = kernel->value(0, kRadius), previous_slope = kernel->derivative(0, kRadius);
        for (int i = 1; i <= 2000; ++i) {
            const double r2 = kRadius2 * 1.1 * i / 2000;
            const double value = kernel->value(r2, kRadius), slope = kernel->derivative(r2, kRadius);
            EXPECT_LE(value, previous_value + 1e-15);
            EXPECT_LE(slope, 1e-15);
            EXPECT_GE(slope, previous_slope - 1e-12);
            previous_value = value;
            previous_slope = slope;
        }
    }
}

TEST(FieldFunction, IsoRadiusReachesTheThresholdExactly) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> log_level(std::log(1e-6), std::log(0.999999));
    for (const auto& kernel : all_kernels()) {
        SCOPED_TRACE(std::string(kernel->name()));
        for (int i = 0; i < 500; ++i) {
            const double weight = 2.5, threshold = weight * std::exp(log_level(rng));
            const std::optional<double> r = kernel->iso_radius(kRadius, weight, threshold);
            ASSERT_TRUE(r.has_value());
            ASSERT_GT(*r, 0);
            ASSERT_LT(*r, kRadius);
            EXPECT_NEAR(weight * kernel->value(*r * *r, kRadius), threshold,
                        iso_tolerance(*kernel, *r / kRadius, weight, threshold))
                << threshold;
        }
    }
    // The paper's rounded-box offset for Kim's kernel: ρ = R·sqrt(1 − (T/w)^(1/3)).
    EXPECT_NEAR(*make_field_function("kim", 0)->iso_radius(2, 1, 0.125), 2 * std::sqrt(0.5), 1e-15);
}

TEST(FieldFunction, WyvillIsoRadiusIsAccurateOnBothSidesOfItsClosedFormBranches) {
    const auto wyvill = make_field_function("wyvill", 0);
    for (double level : {125.0 / 972 * (1 - 1e-12), 125.0 / 972, 125.0 / 972 * (1 + 1e-12), 125.0 / 1944, 1e-12}) {
        const double r = *wyvill->iso_radius(1, 1, level);
        EXPECT_NEAR(wyvill->value(r * r, 1), level, iso_tolerance(*wyvill, r, 1, level)) << level;
    }
}

TEST(FieldFunction, IsoRadiusIsAbsentWhenTheWeightCannotReachTheThreshold) {
    for (const auto& kernel : all_kernels()) {
        EXPECT_FALSE(kernel->iso_radius(1, 0.5, 0.5).has_value());
        EXPECT_FALSE(kernel->iso_radius(1, 0.4, 0.5).has_value());
        EXPECT_FALSE(kernel->iso_radius(1, -1, 0.5).has_value());
        EXPECT_EQ(kernel->iso_radius(0, 2, 0.5), 0.0);  // a hard cube's surface is its box
    }
}

TEST(FieldFunction, RejectsInvalidParametersNamingTheField) {
    const auto kim = make_field_function("kim", 0);
    expect_invalid_naming([&] { kim->iso_radius(1, 1, 0); }, "threshold");
    expect_invalid_naming([&] { kim->iso_radius(1, 1, -0.5); }, "threshold");
    expect_invalid_naming([&] { kim->iso_radius(1, 1, NAN); }, "threshold");
    expect_invalid_naming([&] { kim->iso_radius(-1, 1, 0.5); }, "radius");
    expect_invalid_naming([&] { kim->iso_radius(INFINITY, 1, 0.5); }, "radius");
    expect_invalid_naming([&] { kim->iso_radius(1, NAN, 0.5); }, "weight");
    expect_invalid_naming([] { validate_threshold(INFINITY); }, "threshold");
    expect_invalid_naming([] { BlinnExponential(0); }, "sharpness");
    expect_invalid_naming([] { BlinnExponential(-1); }, "sharpness");
    expect_invalid_naming([] { BlinnExponential(NAN); }, "sharpness");
    expect_invalid_naming([] { make_field_function("gaussian", 1); }, "field");
}

TEST(FieldFunction, FactoryKnowsEveryNameOfTable1) {
    for (std::string_view name : field_function_names()) EXPECT_EQ(make_field_function(name, 1)->name(), name);
    EXPECT_EQ(field_function_names().size(), 5u);
}

}  // namespace
}  // namespace isotrace
