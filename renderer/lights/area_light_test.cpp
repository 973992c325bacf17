// AreaLight on a square (two triangles), on a rectangle (sampled by solid angle) and on a sphere: sample() and
// pdf() agree, the estimator sum(L cos / pdf) / N converges to the closed-form irradiance (within 3 standard
// errors), solid-angle sampling has the lower variance, one-sided emitters give nothing from behind,
// power() = pi * area * L (twice that when two-sided), also with the "emissive" material plugin.
#include "renderer/lights/area_light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "geometry/mesh/triangle_mesh_shape.h"
#include "geometry/rectangle/rectangle_shape.h"
#include "geometry/sphere/sphere_shape.h"
#include "renderer/plugin/surface_hit.h"
#include "renderer/sampling/independent_sampler.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

constexpr double kPi = std::numbers::pi;
const Rgb kRadiance(2.0f, 1.0f, 0.5f);

// Lambertian emitter of the front side (the geometric normal's side), or of both sides.
class TestEmitter final : public Material {
public:
    explicit TestEmitter(bool two_sided) : two_sided_(two_sided) {}
    Rgb albedo(const SurfaceHit&) const override { return {}; }
    Rgb emission(const SurfaceHit& hit, const Vec3f& towards_viewer) const override {
        return two_sided_ || dot(hit.geometric_normal, towards_viewer) > 0 ? kRadiance : Rgb();
    }
    bool is_emissive() const override { return true; }

private:
    bool two_sided_;
};

constexpr float kHalfSide = 1.0f, kHeight = 1.5f;

// The square [-1, 1]^2 at y = 1.5, counter-clockwise seen from below: it emits downwards (-y).
TriangleMeshShape square_light_shape() {
    TriangleMeshData mesh;
    mesh.positions = {{-kHalfSide, kHeight, -kHalfSide}, {kHalfSide, kHeight, -kHalfSide},
                      {kHalfSide, kHeight, kHalfSide}, {-kHalfSide, kHeight, kHalfSide}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    return TriangleMeshShape(std::move(mesh));
}

// The same square as a rectangle shape: edges x and z, whose cross product −y is its front.
RectangleShape square_rectangle_shape() {
    return RectangleShape({0, kHeight, 0}, {2 * kHalfSide, 0, 0}, {0, 0, 2 * kHalfSide});
}

// A shape's area sampling alone: hides the solid-angle sampling of the shape it wraps.
class AreaSamplingOnly final : public Shape {
public:
    explicit AreaSamplingOnly(const Shape& shape) : shape_(shape) {}
    std::string type_name() const override { return "area_only"; }
    std::size_t primitive_count() const override { return 1; }
    Bounds3f bounds() const override { return shape_.bounds(); }
    bool can_bake(const Transform&) const override { return false; }
    void bake(const Transform&) override {}
    RTCGeometry create_geometry(RTCDevice) override { return nullptr; }
    bool supports_surface_sampling() const override { return true; }
    SurfaceSample sample_surface(std::array<float, 2> u) const override { return shape_.sample_surface(u); }
    float surface_area() const override { return shape_.surface_area(); }

private:
    const Shape& shape_;
};

std::array<float, 2> u_sample(uint32_t i) {
    static const IndependentSampler sampler(99);
    return {sampler.sample({i, 0, 0}, 0), sampler.sample({i, 0, 0}, 1)};
}

struct Estimate {
    double mean = 0, standard_error = 0;
};

// Irradiance on a surface at `point` with normal `normal`, red channel, by light sampling.
Estimate estimate_irradiance(const Light& light, const Vec3f& point, const Vec3f& normal, uint32_t samples) {
    double sum = 0, sum_squares = 0;
    for (uint32_t i = 0; i < samples; ++i) {
        const LightSample s = light.sample(point, u_sample(i));
        if (!(s.pdf > 0)) continue;
        const double f = s.radiance.r * std::max(0.0f, dot(normal, s.direction)) / s.pdf;
        sum += f;
        sum_squares += f * f;
    }
    const double mean = sum / samples;
    const double variance = std::max(0.0, sum_squares / samples - mean * mean);
    return {mean, std::sqrt(variance / samples)};
}

// The irradiance below the centre of the square (see the first test).
double square_irradiance() {
    const double x = kHalfSide / kHeight, s = std::sqrt(1 + x * x);
    return kRadiance.r * 4 * x / s * std::atan(x / s);
}

TEST(AreaLight, SquareLightIrradianceMatchesTheClosedForm) {
    const TriangleMeshShape shape = square_light_shape();
    const TestEmitter material(false);
    const AreaLight light(shape, material);
    // A point below the centre of a 2a x 2a square at distance h: four corner rectangles, each with the
    // form factor (1 / 2pi) * 2 X / sqrt(1 + X^2) * atan(X / sqrt(1 + X^2)), X = a / h; E = pi L sum(F).
    const double expected = square_irradiance();
    const Estimate e = estimate_irradiance(light, {0, 0, 0}, {0, 1, 0}, 100000);
    EXPECT_NEAR(e.mean, expected, 3 * e.standard_error) << "standard error " << e.standard_error;
    EXPECT_LT(e.standard_error, 0.01 * expected);  // the comparison is meaningful
}

TEST(AreaLight, RectangleLightSampledBySolidAngleMatchesTheClosedFormWithLessVariance) {
    const RectangleShape rectangle = square_rectangle_shape();
    const AreaSamplingOnly by_area(rectangle);
    const TestEmitter material(false);
    const AreaLight light(rectangle, material), area_light(by_area, material);
    for (const Vec3f& point : {Vec3f(0, 0, 0), Vec3f(0.3f, 1.2f, -0.4f), Vec3f(0.3f, 1.38f, -0.4f), Vec3f(1.3f, 1.38f, -0.4f), Vec3f(0.9f, 1.48f, -0.4f)}) {
        const Estimate solid_angle = estimate_irradiance(light, point, {0, 1, 0}, 50000);
        const Estimate area = estimate_irradiance(area_light, point, {0, 1, 0}, 50000);
        const double joint = std::hypot(solid_angle.standard_error, area.standard_error);
        EXPECT_NEAR(solid_angle.mean, area.mean, 3 * joint) << point.x << " " << point.y;
        if (point.y == 0) { EXPECT_NEAR(solid_angle.mean, square_irradiance(), 3 * solid_angle.standard_error); }
        // Only cos θ at the receiver varies under solid-angle sampling; by area, 1/d² and cos at the light too.
        EXPECT_LT(solid_angle.standard_error, 0.7 * area.standard_error) << point.y;
    }
}

TEST(AreaLight, SphereLightIrradianceMatchesTheClosedForm) {
    const SphereShape shape({{{0, 3, 0}, 0.5}});
    const TestEmitter material(false);
    const AreaLight light(shape, material);
    // A sphere of radius r whose centre is at distance d on the normal: E = pi L (r / d)^2. The far half of
    // the sphere is seen from behind (radiance 0), which the one-sided emission takes care of.
    const double expected = kPi * kRadiance.r * (0.5 / 3) * (0.5 / 3);
    const Estimate e = estimate_irradiance(light, {0, 0, 0}, {0, 1, 0}, 100000);
    EXPECT_NEAR(e.mean, expected, 3 * e.standard_error) << "standard error " << e.standard_error;
    EXPECT_LT(e.standard_error, 0.02 * expected);
}

TEST(AreaLight, SamplePdfEqualsPdf) {
    const TriangleMeshShape square = square_light_shape();
    const SphereShape sphere({{{0, 3, 0}, 0.5}});
    const TestEmitter material(false);
    const AreaLight square_light(square, material), sphere_light(sphere, material);
    const Vec3f points[] = {{0, 0, 0}, {0.3f, -1, 2}, {-3, 1.2f, 0.5f}, {0.2f, 2.5f, -0.1f}};
    for (const Vec3f& point : points) {
        for (uint32_t i = 0; i < 200; ++i) {
            const LightSample a = square_light.sample(point, u_sample(i));
            ASSERT_GT(a.pdf, 0.0f);
            EXPECT_NEAR(length(a.direction), 1.0f, 1e-5f);
            const Vec3f on_square = point + a.direction * a.distance;
            EXPECT_NEAR(on_square.y, kHeight, 1e-4f);
            EXPECT_NEAR(square_light.pdf(point, a.direction, a.distance, {0, -1, 0}), a.pdf, 1e-4f * a.pdf);
            // The normal's orientation does not matter to the density.
            EXPECT_NEAR(square_light.pdf(point, a.direction, a.distance, {0, 1, 0}), a.pdf, 1e-4f * a.pdf);

            const LightSample b = sphere_light.sample(point, u_sample(i));
            ASSERT_GT(b.pdf, 0.0f);
            const Vec3f on_sphere = point + b.direction * b.distance;
            const Vec3f normal = normalize(on_sphere - Vec3f(0, 3, 0));
            EXPECT_NEAR(length(on_sphere - Vec3f(0, 3, 0)), 0.5f, 1e-4f);
            // The normal recomputed here carries float rounding that matters at grazing angles (1 / cos).
            const float cos_light = std::abs(dot(normal, b.direction));
            const float tolerance = (1e-4f + 1e-5f / cos_light) * b.pdf;
            EXPECT_NEAR(sphere_light.pdf(point, b.direction, b.distance, normal), b.pdf, tolerance);
            // Analytic density: d^2 / (|cos| A), A = pi.
            EXPECT_NEAR(b.pdf, b.distance * b.distance / (cos_light * float(kPi)), tolerance);
        }
    }
}

TEST(AreaLight, RectangleSamplePdfEqualsPdfBySolidAngleAndByArea) {
    const RectangleShape rectangle = square_rectangle_shape();
    const TestEmitter material(true);
    const AreaLight light(rectangle, material);
    // Near (by solid angle, uniform), above (the back), and far (by area: it subtends less than 1e-4 sr).
    for (const Vec3f& point : {Vec3f(0, 0, 0), Vec3f(0.3f, 2, 2), Vec3f(-1, 1.4f, 0.2f), Vec3f(10, -300, 5)}) {
        const bool by_solid_angle = rectangle.solid_angle_pdf(point) > 0;
        EXPECT_EQ(by_solid_angle, point.y > -100) << point.y;
        for (uint32_t i = 0; i < 200; ++i) {
            const LightSample s = light.sample(point, u_sample(i));
            ASSERT_GT(s.pdf, 0.0f);
            EXPECT_NEAR((point + s.direction * s.distance).y, kHeight, 2e-4f * s.distance);
            EXPECT_NEAR(light.pdf(point, s.direction, s.distance, {0, -1, 0}), s.pdf, 1e-4f * s.pdf);
            if (by_solid_angle) { EXPECT_EQ(s.pdf, rectangle.solid_angle_pdf(point)); }
        }
    }
}

// Over the directions that hit the square from a point below it: sum pdf * dOmega over a fine grid of the square
// (dOmega = cos dA / d^2) must be 1.
double integrated_density(const Light& light, const Vec3f& point) {
    constexpr int n = 200;
    const float cell = 2 * kHalfSide / n;
    double integral = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vec3f q(-kHalfSide + (i + 0.5f) * cell, kHeight, -kHalfSide + (j + 0.5f) * cell);
            const Vec3f offset = q - point;
            const float d = length(offset);
            const Vec3f direction = offset / d;
            const double d_omega = std::abs(direction.y) * cell * cell / (d * d);
            integral += light.pdf(point, direction, d, {0, -1, 0}) * d_omega;
        }
    return integral;
}

TEST(AreaLight, SolidAngleDensityIntegratesToOne) {
    const TriangleMeshShape shape = square_light_shape();
    const RectangleShape rectangle = square_rectangle_shape();
    const TestEmitter material(false);
    EXPECT_NEAR(integrated_density(AreaLight(shape, material), {0.4f, -0.5f, 0.2f}), 1.0, 1e-4);
    EXPECT_NEAR(integrated_density(AreaLight(rectangle, material), {0.4f, -0.5f, 0.2f}), 1.0, 1e-4);
    EXPECT_NEAR(integrated_density(AreaLight(rectangle, material), {1.5f, 0.5f, -0.3f}), 1.0, 1e-4);
}

TEST(AreaLight, OneSidedEmitterIsDarkFromBehind) {
    const TriangleMeshShape shape = square_light_shape();
    const TestEmitter one_sided(false), two_sided(true);
    const AreaLight light(shape, one_sided), double_light(shape, two_sided);
    const Vec3f above(0.2f, 3.0f, -0.3f);
    for (uint32_t i = 0; i < 100; ++i) {
        const LightSample s = light.sample(above, u_sample(i));
        // Documented choice: the pdf stays the geometric density, the radiance is 0.
        EXPECT_GT(s.pdf, 0.0f);
        EXPECT_TRUE(s.radiance.is_black());
        EXPECT_EQ(double_light.sample(above, u_sample(i)).radiance, kRadiance);
        EXPECT_EQ(light.sample({0.2f, 0.0f, -0.3f}, u_sample(i)).radiance, kRadiance);
    }
    EXPECT_EQ(estimate_irradiance(light, above, {0, -1, 0}, 1000).mean, 0.0);
}

TEST(AreaLight, PowerIsPiTimesAreaTimesRadiance) {
    const TriangleMeshShape square = square_light_shape();
    const SphereShape sphere({{{0, 3, 0}, 0.5}});
    const TestEmitter one_sided(false), two_sided(true);
    EXPECT_NEAR(AreaLight(square, one_sided).power(), kPi * 4 * 2, 1e-4);
    EXPECT_NEAR(AreaLight(square, two_sided).power(), 2 * kPi * 4 * 2, 1e-4);
    EXPECT_NEAR(AreaLight(sphere, one_sided).power(), kPi * kPi * 2, 1e-4);
    EXPECT_FALSE(AreaLight(square, one_sided).is_infinite());
}

TEST(AreaLight, WorksWithTheEmissiveMaterialPlugin) {
    const TriangleMeshShape shape = square_light_shape();
    const testing::ParsedScene one_sided_json(R"({"type": "emissive", "radiance": [2, 1, 0.5]})");
    const testing::ParsedScene two_sided_json(R"({"type": "emissive", "radiance": [2, 1, 0.5], "two_sided": true})");
    const auto one_sided = material_registry().create(one_sided_json.root());
    const auto two_sided = material_registry().create(two_sided_json.root());
    const AreaLight light(shape, *one_sided), double_light(shape, *two_sided);
    EXPECT_NEAR(light.power(), kPi * 4 * 2, 1e-4);
    EXPECT_NEAR(double_light.power(), 2 * kPi * 4 * 2, 1e-4);
    EXPECT_EQ(light.sample({0, 0, 0}, {0.3f, 0.7f}).radiance, kRadiance);
    EXPECT_TRUE(light.sample({0, 3, 0}, {0.3f, 0.7f}).radiance.is_black());
    EXPECT_EQ(double_light.sample({0, 3, 0}, {0.3f, 0.7f}).radiance, kRadiance);
}

// A unit sphere placed as an oblate ellipsoid (semi-axes 0.5, 0.25, 0.5 about (0, 3, 0)): a placed shape's light.
// Its irradiance at the origin is π L times the share of cosine-weighted directions that hit it, counted here by
// intersecting those directions with the ellipsoid; sample() and pdf() agree; its power is π L times its area.
const Transform kEllipsoid = Transform::translate({0, 3, 0}) * Transform::scale({0.5, 0.25, 0.5});

// Whether the ray from the origin along `direction` meets the ellipsoid (the unit sphere in the placement's space).
bool meets_ellipsoid(const Vec3d& direction) {
    const Vec3d o = kEllipsoid.inverse_point(Vec3d{}), d = kEllipsoid.inverse_vector(direction);
    const double b = dot(o, d), c = dot(o, o) - 1;
    return b < 0 && b * b - dot(d, d) * c >= 0;
}

TEST(AreaLight, APlacedShapesLightIsTheTransformedSurfaces) {
    const SphereShape unit({{{0, 0, 0}, 1}});
    const TestEmitter material(false);
    const AreaLight light(unit, material, kEllipsoid);
    EXPECT_FALSE(light.is_delta());

    constexpr int n = 400000;
    int hits = 0;
    for (int i = 0; i < n; ++i) {  // cosine-weighted directions about +y
        const auto u = u_sample(std::uint32_t(i));
        const double r = std::sqrt(double(u[0])), phi = 2 * kPi * u[1];
        hits += meets_ellipsoid({r * std::cos(phi), std::sqrt(1 - r * r), r * std::sin(phi)});
    }
    const double share = double(hits) / n, share_error = std::sqrt(share * (1 - share) / n);
    const Estimate e = estimate_irradiance(light, {0, 0, 0}, {0, 1, 0}, 200000);
    EXPECT_NEAR(e.mean, kPi * kRadiance.r * share, 3 * std::hypot(e.standard_error, kPi * kRadiance.r * share_error));

    for (const Vec3f& point : {Vec3f(0, 0, 0), Vec3f(0.3f, -1, 2), Vec3f(-3, 1.2f, 0.5f)})
        for (std::uint32_t i = 0; i < 200; ++i) {
            const LightSample s = light.sample(point, u_sample(i));
            ASSERT_GT(s.pdf, 0.0f);
            const Vec3d on = Vec3d(point + s.direction * s.distance) - Vec3d{0, 3, 0};
            EXPECT_NEAR(on.x * on.x / 0.25 + on.y * on.y / 0.0625 + on.z * on.z / 0.25, 1, 1e-4);
            const Vec3f normal(normalize(Vec3d{on.x / 0.25, on.y / 0.0625, on.z / 0.25}));
            const float cos_light = std::abs(dot(normal, s.direction));
            EXPECT_NEAR(light.pdf(point, s.direction, s.distance, normal), s.pdf, (1e-4f + 1e-5f / cos_light) * s.pdf);
        }

    // An oblate spheroid of semi-axes a and c < a has area 2πa² (1 + (1 − e²) atanh(e) / e), e² = 1 − c²/a².
    const double a = 0.5, e2 = 1 - 0.25 * 0.25 / (a * a), eccentricity = std::sqrt(e2);
    const double area = 2 * kPi * a * a * (1 + (1 - e2) * std::atanh(eccentricity) / eccentricity);
    EXPECT_NEAR(light.power(), kPi * area * 2, 0.01 * kPi * area * 2);
}

}  // namespace
}  // namespace isotrace
