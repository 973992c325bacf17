// The implicit-field contract, checked for every shape that offers a field: the sign agrees with the shape's
// own inside test (Solid::inside_spans, an independent ray-classification oracle), the gradient agrees with
// finite differences, may_reach_surface never denies a sign change it should see, and every polygoniser closes
// the surface.
#include <gtest/gtest.h>

#include <random>

#include "geometry/box/box_shape.h"
#include "geometry/csg/csg_shape.h"
#include "geometry/implicit/blob_group_shape.h"
#include "geometry/mesh/triangle_mesh_shape.h"
#include "geometry/polygonize/mesh_topology.h"
#include "geometry/polygonize/polygonize_field.h"
#include "geometry/polygonize/polygonize_test_support.h"
#include "geometry/sphere/sphere_shape.h"
#include "geometry/superquadric/superquadric_shape.h"
#include "geometry/superquadric/superquadric_test_support.h"
#include "renderer/embree/embree_device.h"

namespace isotrace {
namespace {

std::unique_ptr<Shape> box() {
    auto shape = std::make_unique<BoxShape>(Vec3d{0.1, -0.2, 0.05}, Vec3d{0.8, 0.5, 0.6});
    shape->bake(Transform::rotate({1, 2, 3}, 25));
    return shape;
}

std::unique_ptr<Shape> spheres() {
    return std::make_unique<SphereShape>(std::vector<Sphere>{{{0, 0, 0}, 0.8}, {{0.7, 0.2, 0.1}, 0.5}});
}

std::unique_ptr<Shape> csg() {
    std::vector<CsgChild> children;
    children.push_back({box(), Transform(), {}});
    children.push_back({spheres(), Transform::translate({0.6, 0.3, 0.4}), {}});
    return std::make_unique<CsgShape>(CsgOperation::Difference, std::move(children));
}

std::unique_ptr<Shape> superquadric() {
    std::mt19937 random(7);
    const Vec3d radii(0.7, 0.5, 0.9);
    std::vector<Superquadric> set;
    set.push_back(superquadric_test::make_superquadric(radii, 0.6, 1.4, superquadric_test::random_deformations(random, radii)));
    return std::make_unique<SuperquadricShape>(std::move(set));
}

std::unique_ptr<Shape> blobs() {
    OrientedBox cube;
    cube.centre = {-0.5, 0.2, 0.4};
    cube.half_size = {0.3, 0.2, 0.25};
    std::vector<Metacube> elements = {Metacube::metaball({0, 0, 0}, 1.0, 1.0), Metacube::metaball({0.8, 0.3, 0}, 0.8, 1.0),
                                      Metacube(cube, 0.6, 1.0)};
    return std::make_unique<BlobGroupShape>(BlobGroup(std::move(elements), make_field_function("kim", 4.0), 0.5));
}

// A closed mesh: a ball polygonised by marching cubes.
std::unique_ptr<Shape> mesh() {
    const BallField ball({0.05, 0, -0.1}, 0.9);
    PolygonizeOptions options;
    options.method = PolygonizeMethod::MarchingCubes;
    options.depth = 4;
    TriangleMeshData data = polygonize_field(ball, options).mesh;
    data.normals.clear();
    return std::make_unique<TriangleMeshShape>(std::move(data));
}

struct Case {
    const char* name;
    std::unique_ptr<Shape> (*make)();
};
const Case kCases[] = {{"box", box},   {"sphere", spheres}, {"csg", csg},
                       {"superquadric", superquadric}, {"blobs", blobs}, {"triangle_mesh", mesh}};

bool inside_by_rays(const Solid& solid, const Vec3d& p) {
    std::vector<InsideSpan> spans;
    QueryScratch scratch;
    solid.inside_spans(p, normalize(Vec3d{0.31, 0.52, 0.79}), -100, 100, spans, scratch);
    for (const InsideSpan& s : spans)
        if (s.enter.t < 0 && 0 < s.exit.t) return true;
    return false;
}

class ShapeFields : public testing::TestWithParam<Case> {};

TEST_P(ShapeFields, SignMatchesTheShapesInsideTest) {
    std::unique_ptr<Shape> shape = GetParam().make();
    const std::unique_ptr<ImplicitField> field = shape->implicit_field();
    ASSERT_TRUE(field);
    auto& solid = dynamic_cast<Solid&>(*shape);
    solid.prepare_span_queries(embree_device());
    const FieldBox b = field->bounds();
    std::mt19937 random(3);
    std::uniform_real_distribution<double> u(0, 1);
    int inside = 0, disagreements = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3d p = b.lower - b.extent() * 0.1 + b.extent() * 1.2 * Vec3d{u(random), u(random), u(random)};
        const double v = field->value(p);
        if (std::abs(v) < 1e-6) continue;  // on the surface either answer is right
        inside += v < 0;
        disagreements += (v < 0) != inside_by_rays(solid, p);
    }
    EXPECT_EQ(disagreements, 0);
    EXPECT_GT(inside, 50);
}

TEST_P(ShapeFields, GradientMatchesFiniteDifferencesNearTheSurface) {
    std::unique_ptr<Shape> shape = GetParam().make();
    const std::unique_ptr<ImplicitField> field = shape->implicit_field();
    const FieldBox b = field->bounds();
    const double h = 1e-6 * max_component(b.extent());
    std::mt19937 random(5);
    std::uniform_real_distribution<double> u(0, 1);
    int checked = 0, bad = 0;
    for (int i = 0; i < 4000 && checked < 200; ++i) {
        const Vec3d p = b.lower + b.extent() * Vec3d{u(random), u(random), u(random)};
        // Away from creases (CSG, box edges, mesh edges) the field is smooth: compare where it is.
        const double v = field->value(p);
        if (std::abs(v) > 0.2 * max_component(b.extent())) continue;
        Vec3d fd;
        for (int k = 0; k < 3; ++k) {
            Vec3d e;
            e[k] = h;
            fd[k] = (field->value(p + e) - field->value(p - e)) / (2 * h);
        }
        const Vec3d g = field->gradient(p);
        ++checked;
        if (length(fd - g) > 1e-3 * std::max(1.0, length(g))) ++bad;
    }
    EXPECT_GT(checked, 50);
    EXPECT_LE(bad, checked / 20) << "creases may disagree, but only rarely";
}

TEST_P(ShapeFields, MayReachSurfaceNeverMissesASignChange) {
    std::unique_ptr<Shape> shape = GetParam().make();
    const std::unique_ptr<ImplicitField> field = shape->implicit_field();
    const FieldBox b = field->bounds();
    std::mt19937 random(11);
    std::uniform_real_distribution<double> u(0, 1);
    int denied = 0;
    for (int i = 0; i < 300; ++i) {
        const Vec3d c = b.lower - b.extent() * 0.2 + b.extent() * 1.4 * Vec3d{u(random), u(random), u(random)};
        const double r = 0.15 * max_component(b.extent()) * u(random);
        if (field->may_reach_surface(c, r)) continue;
        ++denied;
        const bool centre_inside = field->value(c) < 0;
        for (int k = 0; k < 50; ++k) {
            const Vec3d d = normalize(Vec3d{u(random) - 0.5, u(random) - 0.5, u(random) - 0.5});
            const Vec3d p = c + d * (r * std::cbrt(u(random)));
            ASSERT_EQ(field->value(p) < 0, centre_inside) << "at " << p.x << "," << p.y << "," << p.z;
        }
    }
    EXPECT_GT(denied, 30);
}

// Every method closes the surface into a closed, consistently oriented 2-manifold: no cut edge left open, every
// edge of the mesh in exactly two triangles, one ring of triangles round every vertex. (Dual contouring needs the
// split vertices of dual_contouring.h for that: the CSG difference here has tunnels through ambiguous faces at
// depth 5, where an edge used to belong to four triangles — the regression test below.)
TEST_P(ShapeFields, EveryPolygoniserClosesTheSurface) {
    std::unique_ptr<Shape> shape = GetParam().make();
    const std::unique_ptr<ImplicitField> field = shape->implicit_field();
    for (const PolygonizeMethod method :
         {PolygonizeMethod::MarchingCubes, PolygonizeMethod::DualContouring, PolygonizeMethod::SphericalDualContouring})
        for (int depth = 4; depth <= 5; ++depth) {
            PolygonizeOptions options;
            options.method = method;
            options.depth = depth;
            const Polygonization p = polygonize_field(*field, options);
            SCOPED_TRACE("method " + std::to_string(int(method)) + " depth " + std::to_string(depth));
            const EdgeUse use = edge_use(p.mesh);
            EXPECT_EQ(use.boundary, 0u);
            EXPECT_EQ(use.over_shared, 0u);
            EXPECT_EQ(p.report.dual.open_edges, 0u);
            EXPECT_GT(signed_volume(p.mesh), 0);
            EXPECT_TRUE(is_closed_two_manifold(p.mesh));
        }
}

// Octree simplification keeps every shape a closed 2-manifold of the same Euler characteristic, and the vertex
// count never rises with the tolerance (a larger tolerance collapses a superset of the nodes).
TEST_P(ShapeFields, SimplifiedDualContouringStaysAClosedManifold) {
    std::unique_ptr<Shape> shape = GetParam().make();
    const std::unique_ptr<ImplicitField> field = shape->implicit_field();
    PolygonizeOptions options;
    options.method = PolygonizeMethod::DualContouring;
    options.depth = 5;
    const Polygonization full = polygonize_field(*field, options);
    const double size = max_component(field->bounds().extent());
    std::size_t previous = full.mesh.positions.size();
    for (const double tolerance : {0.0, 1e-3, 1e-2, 0.1}) {
        options.simplify = tolerance * size;
        const Polygonization p = polygonize_field(*field, options);
        SCOPED_TRACE("tolerance " + std::to_string(tolerance));
        const EdgeUse use = edge_use(p.mesh);
        EXPECT_EQ(use.boundary, 0u);
        EXPECT_EQ(use.over_shared, 0u);
        EXPECT_TRUE(is_closed_two_manifold(p.mesh));
        EXPECT_EQ(euler_characteristic(p.mesh), euler_characteristic(full.mesh));
        EXPECT_GT(signed_volume(p.mesh), 0);
        EXPECT_LE(p.mesh.positions.size(), previous);
        previous = p.mesh.positions.size();
    }
    EXPECT_LT(previous, full.mesh.positions.size() / 2) << "a tenth of the object's size collapses much";
}

// Regression: two cells sharing an ambiguous face of this CSG difference both join the face's two segments into
// one cycle; their vertices were joined by two dual edges, so one mesh edge belonged to four triangles. Now one
// segment gets a split vertex and the mesh is a closed 2-manifold.
TEST(ShapeFields, TunnelsThroughAmbiguousFacesGetASplitVertex) {
    std::unique_ptr<Shape> shape = csg();
    const std::unique_ptr<ImplicitField> field = shape->implicit_field();
    PolygonizeOptions options;
    options.method = PolygonizeMethod::DualContouring;
    options.depth = 5;
    const Polygonization p = polygonize_field(*field, options);
    EXPECT_GT(p.report.dual.split_vertices, 0u);
    EXPECT_EQ(p.mesh.positions.size(), p.report.dual.cell_vertices + p.report.dual.split_vertices);
    EXPECT_EQ(edge_use(p.mesh).over_shared, 0u);
    EXPECT_TRUE(is_closed_two_manifold(p.mesh));
    // The split vertex lies on the surface like the others.
    for (std::size_t v = p.report.dual.cell_vertices; v < p.mesh.positions.size(); ++v) {
        const Vec3d x(p.mesh.positions[v]);
        EXPECT_LT(std::abs(field->value(x)) / length(field->gradient(x)), 0.02) << v;
    }
}

INSTANTIATE_TEST_SUITE_P(Registered, ShapeFields, testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

// DC keeps a box's corners (three planes meet in the corner's cell); MC cannot (its vertices lie on lattice edges).
// Regression: the superquadric field was a constant 1 outside the object's box, with zero gradient, so a DC
// vertex clamped just outside it had |f|/|∇f| = ∞ (isotrace mesh printed "mean inf, max inf" for an ellipsoid).
TEST(ShapeFields, SuperquadricFieldKeepsRisingOutsideItsBox) {
    std::vector<Superquadric> set;
    set.push_back(superquadric_test::make_superquadric({1, 0.6, 0.4}, 1, 1));
    const SuperquadricShape shape(std::move(set));
    const std::unique_ptr<ImplicitField> field = shape.implicit_field();
    const double top = field->bounds().upper.z;
    // Continuous across the box face, positive and rising beyond it, with an outward gradient.
    EXPECT_NEAR(field->value({0, 0, top - 1e-9}), field->value({0, 0, top + 1e-9}), 1e-6);
    double previous = field->value({0, 0, top});
    for (double z = top + 0.05; z < top + 1; z += 0.05) {
        const double v = field->value({0, 0, z});
        EXPECT_GT(v, previous) << "z " << z;
        EXPECT_GT(field->gradient({0.01, 0.02, z}).z, 0.1) << "z " << z;
        previous = v;
    }
}

TEST(ShapeFields, DualContouringKeepsTheCornersOfACsgBox) {
    std::vector<CsgChild> children;
    children.push_back({std::make_unique<BoxShape>(Vec3d{0.0123, -0.0311, 0.0271}, Vec3d{0.61, 0.47, 0.53}), Transform(), {}});
    children.push_back({std::make_unique<SphereShape>(std::vector<Sphere>{{{0.9, 0.1, 0.0}, 0.3}}), Transform(), {}});
    const CsgShape csg(CsgOperation::Union, std::move(children));
    const std::unique_ptr<ImplicitField> field = csg.implicit_field();
    const auto nearest = [](const TriangleMeshData& mesh, const Vec3d& q) {
        double best = INFINITY;
        for (const Vec3f& p : mesh.positions) best = std::min(best, length(Vec3d(p) - q));
        return best;
    };
    PolygonizeOptions options;
    options.depth = 6;
    options.method = PolygonizeMethod::DualContouring;
    const TriangleMeshData dc = polygonize_field(*field, options).mesh;
    options.method = PolygonizeMethod::MarchingCubes;
    const TriangleMeshData mc = polygonize_field(*field, options).mesh;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d q(0.0123 + (corner & 1 ? 0.61 : -0.61), -0.0311 + (corner & 2 ? 0.47 : -0.47),
                      0.0271 + (corner & 4 ? 0.53 : -0.53));
        if (length(q - Vec3d{0.9, 0.1, 0.0}) < 0.3) continue;  // inside the sphere: not a corner of the union
        EXPECT_LT(nearest(dc, q), 1e-3) << corner;
        EXPECT_GT(nearest(mc, q), 1e-3) << corner;
    }
}

// Simplified, the box's flat faces collapse into a few large leaves (their QEF planes agree), while a corner's
// leaf still holds its three planes, whose intersection is the vertex: the corners stay within 1e-3.
TEST(ShapeFields, SimplifiedDualContouringCollapsesABoxsFacesAndKeepsItsCorners) {
    const Vec3d centre{0.0123, -0.0311, 0.0271}, half{0.61, 0.47, 0.53};
    const BoxShape box(centre, half);
    const std::unique_ptr<ImplicitField> field = box.implicit_field();
    PolygonizeOptions options;
    options.depth = 6;
    options.method = PolygonizeMethod::DualContouring;
    const std::size_t full = polygonize_field(*field, options).mesh.positions.size();
    options.simplify = 1e-4;
    const Polygonization p = polygonize_field(*field, options);
    EXPECT_TRUE(is_closed_two_manifold(p.mesh));
    EXPECT_EQ(euler_characteristic(p.mesh), 2);
    EXPECT_LT(p.mesh.positions.size() * 10, full) << full;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d q = centre + Vec3d(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1) * half;
        double best = INFINITY;
        for (const Vec3f& v : p.mesh.positions) best = std::min(best, length(Vec3d(v) - q));
        EXPECT_LT(best, 1e-3) << corner;
    }
    std::printf("box depth 6: %zu vertices, simplified to 1e-4: %zu\n", full, p.mesh.positions.size());
}

}  // namespace
}  // namespace isotrace
