// Containers derived for functions given without one hold their analytic surfaces (a sphere, a torus, a sphere
// displaced by noise); functions whose surface is unbounded (a gyroid, a plane) get none.
#include "geometry/isosurface/derived_container.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/expression/expression_field.h"

namespace isotrace {
namespace {

std::optional<Container> derived(const std::string& function) {
    return derive_container(*compile_expression({function, {"scene.json", 3, 20}, "objects[0].shape.function"}, {}));
}

// Points (u, v) ∈ [0, 2π) × [0, π] of a sphere of radius r, or of a torus of radii R and r about the z axis.
Vec3d on_sphere(double r, double u, double v) {
    return {r * std::sin(v) * std::cos(u), r * std::sin(v) * std::sin(u), r * std::cos(v)};
}
Vec3d on_torus(double big, double r, double u, double v) {
    return {(big + r * std::cos(2 * v)) * std::cos(u), (big + r * std::cos(2 * v)) * std::sin(u), r * std::sin(2 * v)};
}

template <class Surface>
void expect_holds(const Container& container, Surface&& surface) {
    for (int i = 0; i <= 64; ++i)
        for (int j = 0; j <= 32; ++j) {
            const Vec3d p = surface(2 * std::numbers::pi * i / 64, std::numbers::pi * j / 32);
            ASSERT_LT(container.signed_distance(p), 0) << p.x << " " << p.y << " " << p.z;
        }
}

TEST(DerivedContainer, HoldsASphereATorusAndANoisySphere) {
    const auto sphere = derived("length(p) - 1");
    ASSERT_TRUE(sphere);
    expect_holds(*sphere, [](double u, double v) { return on_sphere(1, u, v); });
    EXPECT_LT(sphere->bounds().x.hi, 1.001);  // the faces moved in from the cube of half-size 2 that proves it

    const auto torus = derived("length(vec(length(vec(x, y, 0)) - 1, z, 0)) - 0.25");
    ASSERT_TRUE(torus);
    expect_holds(*torus, [](double u, double v) { return on_torus(1, 0.25, u, v); });

    // fbm lies within [−1, 1]: the surface lies between radii 0.95 and 1.05.
    const auto noisy = derived("length(p) - 1 + 0.05*fbm(8*p)");
    ASSERT_TRUE(noisy);
    expect_holds(*noisy, [](double u, double v) { return on_sphere(1.05, u, v); });
}

TEST(DerivedContainer, UnboundedSurfacesGetNone) {
    EXPECT_FALSE(derived("sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)"));
    EXPECT_FALSE(derived("z"));
    EXPECT_FALSE(derived("length(vec(x, y, 0)) - 1"));  // an infinite cylinder
}

// A small ball far from the origin: the cube reaches it, and is no larger than twice its reach.
TEST(DerivedContainer, ReachesAnOffsetBall) {
    const auto ball = derived("length(p - vec(100, 0, 0)) - 0.5");
    ASSERT_TRUE(ball);
    expect_holds(*ball, [](double u, double v) { return on_sphere(0.5, u, v) + Vec3d{100, 0, 0}; });
    EXPECT_LE(ball->bounds().x.hi, 100.501);
    EXPECT_GE(ball->bounds().x.lo, 99.499);
}

// A cube off the origin gets a box about itself (within the bisection's steps), not the cube about the origin.
TEST(DerivedContainer, FitsACubeOffTheOrigin) {
    const auto cube = derived("max(abs(x - 3), abs(y + 1), abs(z)) - 0.5");
    ASSERT_TRUE(cube);
    const IntervalBox& box = cube->bounds();
    const Interval expected[] = {{2.5, 3.5}, {-1.5, -0.5}, {-0.5, 0.5}};
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_LE(box[axis].lo, expected[axis].lo) << axis;
        EXPECT_GT(box[axis].lo, expected[axis].lo - 1e-6) << axis;
        EXPECT_GE(box[axis].hi, expected[axis].hi) << axis;
        EXPECT_LT(box[axis].hi, expected[axis].hi + 1e-6) << axis;
    }
}

}  // namespace
}  // namespace isotrace
