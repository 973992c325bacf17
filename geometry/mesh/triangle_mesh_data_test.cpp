#include "geometry/mesh/triangle_mesh_data.h"

#include <gtest/gtest.h>

#include <limits>

#include "geometry/mesh/mesh_test_support.h"

namespace isotrace {
namespace {

using mesh_test::input_error_message;

TriangleMeshData one_triangle() {
    TriangleMeshData mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}};
    return mesh;
}

TEST(TriangleMeshData, ValidMeshPasses) {
    TriangleMeshData mesh = one_triangle();
    mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    mesh.uvs = {{0, 0}, {1, 0}, {0, 1}};
    EXPECT_NO_THROW(mesh.validate("m.ply"));
}

TEST(TriangleMeshData, ValidateNamesFileAndProblem) {
    TriangleMeshData out_of_range = one_triangle();
    out_of_range.triangles.push_back({0, 2, 3});
    EXPECT_EQ(input_error_message([&] { out_of_range.validate("m.ply"); }),
              "m.ply: triangle 1: vertex index 3 out of range (vertex count 3)");

    TriangleMeshData not_finite = one_triangle();
    not_finite.positions[2].y = std::numeric_limits<float>::infinity();
    EXPECT_EQ(input_error_message([&] { not_finite.validate("m.ply"); }).rfind("m.ply: vertex 2: position is not finite", 0),
              0u);

    TriangleMeshData nan_normal = one_triangle();
    nan_normal.normals = {{0, 0, 1}, {0, 0, std::numeric_limits<float>::quiet_NaN()}, {0, 0, 1}};
    EXPECT_EQ(input_error_message([&] { nan_normal.validate("m.ply"); }).rfind("m.ply: vertex 1: normal is not finite", 0),
              0u);

    TriangleMeshData too_few_uvs = one_triangle();
    too_few_uvs.uvs = {{0, 0}};
    EXPECT_EQ(input_error_message([&] { too_few_uvs.validate("m.ply"); }),
              "m.ply: uvs: 1 values for 3 positions (need none or one per position)");

    EXPECT_EQ(input_error_message([&] { TriangleMeshData().validate("m.ply"); }), "m.ply: mesh has no triangles");
}

TEST(TriangleMeshData, RemovesOnlyZeroAreaTriangles) {
    TriangleMeshData mesh = one_triangle();
    mesh.positions.push_back({2, 0, 0});
    mesh.positions.push_back({1e-20f, 0, 0});
    mesh.triangles = {{0, 1, 2}, {0, 0, 2}, {0, 1, 3}, {0, 2, 1}, {0, 4, 2}};
    EXPECT_EQ(mesh.remove_degenerate_triangles(), 2u);  // a repeated corner, and three corners on one line
    // The tiny triangle {0, 4, 2} has area 5e-21, which single precision would round to zero.
    EXPECT_EQ(mesh.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}, {0, 2, 1}, {0, 4, 2}}));
    EXPECT_EQ(mesh.positions.size(), 5u);
}

TEST(TriangleMeshData, BoundsCoverAllPositions) {
    TriangleMeshData mesh = one_triangle();
    mesh.positions.push_back({-1, 2, -3});
    const MeshBounds box = mesh.bounds();
    EXPECT_EQ(box.min, Vec3f(-1, 0, -3));
    EXPECT_EQ(box.max, Vec3f(1, 2, 0));
    const MeshBounds empty = TriangleMeshData().bounds();
    EXPECT_GT(empty.min.x, empty.max.x);
}

}  // namespace
}  // namespace isotrace
