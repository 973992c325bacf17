// Surface sampling of triangle meshes (area lights), after a real bake by RenderScene with a mirroring,
// scaling transform: triangles are chosen in proportion to their area (chi-square), points are uniform inside
// a triangle (chi-square on barycentrics, for triangles in the middle of the area table so that the reuse of
// u[0] is exercised), pdf_area * area = 1, and the normal is the geometric normal a ray hit reports.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/mesh/triangle_mesh_shape.h"
#include "renderer/sampling/independent_sampler.h"
#include "renderer/scene/render_scene.h"
#include "tests/support/chi_square.h"

namespace isotrace {
namespace {

// Five separated triangles of different sizes and orientations (x ranges do not overlap).
TriangleMeshData test_mesh() {
    TriangleMeshData mesh;
    mesh.positions = {{0, 0, 0},  {1, 0, 0},    {0, 1, 0},           // 0: area 0.5, +z
                      {2, 0, 0},  {2, 0, 2},    {5, 0, 0},           // 1: area 3, +y
                      {6, 0, 0},  {6, 2, 0},    {6, 0, 1},           // 2: area 1, +x
                      {8, 0, 0},  {8.2f, 0, 0}, {8, 0, 0.1f},        // 3: area 0.01, -y
                      {10, 0, 0}, {11, 1, 1},   {10, 2, 0}};         // 4: area sqrt(2), slanted
    mesh.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}, {12, 13, 14}};
    return mesh;
}

// Mirrors x (so bake() swaps the winding), scales by 1.5, rotates and moves.
Transform test_transform() {
    return Transform::translate({0.5, -1, 2}) * Transform::rotate({1, 2, 3}, 40) * Transform::scale({-1.5, 1.5, 1.5});
}

struct BakedMesh {
    std::unique_ptr<RenderScene> scene;
    const Shape* shape = nullptr;
    std::vector<std::array<Vec3d, 3>> triangles;  // world-space corners, in the original order
};

BakedMesh bake_test_mesh() {
    BakedMesh result;
    const TriangleMeshData mesh = test_mesh();
    const Transform to_world = test_transform();
    for (const auto& t : mesh.triangles)
        result.triangles.push_back({to_world.point(Vec3d(mesh.positions[t[0]])),
                                    to_world.point(Vec3d(mesh.positions[t[1]])),
                                    to_world.point(Vec3d(mesh.positions[t[2]]))});
    result.scene = std::make_unique<RenderScene>();
    SceneObject object;
    object.shape = std::make_unique<TriangleMeshShape>(mesh);
    object.to_world = to_world;
    result.scene->add_object(std::move(object));
    result.scene->commit();
    result.shape = result.scene->objects()[0].shape.get();
    return result;
}

double area(const std::array<Vec3d, 3>& t) { return 0.5 * length(cross(t[1] - t[0], t[2] - t[0])); }

// Barycentrics (b1, b2) of p in t when p lies on it (within a tolerance), else nothing.
std::optional<std::array<double, 2>> barycentrics(const std::array<Vec3d, 3>& t, const Vec3d& p) {
    const Vec3d e1 = t[1] - t[0], e2 = t[2] - t[0], n = cross(e1, e2);
    const double n2 = dot(n, n);
    const Vec3d d = p - t[0];
    if (std::abs(dot(d, n)) / std::sqrt(n2) > 1e-4) return std::nullopt;
    const double b1 = dot(cross(d, e2), n) / n2, b2 = dot(cross(e1, d), n) / n2;
    if (b1 < -1e-4 || b2 < -1e-4 || b1 + b2 > 1 + 1e-4) return std::nullopt;
    return std::array<double, 2>{b1, b2};
}

std::array<float, 2> u_sample(uint32_t i) {
    static const IndependentSampler sampler(31);
    return {sampler.sample({i, 0, 0}, 0), sampler.sample({i, 0, 0}, 1)};
}

TEST(TriangleMeshSampling, AreaAndPdf) {
    const BakedMesh baked = bake_test_mesh();
    ASSERT_TRUE(baked.shape->supports_surface_sampling());
    double total = 0;
    for (const auto& t : baked.triangles) total += area(t);
    EXPECT_NEAR(total, 2.25 * (0.5 + 3 + 1 + 0.01 + std::sqrt(2.0)), 1e-4);
    EXPECT_NEAR(baked.shape->surface_area(), total, 1e-5 * total);
    for (uint32_t i = 0; i < 100; ++i)
        EXPECT_NEAR(baked.shape->sample_surface(u_sample(i)).pdf_area * baked.shape->surface_area(), 1.0, 1e-6);
}

TEST(TriangleMeshSampling, TrianglesAreChosenInProportionToTheirArea) {
    const BakedMesh baked = bake_test_mesh();
    constexpr uint32_t samples = 100000;
    std::vector<double> observed(baked.triangles.size(), 0), expected;
    for (const auto& t : baked.triangles) expected.push_back(samples * area(t) / baked.shape->surface_area());
    for (uint32_t i = 0; i < samples; ++i) {
        const Vec3d p(baked.shape->sample_surface(u_sample(i)).position);
        int found = -1;
        for (std::size_t k = 0; k < baked.triangles.size(); ++k)
            if (barycentrics(baked.triangles[k], p)) found = int(k);
        ASSERT_GE(found, 0) << "sample " << i << " is on no triangle";
        observed[std::size_t(found)] += 1;
    }
    EXPECT_GT(test_support::chi_square_test(observed, expected).p_value, 0.01);
}

TEST(TriangleMeshSampling, PointsAreUniformInsideATriangle) {
    const BakedMesh baked = bake_test_mesh();
    constexpr uint32_t samples = 200000;
    for (std::size_t k : {std::size_t(1), std::size_t(4)}) {  // middle and last entries of the area table
        std::vector<std::array<double, 2>> points;
        for (uint32_t i = 0; i < samples; ++i)
            if (auto b = barycentrics(baked.triangles[k], Vec3d(baked.shape->sample_surface(u_sample(i)).position)))
                points.push_back(*b);
        ASSERT_GT(points.size(), 20000u);
        const test_support::Grid2D grid{0, 1, 0, 1, 10, 10};
        const auto result = test_support::chi_square_test_2d(
            grid, points.size(), [&](std::size_t i) { return test_support::Point2{points[i][0], points[i][1]}; },
            [](double b1, double b2) { return b1 + b2 < 1 ? 2.0 : 0.0; });
        EXPECT_GT(result.p_value, 0.01) << "triangle " << k << ": statistic " << result.statistic;
    }
}

TEST(TriangleMeshSampling, NormalsAreTheGeometricNormalsOfHits) {
    const BakedMesh baked = bake_test_mesh();
    for (uint32_t i = 0; i < 500; ++i) {
        const SurfaceSample s = baked.shape->sample_surface(u_sample(i));
        ASSERT_NEAR(length(s.normal), 1.0f, 1e-5f);
        for (float side : {1.0f, -1.0f}) {  // from the front and from the back: the normal is not flipped
            Ray ray;
            ray.origin = s.position + s.normal * (0.25f * side);
            ray.direction = s.normal * -side;
            ray.t_far = 1;
            const auto hit = baked.scene->intersect(ray, RayKind::Camera);
            ASSERT_TRUE(hit) << "sample " << i;
            EXPECT_NEAR(hit->t, 0.25f, 1e-4f);
            EXPECT_NEAR(dot(hit->geometric_normal, s.normal), 1.0f, 1e-5f) << "sample " << i;
        }
    }
}

TEST(TriangleMeshSampling, BakeWithoutMirrorKeepsTheCounterClockwiseFront) {
    TriangleMeshData mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}};
    TriangleMeshShape shape(mesh);
    EXPECT_NEAR(shape.surface_area(), 0.5f, 1e-7f);
    EXPECT_EQ(shape.sample_surface({0.3f, 0.6f}).normal, Vec3f(0, 0, 1));
    shape.bake(Transform::scale({2, 2, 2}));
    EXPECT_NEAR(shape.surface_area(), 2.0f, 1e-6f);
    shape.bake(Transform::scale({1, 1, -1}));  // mirrored: the front is the mirrored normal, -z
    EXPECT_EQ(shape.sample_surface({0.3f, 0.6f}).normal, Vec3f(0, 0, -1));
}

}  // namespace
}  // namespace isotrace
