// Octree simplification of dual contouring: the mergeable QEF, the collapse's topology test, and what the
// simplified meshes guarantee (closed 2-manifolds, vertex error within the stated bound, fewer vertices as the
// tolerance rises, the same bytes for any thread count).
#include "geometry/polygonize/octree_simplification.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <random>

#include "geometry/polygonize/collapse_topology.h"
#include "geometry/polygonize/mesh_topology.h"
#include "geometry/polygonize/polygonize_field.h"
#include "geometry/polygonize/polygonize_test_support.h"

namespace isotrace {
namespace {

// The 27 signs of a node's children from a predicate on the points (x, y, z) ∈ {0, 1, 2}³.
template <typename Inside>
std::uint32_t grid(Inside inside) {
    std::uint32_t bits = 0;
    for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 3; ++x)
                if (inside(x, y, z)) bits |= 1u << (x + 3 * y + 9 * z);
    return bits;
}

TEST(Qef, MergedQefsEqualTheQefOfAllThePlanes) {
    std::mt19937 random(1);
    std::uniform_real_distribution<double> u(-1, 1);
    Qef all, first, second;
    for (int i = 0; i < 10; ++i) {
        const Vec3d p{3 + u(random), -2 + u(random), 5 + u(random)}, n(u(random), u(random), u(random));
        all.add(p, n);
        (i < 4 ? first : second).add(p, n);
    }
    Qef merged = first;
    merged.merge(second);
    for (int k = 0; k < 5; ++k) {
        const Vec3d x{3 + u(random), -2 + u(random), 5 + u(random)};
        EXPECT_NEAR(merged.error(x), all.error(x), 1e-12);
    }
    EXPECT_NEAR(length(merged.solve() - all.solve()), 0, 1e-12);
    EXPECT_NEAR(length(merged.mass_point() - all.mass_point()), 0, 1e-12);
    Qef empty;
    empty.merge(all);
    EXPECT_NEAR(length(empty.solve() - all.solve()), 0, 1e-12);
}

TEST(Qef, ErrorIsTheSumOfSquaredDistancesToThePlanes) {
    Qef qef;
    qef.add({1, 0, 0}, {2, 0, 0});  // x = 1 (the normal is normalised)
    qef.add({0, 2, 0}, {0, 1, 0});  // y = 2
    qef.add({0, 0, 0}, {0, 0, 0});  // no plane: a mass point only
    EXPECT_NEAR(qef.error({1, 2, 7}), 0, 1e-15);
    EXPECT_NEAR(qef.error({4, 0, 0}), 9 + 4, 1e-12);
}

TEST(CollapseTopology, APlaneThroughTheNodeCollapses) {
    EXPECT_TRUE(collapse_keeps_topology(grid([](int, int, int z) { return z == 0; })));
    EXPECT_TRUE(collapse_keeps_topology(grid([](int x, int y, int z) { return x + y + z <= 2; })));
    EXPECT_TRUE(collapse_keeps_topology(grid([](int x, int y, int z) { return x + y + z <= 1; })));  // a corner cut off
    // A bump through the centre of a node face is still one disc.
    EXPECT_TRUE(collapse_keeps_topology(grid([](int x, int y, int z) { return z == 0 || (x == 1 && y == 0 && z == 1); })));
}

TEST(CollapseTopology, ChangesTheCoarseCellCannotSeeAreRefused) {
    // Empty, full: no surface.
    EXPECT_FALSE(collapse_keeps_topology(0));
    EXPECT_FALSE(collapse_keeps_topology((1u << 27) - 1));
    // A bubble around the centre: the node's corners are all outside.
    EXPECT_FALSE(collapse_keeps_topology(grid([](int x, int y, int z) { return x == 1 && y == 1 && z == 1; })));
    // A bump reaching a node edge: the edge's midpoint differs from both its ends.
    EXPECT_FALSE(collapse_keeps_topology(grid([](int x, int y, int z) { return z == 0 || (x == 1 && y == 0 && z == 2); })));
    // A slab through the middle: two sheets, two cycles.
    EXPECT_FALSE(collapse_keeps_topology(grid([](int, int, int z) { return z == 1; })));
    // A closed loop in one face: its centre differs from its whole boundary.
    EXPECT_FALSE(collapse_keeps_topology(grid([](int x, int y, int z) { return z == 0 && !(x == 1 && y == 1); })));
    // Two opposite corners of the node: two discs.
    EXPECT_FALSE(collapse_keeps_topology(grid([](int x, int y, int z) { return x + y + z == 0 || x + y + z == 6; })));
    // An ambiguous face between two children (inside corners on a diagonal of the face x = 1, y, z ∈ [0, 1]).
    EXPECT_FALSE(collapse_keeps_topology(grid([](int x, int y, int z) {
        return x + y + z <= 1 || (x == 1 && y == 1 && z == 1);
    })));
}

// A tunnel through the node (a solid ring round its z axis): the node's surface is an annulus, not a disc.
TEST(CollapseTopology, ATunnelThroughTheNodeIsRefused) {
    EXPECT_FALSE(collapse_keeps_topology(grid([](int x, int y, int) { return !(x == 1 && y == 1); })));
}

Polygonization simplified(const ImplicitField& field, int depth, std::optional<double> tolerance) {
    PolygonizeOptions options;
    options.method = PolygonizeMethod::DualContouring;
    options.depth = depth;
    options.simplify = tolerance;
    return polygonize_field(field, options);
}

// The bound stated in docs/polygonize.md: a vertex lies within τ of the tangent plane at every crossing in its
// leaf, and within the leaf (diagonal D). On a sphere of radius R that puts it within τ + D²/(2(R − τ)) of the
// sphere. Measured here with D the diagonal of the coarsest leaf.
TEST(OctreeSimplification, VertexErrorStaysWithinTheToleranceBound) {
    const double radius = 1.0;
    const BallField ball({0.03, -0.02, 0.05}, radius);
    const double cell = 2 * radius * 1.04 / 64;  // depth 6
    for (const double tolerance : {1e-4, 1e-3, 1e-2, 3e-2}) {
        const Polygonization p = simplified(ball, 6, tolerance);
        const double diagonal = std::sqrt(3.0) * cell * double(1 << (6 - p.report.simplification.coarsest_level));
        const double bound = tolerance + diagonal * diagonal / (2 * (radius - tolerance));
        double worst = 0;
        for (const Vec3f& v : p.mesh.positions) worst = std::max(worst, std::abs(ball.value(Vec3d(v))));
        EXPECT_LE(worst, bound) << tolerance;
        EXPECT_GT(p.report.simplification.collapsed_nodes, 0u) << tolerance;
        std::printf("sphere depth 6, tolerance %g: %zu vertices, coarsest level %d, max |f| %.3g (bound %.3g)\n",
                    tolerance, p.mesh.positions.size(), p.report.simplification.coarsest_level, worst, bound);
    }
}

TEST(OctreeSimplification, SphereAndTorusKeepTheirGenusAndShrinkMonotonically) {
    const BallField ball({0.1, -0.05, 0.2}, 1.0);
    const TorusField torus({0.05, 0.1, -0.1}, 1.0, 0.35);
    for (const auto& [field, euler] : {std::pair<const ImplicitField*, long>{&ball, 2}, {&torus, 0}}) {
        std::size_t previous = simplified(*field, 5, std::nullopt).mesh.positions.size();
        for (const double tolerance : {0.0, 1e-3, 1e-2, 0.03, 0.1, 0.3}) {
            const Polygonization p = simplified(*field, 5, tolerance);
            SCOPED_TRACE("euler " + std::to_string(euler) + " tolerance " + std::to_string(tolerance));
            EXPECT_TRUE(is_closed_two_manifold(p.mesh));
            EXPECT_EQ(euler_characteristic(p.mesh), euler);
            EXPECT_EQ(connected_components(p.mesh), 1u);
            EXPECT_LE(p.mesh.positions.size(), previous);
            previous = p.mesh.positions.size();
        }
        EXPECT_LT(previous, 600u);
    }
}

TEST(OctreeSimplification, MeshesAreTheSameForAnyThreadCount) {
    const TorusField torus({0.05, 0.1, -0.1}, 1.0, 0.35);
    Polygonization one, many;
    {
        tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
        one = simplified(torus, 6, 0.01);
    }
    {
        tbb::global_control several(tbb::global_control::max_allowed_parallelism, 4);
        many = simplified(torus, 6, 0.01);
    }
    ASSERT_EQ(one.mesh.positions.size(), many.mesh.positions.size());
    ASSERT_EQ(one.mesh.triangles.size(), many.mesh.triangles.size());
    EXPECT_EQ(0, std::memcmp(one.mesh.positions.data(), many.mesh.positions.data(), one.mesh.positions.size() * sizeof(Vec3f)));
    EXPECT_EQ(0, std::memcmp(one.mesh.triangles.data(), many.mesh.triangles.data(),
                             one.mesh.triangles.size() * sizeof(one.mesh.triangles[0])));
}

TEST(OctreeSimplification, BadTolerancesAndMethodsAreRejected) {
    const BallField ball({0, 0, 0}, 1.0);
    for (const double bad : {-1e-3, double(NAN), double(INFINITY)}) {
        try {
            simplified(ball, 4, bad);
            FAIL() << bad;
        } catch (const std::invalid_argument& e) {
            EXPECT_EQ(std::string(e.what()).rfind("simplify: the tolerance must be", 0), 0u) << e.what();
        }
    }
    for (const PolygonizeMethod method : {PolygonizeMethod::MarchingCubes, PolygonizeMethod::SphericalDualContouring}) {
        PolygonizeOptions options;
        options.method = method;
        options.depth = 4;
        options.simplify = 0.01;
        try {
            polygonize_field(ball, options);
            FAIL() << int(method);
        } catch (const std::invalid_argument& e) {
            EXPECT_EQ(std::string(e.what()).rfind("simplify: only dual contouring", 0), 0u) << e.what();
        }
    }
}

}  // namespace
}  // namespace isotrace
