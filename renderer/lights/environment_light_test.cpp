// Environment light: the lat-long conventions (+y pole = top row, u = 0.5 = -z, +x at u = 0.75), bilinear
// lookups, scale and rotation; importance sampling checked by a chi-square test of sampled directions against
// the integral of pdf() over (phi, cos theta) cells, for a structured EXR map (sun + gradient + black ground),
// also rotated; a pdf without the sin(theta) factor must fail that test; pdf is proportional to luminance
// where the map is smooth and never 0 where light arrives; constant environments; power; scene errors.
#include "renderer/lights/environment_light.h"

#include <gtest/gtest.h>

#include <limits>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "renderer/colour/colour_system.h"
#include "renderer/core/input_error.h"
#include "renderer/sampling/independent_sampler.h"
#include "tests/support/chi_square.h"
#include "tests/support/scene_files.h"
#include "tests/support/test_images.h"

namespace isotrace {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kWidth = 32, kHeight = 16;
const Rgb kTopRow(0.3f, 0.5f, 0.7f);
const Rgb kSun(100, 90, 80);

const ColourSystem& colours() {
    static const ColourSystem system("", "lin_rec709");
    return system;
}

// Test map, row 0 = top: top row constant; a gradient linear in x and in y (so a 3x3 symmetric blur leaves
// it unchanged); a 2x2 sun at columns 20-21, rows 4-5; black ground from row 12 (theta > 135 degrees) down.
Rgb test_texel(int x, int y) {
    if (y == 0) return kTopRow;
    if (y >= 12) return {};
    if (x >= 20 && x <= 21 && y >= 4 && y <= 5) return kSun;
    const float g = (0.2f + 0.8f * float(x) / kWidth) * (1.0f + float(y) / kHeight);
    return Rgb(1.0f, 0.8f, 0.6f) * g;
}

float luminance(const Rgb& c) { return (c.r + c.g + c.b) / 3; }

class EnvironmentLightTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::vector<float> pixels;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const Rgb c = test_texel(x, y);
                pixels.insert(pixels.end(), {c.r, c.g, c.b});
            }
        testing::write_rgb_image(directory_ / "sky.exr", kWidth, kHeight, pixels);
    }

    std::unique_ptr<Light> make(const std::string& json) const {
        const testing::ParsedScene scene(json, &colours(), directory_.path());
        return light_registry().create(scene.root());
    }
    std::unique_ptr<Light> sky(const std::string& extra = "") const {
        return make(R"({"type": "environment", "file": "sky.exr")" + extra + "}");
    }

    testing::TemporaryDirectory directory_{"environment_light"};
};

std::array<float, 2> u_sample(uint32_t i) {
    static const IndependentSampler sampler(4242);
    return {sampler.sample({i, 0, 0}, 0), sampler.sample({i, 0, 0}, 1)};
}

Vec3f direction_of(double phi, double cos_theta) {  // phi as in the map's u: atan2(x, -z)
    const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
    return Vec3f(Vec3d(sin_theta * std::sin(phi), cos_theta, -sin_theta * std::cos(phi)));
}

const test_support::Grid2D kGrid{-kPi, kPi, -1, 1, 24, 16};  // (phi, cos theta): cells of equal solid angle

test_support::Point2 grid_point(const Vec3f& d) { return {std::atan2(d.x, -d.z), d.y}; }

// Samples the light and returns the directions; also checks each sample's pdf against pdf().
std::vector<Vec3f> sample_directions(const Light& light, std::size_t count) {
    std::vector<Vec3f> directions;
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const LightSample s = light.sample({0, 0, 0}, u_sample(uint32_t(i)));
        EXPECT_GT(s.pdf, 0.0f);
        EXPECT_FALSE(s.is_delta);
        EXPECT_TRUE(std::isinf(s.distance));
        EXPECT_NEAR(length(s.direction), 1.0f, 1e-5f);
        const float pdf = light.pdf({0, 0, 0}, s.direction, s.distance, {});
        if (std::abs(pdf - s.pdf) > 1e-3f * s.pdf) ++mismatches;  // only where rounding crosses a cell edge
        directions.push_back(s.direction);
    }
    EXPECT_LE(mismatches, count / 1000) << "sample pdf differs from pdf()";
    return directions;
}

test_support::ChiSquareResult chi_square(const std::vector<Vec3f>& directions,
                                         const std::function<double(double, double)>& density) {
    return test_support::chi_square_test_2d(
        kGrid, directions.size(), [&](std::size_t i) { return grid_point(directions[i]); }, density);
}

// Histogram of sampled directions over (phi, theta) cells of map space aligned with the texels (2 x 2 cells
// per texel). In the (phi, theta) measure the density is pdf() * sin(theta) = pdf_uv / (2 pi^2), constant over
// a texel, so a cell's expected count is exactly N * pdf(centre) * sin(theta_centre) * dphi * dtheta: no
// numerical integration error, whatever the contrast of the map. (Quadrature over (cos theta, phi) cells
// that cut across texels and a bright sun was both slow and not exact.)
struct CellFit {
    std::vector<double> observed, expected, expected_without_sin;
    double expected_total = 0;
};

CellFit fit_cells(const Light& light, const std::vector<Vec3f>& directions, const Transform& to_world = {}) {
    constexpr int columns = 2 * kWidth, rows = 2 * kHeight;
    const double d_phi = 2 * kPi / columns, d_theta = kPi / rows;
    CellFit fit;
    fit.observed.assign(columns * rows, 0);
    const Transform to_map = to_world.inverse();
    for (const Vec3f& direction : directions) {
        const Vec3d m = normalize(to_map.vector(Vec3d(direction)));
        const double phi = std::atan2(m.x, -m.z), theta = std::acos(std::clamp(m.y, -1.0, 1.0));
        const int c = std::min(columns - 1, int((phi + kPi) / d_phi));
        const int r = std::min(rows - 1, int(theta / d_theta));
        fit.observed[std::size_t(r * columns + c)] += 1;
    }
    const double n = double(directions.size());
    double wrong_total = 0;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) {
            const double phi = -kPi + (c + 0.5) * d_phi, theta = (r + 0.5) * d_theta;
            const Vec3f d(to_world.vector(Vec3d(direction_of(phi, std::cos(theta)))));
            const double pdf = light.pdf({}, d, 0, {});
            fit.expected.push_back(n * pdf * std::sin(theta) * d_phi * d_theta);
            // The deliberately wrong density: pdf_uv / (2 pi^2) per solid angle, i.e. without 1 / sin(theta).
            fit.expected_without_sin.push_back(pdf * std::sin(theta) * std::sin(theta));
            fit.expected_total += fit.expected.back();
            wrong_total += fit.expected_without_sin.back();
        }
    for (double& e : fit.expected_without_sin) e *= n / wrong_total;  // normalised: only the shape is wrong
    return fit;
}

TEST_F(EnvironmentLightTest, ConventionsPoleCentreAndAxes) {
    const auto light = sky();
    EXPECT_TRUE(light->is_infinite());
    // +y: the top row (constant, so u does not matter at the pole).
    EXPECT_EQ(light->escaped_radiance({0, 1, 0}), kTopRow);
    EXPECT_EQ(light->escaped_radiance(normalize(Vec3f(0.001f, 1, 0.002f))), kTopRow);
    // -z = u 0.5, v 0.5: halfway between columns 15, 16 and rows 7, 8 (bilinear average of four texels).
    const Rgb centre = (test_texel(15, 7) + test_texel(16, 7) + test_texel(15, 8) + test_texel(16, 8)) * 0.25f;
    const Rgb at_minus_z = light->escaped_radiance({0, 0, -1});
    EXPECT_NEAR(at_minus_z.r, centre.r, 1e-5f);
    EXPECT_NEAR(at_minus_z.g, centre.g, 1e-5f);
    EXPECT_NEAR(at_minus_z.b, centre.b, 1e-5f);
    // Texel centres are hit exactly: column x, row y at u = (x + 0.5) / W, theta = pi (y + 0.5) / H.
    for (const auto& [x, y] : {std::pair{24, 6}, std::pair{3, 2}, std::pair{20, 4}}) {
        const Vec3f d = direction_of(2 * kPi * ((x + 0.5) / kWidth - 0.5), std::cos(kPi * (y + 0.5) / kHeight));
        const Rgb value = light->escaped_radiance(d);
        EXPECT_NEAR(value.g, test_texel(x, y).g, 1e-4f * test_texel(x, y).g) << x << ", " << y;
    }
    // +x at u = 0.75 (column 24 starts there), -x at u = 0.25, ground below.
    EXPECT_EQ(EnvironmentLight::direction_to_uv({1, 0, 0})[0], 0.75f);
    EXPECT_EQ(EnvironmentLight::direction_to_uv({-1, 0, 0})[0], 0.25f);
    EXPECT_EQ(EnvironmentLight::direction_to_uv({0, 0, -1}), (std::array<float, 2>{0.5f, 0.5f}));
    EXPECT_EQ(EnvironmentLight::direction_to_uv({0, 1, 0})[1], 0.0f);
    EXPECT_TRUE(light->escaped_radiance({0, -1, 0}).is_black());
    // Round trip.
    for (uint32_t i = 0; i < 100; ++i) {
        const auto uv = u_sample(i);
        const auto back = EnvironmentLight::direction_to_uv(EnvironmentLight::uv_to_direction(uv));
        EXPECT_NEAR(back[0], uv[0], 1e-4f);
        EXPECT_NEAR(back[1], uv[1], 1e-4f);
    }
    // Scale.
    EXPECT_EQ(sky(R"(, "scale": 2)")->escaped_radiance({0, 1, 0}), kTopRow * 2.0f);
}

TEST_F(EnvironmentLightTest, TransformRotatesTheMap) {
    const auto plain = sky();
    const auto turned = sky(R"(, "transform": {"rotate": {"axis": [0, 1, 0], "angle": 90}})");
    // Rotating 90 degrees about +y takes the map's -z (its centre) to world -x.
    EXPECT_EQ(turned->escaped_radiance({-1, 0, 0}), plain->escaped_radiance({0, 0, -1}));
    const auto tilted = sky(R"(, "transform": {"rotate": {"axis": [1, 2, 3], "angle": 70}})");
    const Transform rotation = Transform::rotate({1, 2, 3}, 70);
    for (uint32_t i = 0; i < 200; ++i) {
        const auto u = u_sample(i);
        const Vec3f d = direction_of(2 * kPi * (u[0] - 0.5), 2 * u[1] - 1);
        const Rgb expected = plain->escaped_radiance(d), actual = tilted->escaped_radiance(rotation.vector(d));
        EXPECT_NEAR(actual.r, expected.r, 1e-3f * (1 + expected.r));
        const float pdf = plain->pdf({}, d, 0, {});
        EXPECT_NEAR(tilted->pdf({}, rotation.vector(d), 0, {}), pdf, 1e-3f * pdf);
    }
}

TEST_F(EnvironmentLightTest, SampledDirectionsFollowPdf) {
    const auto light = sky();
    constexpr std::size_t count = 100000;
    const CellFit fit = fit_cells(*light, sample_directions(*light, count));
    EXPECT_NEAR(fit.expected_total, double(count), 1e-4 * count);  // pdf() integrates to 1 over the sphere
    const auto result = test_support::chi_square_test(fit.observed, fit.expected);
    EXPECT_GT(result.p_value, 0.01) << "statistic " << result.statistic << " dof " << result.dof;

    // Proof that the test can fail: the same samples against a pdf that forgot the 1 / sin(theta) of the
    // lat-long Jacobian (pdf_uv / (2 pi^2) instead of pdf_uv / (2 pi^2 sin theta)), normalised to 1.
    const auto wrong = test_support::chi_square_test(fit.observed, fit.expected_without_sin);
    EXPECT_LT(wrong.p_value, 1e-12) << "statistic " << wrong.statistic << " dof " << wrong.dof;
}

TEST_F(EnvironmentLightTest, RotatedMapSamplesFollowPdf) {
    const auto light = sky(R"(, "transform": {"rotate": [30, -50, 10]})");
    const Transform to_world =
        Transform::rotate({0, 0, 1}, 10) * Transform::rotate({0, 1, 0}, -50) * Transform::rotate({1, 0, 0}, 30);
    constexpr std::size_t count = 100000;
    const CellFit fit = fit_cells(*light, sample_directions(*light, count), to_world);
    EXPECT_NEAR(fit.expected_total, double(count), 1e-4 * count);
    const auto result = test_support::chi_square_test(fit.observed, fit.expected);
    EXPECT_GT(result.p_value, 0.01) << "statistic " << result.statistic << " dof " << result.dof;
    // The unrotated expectation does not fit the rotated samples.
    const CellFit unrotated = fit_cells(*light, sample_directions(*light, count));
    EXPECT_LT(test_support::chi_square_test(unrotated.observed, fit.expected).p_value, 1e-12);
}

TEST_F(EnvironmentLightTest, PdfIsProportionalToLuminanceAndNeverZeroWhereLightArrives) {
    const auto light = sky();
    // At texel centres whose 3x3 neighbourhood is gradient (away from the top row, ground, sun and the
    // u seam), the cell weight equals the texel's luminance times sin(theta), so pdf / luminance is constant.
    double ratio = 0;
    int checked = 0;
    for (int y = 2; y <= 10; ++y)
        for (int x = 1; x <= kWidth - 2; ++x) {
            if (x >= 19 && x <= 22 && y >= 3 && y <= 6) continue;
            const Vec3f d = direction_of(2 * kPi * ((x + 0.5) / kWidth - 0.5), std::cos(kPi * (y + 0.5) / kHeight));
            const double r = light->pdf({}, d, 0, {}) / luminance(light->escaped_radiance(d));
            if (checked++ == 0) ratio = r;
            EXPECT_NEAR(r, ratio, 1e-4 * ratio) << "texel " << x << ", " << y;
        }
    EXPECT_GT(checked, 200);
    // The sun is the brightest, the ground has no probability, and wherever radiance is non-zero the pdf is
    // positive (the bilinear filter's reach is included in the weights).
    const Vec3f sun = direction_of(2 * kPi * (21.0 / kWidth - 0.5), std::cos(kPi * 5.0 / kHeight));
    EXPECT_GT(light->pdf({}, sun, 0, {}), 50 * light->pdf({}, {0, 0, -1}, 0, {}));
    EXPECT_EQ(light->pdf({}, {0, -1, 0}, 0, {}), 0.0f);
    EXPECT_EQ(light->pdf({}, direction_of(1.0, std::cos(kPi * 13.5 / kHeight)), 0, {}), 0.0f);
    for (uint32_t i = 0; i < 20000; ++i) {
        const auto u = u_sample(i);
        const Vec3f d = direction_of(2 * kPi * (u[0] - 0.5), 2 * u[1] - 1);
        if (!light->escaped_radiance(d).is_black()) {
            EXPECT_GT(light->pdf({}, d, 0, {}), 0.0f) << i;
        }
    }
}

TEST_F(EnvironmentLightTest, ConstantEnvironmentIsUniform) {
    const auto light = make(R"({"type": "environment", "radiance": [1, 2, 3], "scale": 0.5})");
    EXPECT_TRUE(light->is_infinite());
    EXPECT_EQ(light->escaped_radiance({0.6f, 0, 0.8f}), Rgb(0.5f, 1, 1.5f));
    EXPECT_FLOAT_EQ(light->pdf({}, {0, 1, 0}, 0, {}), float(1 / (4 * kPi)));
    EXPECT_FLOAT_EQ(light->pdf({}, {0.6f, 0, -0.8f}, 0, {}), float(1 / (4 * kPi)));
    const auto directions = sample_directions(*light, 50000);
    const auto result = chi_square(directions, [](double, double) { return 1 / (4 * kPi); });
    EXPECT_GT(result.p_value, 0.01) << "statistic " << result.statistic;
    EXPECT_EQ(light->sample({}, {0.2f, 0.3f}).radiance, Rgb(0.5f, 1, 1.5f));
}

TEST_F(EnvironmentLightTest, PowerUsesTheSceneRadiusAndAverageRadiance) {
    Bounds3f bounds;
    bounds.extend({-1, -1, -1});
    bounds.extend({1, 1, 1});  // bounding sphere radius sqrt(3)
    auto constant = make(R"({"type": "environment", "radiance": [1, 2, 3]})");
    constant->preprocess(bounds);
    EXPECT_NEAR(constant->power(), kPi * 3 * 3, 1e-4);
    // A map of one colour: the average is that colour, times the scale.
    testing::write_rgb_image(directory_ / "flat.exr", 4, 2, std::vector<float>(4 * 2 * 3, 2.0f));
    auto map = make(R"({"type": "environment", "file": "flat.exr", "scale": 1.5})");
    EXPECT_EQ(map->power(), 0.0f);  // before preprocess()
    map->preprocess(bounds);
    EXPECT_NEAR(map->power(), kPi * 3 * 3, 1e-4);
}

// A sky of 1e20 over a scene 1e18 across: pi R^2 L overflowed float, and light selection then failed.
TEST_F(EnvironmentLightTest, PowerOfAHugeSceneSaturatesInsteadOfOverflowing) {
    Bounds3f bounds;
    bounds.extend({-1e18f, -1e18f, -1e18f});
    bounds.extend({1e18f, 1e18f, 1e18f});
    auto constant = make(R"({"type": "environment", "radiance": 1e20})");
    constant->preprocess(bounds);
    EXPECT_EQ(constant->power(), std::numeric_limits<float>::max());
}

// The direction of a ray RenderScene could not trace (RenderScene::intersect) has no place on the map.
TEST_F(EnvironmentLightTest, NonFiniteDirectionsEscapeToBlack) {
    const auto plain = sky();
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (const Vec3f& d : {Vec3f(nan, 0, 0), Vec3f(0, inf, 0), Vec3f(inf, inf, -inf)})
        EXPECT_TRUE(plain->escaped_radiance(d).is_black());
}

TEST_F(EnvironmentLightTest, SceneErrors) {
    EXPECT_THROW(make(R"({"type": "environment", "file": "sky.exr", "radiance": 1})"), InputError);
    EXPECT_THROW(make(R"({"type": "environment", "file": "sky.exr", "transform": {"scale": 2}})"), InputError);
    EXPECT_THROW(make(R"({"type": "environment", "file": "missing.exr"})"), InputError);
    EXPECT_THROW(make(R"({"type": "environment", "file": "sky.exr", "space": "no such space"})"), InputError);
    EXPECT_THROW(make(R"({"type": "environment", "radiance": 1, "transform": {"rotate": [0, 90, 0]}})"), InputError);
    EXPECT_THROW(make(R"({"type": "environment", "file": "sky.exr", "scael": 2})"), InputError);
    EXPECT_NO_THROW(make(R"({"type": "environment", "file": "sky.exr", "space": "lin_rec709",
                             "transform": {"rotate": [0, 90, 0], "translate": [1, 2, 3]}})"));
}

}  // namespace
}  // namespace isotrace
