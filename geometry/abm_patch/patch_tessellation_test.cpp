// Tessellation: watertight across shared curves, within the tolerance of the surface, normals facing the front.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "geometry/abm_patch/abm_patch_test_support.h"
#include "geometry/abm_patch/patch_tessellation.h"
#include "geometry/mesh/closest_triangle_point.h"

namespace isotrace {
namespace {

using abm_test::bezier;
using abm_test::curved_loop;
using abm_test::curved_tetrahedron;

// Every edge of the mesh, keyed by the positions of its ends, must be used exactly twice, once in each direction.
void expect_closed_by_position(const TriangleMeshData& mesh) {
    EXPECT_EQ(abm_test::open_edges(mesh), 0);
}

TEST(PatchTessellation, PatchesSharingCurvesAreWatertight) {
    for (bool polygon : {false, true}) {
        const std::vector<AbmPatch> patches = curved_tetrahedron(polygon);
        PatchTessellationReport report;
        TriangleMeshData mesh = tessellate_patches(patches, {.tolerance = 2e-3}, &report);
        EXPECT_LE(report.largest_deviation, 2e-3);
        EXPECT_FALSE(report.capped);
        mesh.remove_degenerate_triangles();
        expect_closed_by_position(mesh);
        // Outward: the enclosed volume is positive.
        double volume = 0;
        for (const auto& t : mesh.triangles)
            volume += dot(Vec3d(mesh.positions[t[0]]), cross(Vec3d(mesh.positions[t[1]]), Vec3d(mesh.positions[t[2]]))) / 6;
        EXPECT_GT(volume, 0) << (polygon ? "polygon" : "right triangle");
    }
}

TEST(PatchTessellation, EachVertexsUvIsTheDomainPointItWasEvaluatedAt) {
    for (bool polygon : {false, true}) {
        const AbmPatch patch = curved_tetrahedron(polygon)[0];
        const TriangleMeshData mesh = tessellate_patches({patch}, {.tolerance = 1e-3});
        ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const Vec3d surface = patch({mesh.uvs[i][0], mesh.uvs[i][1]});
            EXPECT_NEAR(length(surface - Vec3d(mesh.positions[i])), 0, 1e-5) << i << (polygon ? " polygon" : "");
        }
    }
}

TEST(PatchTessellation, UniformSegmentsAreWatertightToo) {
    TriangleMeshData mesh = tessellate_patches(curved_tetrahedron(false), {.segments = 5});
    EXPECT_EQ(mesh.triangles.size(), 4u * 3 * 5 * (1 + 2 * 4));  // per sector: a fan and 4 bands of 2 per column
    mesh.remove_degenerate_triangles();
    expect_closed_by_position(mesh);
}

TEST(PatchTessellation, TheSurfaceLiesWithinTheToleranceOfTheMesh) {
    for (int n : {3, 4, 5, 8}) {
        const AbmPatch patch(n == 3 ? right_triangle_domain() : n == 4 ? unit_square_domain() : regular_polygon_domain(n),
                             curved_loop(n), 1.5);
        for (double tolerance : {1e-2, 1e-3}) {
            const TriangleMeshData mesh = tessellate_patches({patch}, {.tolerance = tolerance});
            const ClosestPointQuery query(mesh);
            std::mt19937 random(n);
            std::uniform_real_distribution<double> unit(0, 1);
            const DomainPoint c = patch.domain().centre();
            double worst = 0;
            for (int k = 0; k < 2000; ++k) {
                const DomainPoint edge = patch.domain().on_side(k % n, unit(random));
                const double r = std::sqrt(unit(random));
                worst = std::max(worst, query.nearest(patch({c.x + r * (edge.x - c.x), c.y + r * (edge.y - c.y)}), INFINITY).distance);
            }
            EXPECT_LE(worst, tolerance) << n << " sides";
        }
    }
}

TEST(PatchTessellation, FinerToleranceGivesMoreTrianglesAndNormalsFaceTheFront) {
    const AbmPatch patch(regular_polygon_domain(5), curved_loop(5));
    const TriangleMeshData coarse = tessellate_patches({patch}, {.tolerance = 1e-2});
    const TriangleMeshData fine = tessellate_patches({patch}, {.tolerance = 1e-3});
    EXPECT_GT(fine.triangles.size(), 2 * coarse.triangles.size());
    ASSERT_EQ(fine.normals.size(), fine.positions.size());
    for (const auto& t : fine.triangles) {
        const Vec3f face = cross(fine.positions[t[1]] - fine.positions[t[0]], fine.positions[t[2]] - fine.positions[t[0]]);
        if (!(length(face) > 0)) continue;
        for (std::uint32_t i : t) {
            // The patch is a cone at its corners (abm_patch.h): the faces there turn farther from the normal.
            const bool corner = std::any_of(patch.sides().begin(), patch.sides().end(),
                                            [&](const PatchSide& s) { return Vec3f(s.start()) == fine.positions[i]; });
            EXPECT_GT(dot(fine.normals[i], normalize(face)), corner ? 0.0f : 0.5f);
        }
    }
}

// A patch whose curves lie on one line folds at every vertex: each takes the normal of its triangles, found in
// one pass over them. A search of all triangles per vertex took 10¹² steps here: CTest's time limit catches it.
TEST(PatchTessellation, APatchFoldedEverywhereTakesItsNormalsInOnePass) {
    using abm_test::side;
    const Vec3d a{0, 0, 0}, b{1, 0, 0}, c{2, 0, 0};
    const AbmPatch flat(right_triangle_domain(), {side(bezier({a, b})), side(bezier({b, c})), side(bezier({c, a}))});
    const TriangleMeshData mesh = tessellate_patches({flat}, {.segments = 512});
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (const Vec3f& n : mesh.normals) ASSERT_EQ(n, Vec3f(0, 0, 1));  // no triangle has an area
}

TEST(PatchTessellation, RejectsBadOptions) {
    const std::vector<AbmPatch> patches = curved_tetrahedron(false);
    EXPECT_THROW(tessellate_patches(patches, {.tolerance = 0}), std::invalid_argument);
    EXPECT_THROW(tessellate_patches(patches, {.max_segments = 0}), std::invalid_argument);
    EXPECT_THROW(tessellate_patches(patches, {.segments = 5000}), std::invalid_argument);
}

}  // namespace
}  // namespace isotrace
