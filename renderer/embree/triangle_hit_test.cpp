// A triangle hit solved again: exact answers where the arithmetic is exact, the same point from both sides of the
// equation elsewhere (in double and in float), Embree's conventions (u and v of the second and third corners,
// Ng = e1 × e2), and the cases that cannot be solved.
#include "renderer/embree/triangle_hit.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace isotrace {
namespace {

TEST(TriangleHit, AxisAlignedRayGetsExactDistanceAndBarycentrics) {
    TriangleSolution<double> s;
    ASSERT_TRUE(solve_triangle_hit<double>({0.25, 0.5, 5}, {0, 0, -2}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, s));
    EXPECT_EQ(s.t, 2.0);
    EXPECT_EQ(s.u, 0.25);
    EXPECT_EQ(s.v, 0.5);
    EXPECT_EQ(s.normal.x, 0.0);
    EXPECT_EQ(s.normal.y, 0.0);
    EXPECT_EQ(s.normal.z, 1.0);  // (p1 − p0) × (p2 − p0): Embree's Ng
}

// Random triangles and rays aimed at a random point of each: the solved point is on the ray and on the triangle,
// and its barycentrics are the aimed point's, to the precision of Real.
template <class Real>
void expect_solutions_on_ray_and_triangle(double tolerance) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-3, 3), weight(0, 1);
    int solved = 0;
    for (int i = 0; i < 1000; ++i) {
        const Vec3d p0{coordinate(random), coordinate(random), coordinate(random)};
        const Vec3d p1{coordinate(random), coordinate(random), coordinate(random)};
        const Vec3d p2{coordinate(random), coordinate(random), coordinate(random)};
        double a = weight(random), b = weight(random);
        if (a + b > 1) a = 1 - a, b = 1 - b;
        const Vec3d target = p0 + (p1 - p0) * a + (p2 - p0) * b;
        const Vec3d origin{coordinate(random) * 3, coordinate(random) * 3, coordinate(random) * 3};
        const Vec3d direction = (target - origin) * (0.5 + weight(random));
        // Nearly edge-on triangles put the barycentrics' rounding beyond any fixed tolerance: left out.
        if (std::abs(dot(normalize(cross(p1 - p0, p2 - p0)), normalize(direction))) < 0.05) continue;
        TriangleSolution<Real> s;
        ASSERT_TRUE(solve_triangle_hit(Vec3T<Real>(origin), Vec3T<Real>(direction), Vec3T<Real>(p0), Vec3T<Real>(p1),
                                       Vec3T<Real>(p2), s));
        ++solved;
        const Vec3d on_ray = origin + direction * double(s.t);
        const Vec3d on_triangle = p0 + (p1 - p0) * double(s.u) + (p2 - p0) * double(s.v);
        EXPECT_LT(length(on_ray - on_triangle), tolerance * (length(origin) + length(target) + 1)) << i;
        EXPECT_NEAR(s.u, a, 100 * tolerance) << i;
        EXPECT_NEAR(s.v, b, 100 * tolerance) << i;
    }
    EXPECT_GT(solved, 900);
}

TEST(TriangleHit, SolvedPointLiesOnTheRayAndInTheTriangle) {
    expect_solutions_on_ray_and_triangle<double>(1e-12);
    expect_solutions_on_ray_and_triangle<float>(1e-4);
}

TEST(TriangleHit, RayInThePlaneOrDegenerateTriangleIsNotSolved) {
    TriangleSolution<double> s;
    EXPECT_FALSE(solve_triangle_hit<double>({0, 0, 1}, {1, 0, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, s));
    EXPECT_FALSE(solve_triangle_hit<double>({0, 0, 5}, {0, 0, -1}, {0, 0, 1}, {1, 0, 1}, {2, 0, 1}, s));
}

TEST(TriangleHit, ResolvedHitReplacesEmbreesNumbersAndStaysInTheTriangle) {
    const std::vector<Vec3f> positions = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    const std::vector<std::array<std::uint32_t, 3>> triangles = {{0, 1, 2}};
    const TriangleView mesh{positions, triangles};
    RTCHit hit{};
    hit.primID = 0;
    hit.u = hit.v = 0.3f;  // Embree's rounding, to be replaced
    float t = 1.9999999f;
    resolve_triangle_hit(mesh, {0.25f, 0.5f, 5}, {0, 0, -2}, hit, t);
    EXPECT_EQ(t, 2.0f);
    EXPECT_EQ(hit.u, 0.25f);
    EXPECT_EQ(hit.v, 0.5f);
    EXPECT_EQ(hit.Ng_z, 1.0f);
    // A hit a hair outside the edge u + v = 1 (Embree's float test took it) is put on the edge.
    resolve_triangle_hit(mesh, {0.5f + 1e-6f, 0.5f + 1e-6f, 5}, {0, 0, -2}, hit, t);
    EXPECT_LE(double(hit.u) + double(hit.v), 1.0 + 1e-7);
    EXPECT_NEAR(hit.u, 0.5f, 1e-6f);
    // A hit a hair outside the edge v = 0.
    resolve_triangle_hit(mesh, {0.5f, -1e-6f, 5}, {0, 0, -2}, hit, t);
    EXPECT_EQ(hit.v, 0.0f);
    EXPECT_EQ(hit.u, 0.5f);
    // A ray in the triangle's plane cannot be solved: Embree's numbers stay.
    hit.u = 0.125f, hit.v = 0.25f, t = 3;
    resolve_triangle_hit(mesh, {0, 0, 1}, {1, 0, 0}, hit, t);
    EXPECT_EQ(t, 3.0f);
    EXPECT_EQ(hit.u, 0.125f);
    EXPECT_EQ(hit.v, 0.25f);
}

}  // namespace
}  // namespace isotrace
