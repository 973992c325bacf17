// Pixel filters created through the registry: importance-sampled offsets stay within the radius, carry
// (nearly) constant positive weights, and are distributed like the normalised filter profile (chi-square).
#include "renderer/plugin/pixel_filter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "renderer/core/input_error.h"
#include "renderer/params/json_document.h"
#include "renderer/params/scene_node.h"
#include "renderer/sampling/independent_sampler.h"
#include "tests/support/chi_square.h"

namespace isotrace {
namespace {

using test_support::chi_square_test_2d;
using test_support::Grid2D;
using test_support::Point2;

std::unique_ptr<PixelFilter> make_filter(const std::string& json) {
    const JsonValue document = parse_json(json, "filter.json");
    const SceneNode node(document, "filter", std::make_shared<SceneFileContext>());
    return pixel_filter_registry().create(node);
}

struct FilterCase {
    std::string json;
    float radius;
    std::function<double(double)> profile;  // written out independently of the plugin
};

std::vector<FilterCase> filter_cases() {
    const auto gaussian = [](double radius, double sigma) {
        return [=](double x) {
            const auto g = [&](double v) { return std::exp(-v * v / (2 * sigma * sigma)); };
            return std::abs(x) >= radius ? 0.0 : std::max(0.0, g(x) - g(radius));
        };
    };
    const auto blackman_harris = [](double radius) {
        return [=](double x) {
            if (std::abs(x) >= radius) return 0.0;
            const double t = (x + radius) / (2 * radius);  // 0 .. 1 across the support
            const double a = 2 * std::numbers::pi * t;
            return 0.35875 - 0.48829 * std::cos(a) + 0.14128 * std::cos(2 * a) - 0.01168 * std::cos(3 * a);
        };
    };
    return {
        {R"({"type": "box"})", 0.5f, [](double x) { return std::abs(x) <= 0.5 ? 1.0 : 0.0; }},
        {R"({"type": "box", "radius": 1.5})", 1.5f, [](double x) { return std::abs(x) <= 1.5 ? 1.0 : 0.0; }},
        {R"({"type": "gaussian"})", 1.5f, gaussian(1.5, 0.5)},
        {R"({"type": "gaussian", "radius": 2, "sigma": 0.8})", 2.0f, gaussian(2.0, 0.8)},
        {R"({"type": "blackman_harris"})", 2.0f, blackman_harris(2.0)},
        {R"({"type": "blackman_harris", "radius": 1})", 1.0f, blackman_harris(1.0)},
    };
}

// Two independent uniform numbers per sample, as the renderer draws them (a pixel's dimensions 0 and 1).
std::array<float, 2> uniform_pair(const Sampler& sampler, std::size_t i) {
    const PixelSampleKey key{std::uint32_t(i % 97), std::uint32_t(i / 97), 0};
    return {sampler.sample(key, 0), sampler.sample(key, 1)};
}

TEST(PixelFilter, RegistryCreatesEveryFilterWithItsRadius) {
    for (const FilterCase& c : filter_cases()) {
        const auto filter = make_filter(c.json);
        EXPECT_FLOAT_EQ(filter->radius(), c.radius) << c.json;
        // evaluate() is the profile (up to float rounding) and vanishes outside the radius.
        for (double x = -c.radius - 0.5; x <= c.radius + 0.5; x += 0.01) {
            EXPECT_NEAR(filter->evaluate(float(x)), c.profile(float(x)), 1e-6) << c.json << " x = " << x;
        }
        EXPECT_EQ(filter->evaluate(c.radius * 1.01f), 0.0f);
        EXPECT_EQ(filter->evaluate(-c.radius * 1.01f), 0.0f);
    }
}

TEST(PixelFilter, BadParametersAreInputErrors) {
    EXPECT_THROW(make_filter(R"({"type": "gaussian", "radius": -1})"), InputError);
    EXPECT_THROW(make_filter(R"({"type": "gaussian", "sigma": 0})"), InputError);
    EXPECT_THROW(make_filter(R"({"type": "box", "radius": 0})"), InputError);
    EXPECT_THROW(make_filter(R"({"type": "blackman_harris", "width": 2})"), InputError);  // unknown key
    EXPECT_THROW(make_filter(R"({"type": "mitchell"})"), InputError);
}

TEST(PixelFilter, OffsetsStayWithinTheRadiusAndWeightsArePositiveAndConstant) {
    const IndependentSampler sampler(17);
    constexpr float kLargestBelowOne = 0x1.fffffep-1f;
    for (const FilterCase& c : filter_cases()) {
        const auto filter = make_filter(c.json);
        std::vector<std::array<float, 2>> inputs = {
            {0, 0}, {kLargestBelowOne, kLargestBelowOne}, {0, kLargestBelowOne}, {0.5f, 0.5f}, {1e-7f, 0.999999f}};
        for (std::size_t i = 0; i < 100000; ++i) inputs.push_back(uniform_pair(sampler, i));
        float lowest = INFINITY, highest = 0;
        for (const auto& u : inputs) {
            const FilterSample s = filter->sample(u);
            ASSERT_LE(std::abs(s.dx), c.radius) << c.json << " u = " << u[0];
            ASSERT_LE(std::abs(s.dy), c.radius) << c.json << " u = " << u[1];
            ASSERT_TRUE(std::isfinite(s.weight)) << c.json;
            lowest = std::min(lowest, s.weight);
            highest = std::max(highest, s.weight);
        }
        // Filter importance sampling: the weight filter/pdf is the same for every sample (offsets are drawn
        // exactly from the tabulated profile), so no sample is worth more than another and none is wasted.
        EXPECT_GT(lowest, 0.0f) << c.json;
        EXPECT_EQ(highest, lowest) << c.json << ": weights range over [" << lowest << ", " << highest << "]";
    }
}

// The density of the offsets must be the normalised filter, f(x) f(y) / (integral f)^2.
test_support::ChiSquareResult offset_fit(const PixelFilter& filter, const std::function<double(double)>& profile,
                                         std::size_t count, std::uint64_t seed) {
    const double r = filter.radius();
    double integral = 0;
    const int steps = 100000;
    for (int k = 0; k < steps; ++k) integral += profile(-r + (k + 0.5) * (2 * r / steps)) * (2 * r / steps);
    const IndependentSampler sampler(seed);
    const Grid2D grid{-r, r, -r, r, 24, 24};
    return chi_square_test_2d(
        grid, count,
        [&](std::size_t i) -> Point2 {
            const FilterSample s = filter.sample(uniform_pair(sampler, i));
            return {s.dx, s.dy};
        },
        [&](double x, double y) { return profile(x) * profile(y) / (integral * integral); });
}

TEST(PixelFilter, OffsetsFollowTheNormalisedFilterProfile) {
    const auto cases = filter_cases();
    const double significance = test_support::sidak_significance(0.01, int(cases.size()));
    for (const FilterCase& c : cases) {
        const auto filter = make_filter(c.json);
        const auto result = offset_fit(*filter, c.profile, 200000, 1234);
        EXPECT_GT(result.p_value, significance)
            << c.json << ": chi2 = " << result.statistic << ", dof = " << result.dof << ", p = " << result.p_value;
        EXPECT_GT(result.dof, 100) << c.json;
    }
}

TEST(PixelFilter, ChiSquareRejectsAWrongProfile) {
    // The same test with a subtly wrong expectation must fail: the test has the power to see mistakes.
    const auto gaussian = make_filter(R"({"type": "gaussian"})");
    const auto wider = [](double x) {  // sigma 0.55 instead of 0.5
        const auto g = [](double v) { return std::exp(-v * v / (2 * 0.55 * 0.55)); };
        return std::abs(x) >= 1.5 ? 0.0 : std::max(0.0, g(x) - g(1.5));
    };
    EXPECT_LT(offset_fit(*gaussian, wider, 200000, 1234).p_value, 1e-9);

    const auto blackman_harris = make_filter(R"({"type": "blackman_harris"})");
    const auto hann = [](double x) { return std::abs(x) >= 2 ? 0.0 : 0.5 + 0.5 * std::cos(std::numbers::pi * x / 2); };
    EXPECT_LT(offset_fit(*blackman_harris, hann, 200000, 1234).p_value, 1e-9);

    const auto box = make_filter(R"({"type": "box"})");
    const auto tent = [](double x) { return std::max(0.0, 1 - std::abs(x) / 0.5); };
    EXPECT_LT(offset_fit(*box, tent, 200000, 1234).p_value, 1e-9);
}

}  // namespace
}  // namespace isotrace
