#include "geometry/mesh/mesh_quality.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace isotrace {
namespace {

// Two triangles sharing the edge 1–2 in the z = 0 plane, both facing +z.
TriangleMeshData square() {
    TriangleMeshData mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
    return mesh;
}

TEST(MeshQuality, UnchangedMeshIsClean) {
    const MeshQuality q = measure_mesh_quality(square(), square());
    EXPECT_EQ(q.flipped_faces, 0u);
    EXPECT_DOUBLE_EQ(q.max_edge_stretch, 1);
    EXPECT_EQ(q.stretched_edges, 0u);
    EXPECT_EQ(q.crossing_edges, 0u);
}

TEST(MeshQuality, CountsAFaceTurnedOverAndTheStretch) {
    TriangleMeshData moved = square();
    moved.positions[3] = {-2, -2, 0};  // drags the second triangle across the shared edge: it now faces −z
    const MeshQuality q = measure_mesh_quality(square(), moved);
    EXPECT_EQ(q.flipped_faces, 1u);
    EXPECT_NEAR(q.max_edge_stretch, std::sqrt(9.0 + 4.0), 1e-6);  // edge 1–3 from length 1 to √13
    EXPECT_EQ(q.stretched_edges, 2u);                              // 1–3 and 3–2
}

TEST(MeshQuality, CountsEdgesPiercingAnotherTriangle) {
    TriangleMeshData before = square();
    before.positions.push_back({0.3, 0.3, 1});
    before.positions.push_back({0.4, 0.3, 2});
    before.positions.push_back({0.3, 0.4, 2});
    before.triangles.push_back({4, 5, 6});  // above the square, apart
    TriangleMeshData after = before;
    after.positions[4] = {0.3, 0.3, -1};  // its edges 4–5 and 6–4 now pass through the square's first triangle
    const MeshQuality q = measure_mesh_quality(before, after);
    EXPECT_EQ(q.input_crossing_edges, 0u);
    EXPECT_EQ(q.crossing_edges, 2u);
    EXPECT_NE(describe(q).find("2 self-intersecting edges (input 0)"), std::string::npos) << describe(q);
}

TEST(MeshQuality, RefusesMeshesOfDifferentTriangles) {
    TriangleMeshData other = square();
    other.triangles.pop_back();
    EXPECT_THROW(measure_mesh_quality(square(), other), std::invalid_argument);
}

}  // namespace
}  // namespace isotrace
