// Bézier patch files: evaluation against closed forms, welded tessellation, Newell's teapot, malformed files.
#include "geometry/mesh/bezier_patches.h"

#include <gtest/gtest.h>

#include "geometry/mesh/mesh_file.h"
#include "geometry/mesh/mesh_test_support.h"

namespace isotrace {
namespace {

using mesh_test::input_error_message;
using mesh_test::ScratchDirectory;

// A bicubic patch over [0,1]² whose control heights make z = u·v (bilinear precision of Bézier patches).
BezierPatch saddle() {
    BezierPatch patch;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3; ++j) patch.control_points.push_back({i / 3.0, j / 3.0, (i / 3.0) * (j / 3.0)});
    return patch;
}

TEST(BezierPatches, EvaluatesPositionAndPartialDerivatives) {
    const BezierPatch patch = saddle();
    for (double u : {0.0, 0.3, 1.0})
        for (double v : {0.0, 0.6, 1.0}) {
            const BezierPatch::Sample s = patch.evaluate(u, v);
            EXPECT_NEAR(length(s.position - Vec3d(u, v, u * v)), 0, 1e-14);
            EXPECT_NEAR(length(s.d_u - Vec3d(1, 0, v)), 0, 1e-13);
            EXPECT_NEAR(length(s.d_v - Vec3d(0, 1, u)), 0, 1e-13);
        }
}

TEST(BezierPatches, NeighbouringPatchesAreWeldedAlongTheirCommonEdge) {
    BezierPatch right = saddle();
    for (Vec3d& p : right.control_points) p = Vec3d(p.x + 1, p.y, p.y);  // continues along x, z = v at u = 0
    BezierPatch left = saddle();
    for (Vec3d& p : left.control_points) p.z = p.y * (p.x);                // z = v at u = 1
    const TriangleMeshData mesh = tessellate_bezier_patches({left, right}, 4);
    EXPECT_EQ(mesh.positions.size(), 9u * 5u);  // the shared column of 5 vertices appears once
    EXPECT_EQ(mesh.triangles.size(), 2u * 2u * 16u);
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
}

TEST(BezierPatches, TessellatesNewellsTeapot) {
    MemoryBudget memory;
    const std::vector<BezierPatch> patches = load_bezier_patches(ISOTRACE_SCENES_DIR "/data/teapot.bpt", memory);
    ASSERT_EQ(patches.size(), 28u);
    const TriangleMeshData teapot = load_mesh_file(ISOTRACE_SCENES_DIR "/data/teapot.bpt", memory);
    const MeshBounds b = teapot.bounds();
    // Extents that patch corners reach (corners are interpolated): the handle's x = −3, the knob z = 3.15, the
    // base z = 0.15, the body's widest y = 2. The spout's tip lies inside its control points' hull.
    EXPECT_NEAR(b.min.x, -3, 1e-4);
    EXPECT_GT(b.max.x, 3.4);
    EXPECT_LT(b.max.x, 3.525);
    EXPECT_NEAR(b.min.z, 0.15, 1e-6);
    EXPECT_NEAR(b.max.z, 3.15, 1e-6);
    EXPECT_NEAR(b.max.y, 2, 1e-4);
    bool has_rim_corner = false;  // the first control point of the first patch
    for (const Vec3f& p : teapot.positions) has_rim_corner |= p == Vec3f(1.4f, 0.0f, 2.4f);
    EXPECT_TRUE(has_rim_corner);
    for (const Vec3f& n : teapot.normals) EXPECT_NEAR(length(Vec3d(n)), 1, 1e-5);
}

TEST(BezierPatches, MalformedFilesNameTheLine) {
    MemoryBudget memory;
    ScratchDirectory scratch;
    const std::string short_file = scratch.write("short.bpt", "1\n3 3\n0 0 0\n");
    EXPECT_EQ(input_error_message([&] { load_bezier_patches(short_file, memory); }), short_file + ":4: unexpected end of file");
    const std::string bad_number = scratch.write("nan.bpt", "1\n1 1\n0 0 0\n1 0 nan\n");
    EXPECT_EQ(input_error_message([&] { load_bezier_patches(bad_number, memory); }), bad_number + ":4: 'nan' is not a finite number");
    const std::string bad_degree = scratch.write("degree.bpt", "1\n0 3\n");
    EXPECT_EQ(input_error_message([&] { load_bezier_patches(bad_degree, memory); }),
              bad_degree + ":2: a patch degree must be an integer in [1, 16]");
    const std::string bad_count = scratch.write("count.bpt", "2.5\n");
    EXPECT_EQ(input_error_message([&] { load_bezier_patches(bad_count, memory); }),
              bad_count + ":1: the patch count must be an integer in [1, 100000]");
}

// 100,000 patches ran minutes to 8.7 GB under a 1 GB limit: the patches and their tessellation are charged first.
TEST(BezierPatches, ATessellationBeyondTheBudgetIsRefusedWithTheFigureBeforeItIsMade) {
    ScratchDirectory scratch;
    std::string text = "2000\n";
    for (int p = 0; p < 2000; ++p) text += "1 1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n";
    const std::string path = scratch.write("many.bpt", text);
    MemoryBudget memory(std::uint64_t(64) << 20);
    EXPECT_EQ(input_error_message([&] { load_mesh_file(path, memory); }),
              path + ": a tessellation of 2000 Bézier patches into 1024000 triangles needs about 236 MB (on top of 256 kB "
                     "already needed), more than the memory limit of 67.1 MB (--max-memory; the default is 80 % of "
                     "physical memory)");
    EXPECT_LT(memory.charged_bytes(), std::uint64_t(1) << 20);  // the patches themselves
}

}  // namespace
}  // namespace isotrace
