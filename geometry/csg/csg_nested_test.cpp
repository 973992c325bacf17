// Nested CSG (a CSG in a CSG in a CSG, with superquadric and mesh leaves): its spans are those the tree gave when
// its buffers were per-thread state, concurrent queries with scratches of their own do not disturb each other,
// and a render of it is the same with one thread and with two.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "geometry/csg/csg_shape.h"
#include "renderer/embree/embree_device.h"
#include "renderer/render/tile_renderer.h"
#include "renderer/scene/loaded_scene.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

// A union of (the intersection of a stretched superquadric and a sphere, minus a mesh box) and a pair of
// superquadrics. Parts: 0 the stretched superquadric, 1 the sphere, 2 the mesh box, 3 the pair.
constexpr const char* kNestedTree = R"({"type": "csg", "op": "union", "children": [
  {"shape": {"type": "csg", "op": "difference", "children": [
    {"shape": {"type": "csg", "op": "intersection", "children": [
      {"shape": {"type": "superquadric", "radii": [1, 1, 1], "exponents": [0.5, 0.8]},
       "transform": {"scale": [1.2, 0.8, 1]}},
      {"shape": {"type": "sphere", "radius": 1.1}}]}},
    {"shape": {"type": "mesh",
      "positions": [[-0.4, -0.55, -0.7], [0.6, -0.55, -0.7], [0.6, 0.95, -0.7], [-0.4, 0.95, -0.7],
                    [-0.4, -0.55, 1.3], [0.6, -0.55, 1.3], [0.6, 0.95, 1.3], [-0.4, 0.95, 1.3]],
      "triangles": [[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4], [3, 7, 6], [3, 6, 2],
                    [0, 4, 7], [0, 7, 3], [1, 2, 6], [1, 6, 5]]},
     "transform": {"translate": [0.5, 0, 0.2]}}]}},
  {"shape": {"type": "superquadric", "superquadrics": [
     {"radii": [0.3, 0.3, 0.6], "exponents": [0.3, 1], "center": [1.4, 0, 0]},
     {"radii": [0.5, 0.2, 0.2], "exponents": [1, 0.4], "center": [1.6, 0.3, 0.1]}]}}]})";

std::unique_ptr<CsgShape> nested_tree() {
    const testing::ParsedScene parsed(kNestedTree);
    std::unique_ptr<Shape> shape = shape_registry().create(parsed.root());
    std::unique_ptr<CsgShape> tree(dynamic_cast<CsgShape*>(shape.release()));
    tree->prepare_span_queries(embree_device());
    return tree;
}

// Query `k`: from a circle of radius 4 around the tree towards a point near its centre; every fourth starts at
// t = 1, inside the tree, so that its first span is cut.
struct SpanQuery {
    Vec3d origin, direction;
    double t_min, t_max;
};

SpanQuery span_query(int k) {
    const double a = 0.2618 * k;
    const Vec3d origin{4 * std::cos(a), 0.05 * (k % 5) - 0.1, 4 * std::sin(a)};
    const Vec3d target{0.3 * std::sin(3.0 * k), 0.1 * (k % 3), 0.2 * std::cos(2.0 * k)};
    return {origin, target - origin, k % 4 == 0 ? 1.0 : 0.1, 1.9};
}
constexpr int kQueries = 24;

std::vector<InsideSpan> spans_of(const CsgShape& tree, int k, QueryScratch& scratch) {
    const SpanQuery q = span_query(k);
    std::vector<InsideSpan> spans;
    tree.inside_spans(q.origin, q.direction, q.t_min, q.t_max, spans, scratch);
    return spans;
}

// Two threads at once, each with a scratch of its own, call mismatch(k, scratch) for every query k, 40 times over,
// the second starting half-way through them, so that they ask different rays at the same moment: how many calls
// returned true.
template <class Mismatch>
int mismatches_on_two_threads(Mismatch mismatch) {
    int mismatches[2] = {0, 0};
    const auto ask = [&](int thread) {
        QueryScratch own;
        for (int round = 0; round < 40; ++round)
            for (int i = 0; i < kQueries; ++i)
                mismatches[thread] += mismatch((thread * kQueries / 2 + i) % kQueries, own);
    };
    std::thread first(ask, 0), second(ask, 1);
    first.join();
    second.join();
    return mismatches[0] + mismatches[1];
}

// Query k's spans a and b agree, normals included (those the leaves defer, as the tree computes them).
bool same_spans(const CsgShape& tree, int k, const std::vector<InsideSpan>& a, const std::vector<InsideSpan>& b) {
    if (a.size() != b.size()) return false;
    const SpanQuery q = span_query(k);
    const auto normal = [&](const BoundaryPoint& end) { return tree.boundary_normal(q.origin, q.direction, end); };
    for (std::size_t i = 0; i < a.size(); ++i)
        for (const auto& [x, y] : {std::pair(a[i].enter, b[i].enter), std::pair(a[i].exit, b[i].exit)})
            if (x.t != y.t || x.part != y.part || x.primitive != y.primitive ||
                (x.on_surface() && normal(x) != normal(y)))
                return false;
    return true;
}

// The spans the tree gave before its buffers became the query's, with the mesh's crossings solved in double
// (triangle_hit.h) since: t of both ends, their parts and primitives (kCut where the query range cut the span). They
// hold on every machine: none of them is a product with Embree's approximate reciprocal.
struct ExpectedSpan {
    double enter, exit;
    std::uint32_t enter_part, exit_part, enter_primitive, exit_primitive;
};
struct ExpectedQuery {
    int k;
    std::vector<ExpectedSpan> spans;
};
constexpr std::uint32_t kCut = BoundaryPoint::kCut;

TEST(CsgNested, SpansAreThoseTheTreeGaveBefore) {
    const std::vector<ExpectedQuery> expected = {
    {0, {{1, 1.2675140980540549, 0, 1, kCut, 0}}},
    {1, {{0.56757633366829907, 0.72171021178663863, 3, 3, 0, 0}, {0.98491011289488184, 1.2773270924226863, 2, 1, 9, 0}}},
    {2, {{0.94818810858310165, 1.2249537862292388, 2, 1, 9, 0}}},
    {3, {{1.0087384170774734, 1.349803607238486, 2, 1, 9, 0}}},
    {4, {{1, 1.2383988039711014, 0, 1, kCut, 0}}},
    {5, {{1.0823971181886844, 1.2057056092706866, 2, 0, 1, 0}}},
    {6, {{0.78306912631896752, 1.304828218312106, 0, 0, 0, 0}}},
    {7, {{0.74647232790123519, 0.88261063641007509, 0, 2, 0, 8}, {1.1374606716732791, 1.2498148393863011, 2, 1, 1, 0}}},
    {8, {{1, 1.2206187761202942, 0, 0, kCut, 0}}},
    {9, {{0.71072648690997886, 0.94000274278715912, 1, 2, 0, 8}}},
    {10, {{0.78410719741962909, 1.125140933222371, 1, 2, 0, 9}, {1.3031838083999061, 1.3722794693451716, 2, 1, 0, 0}}},
    {11, {{0.67005173420536868, 0.95197196234785342, 1, 2, 0, 9}, {1.2343430265411635, 1.2739405639299584, 3, 3, 0, 0}}},
    {12, {{1, 1.1073699564431734, 0, 2, kCut, 9}, {1.3774604147701401, 1.539513863675517, 3, 3, 0, 0}}},
    {13, {{0.67328034642935863, 0.95445552691272206, 1, 2, 0, 9}, {1.2007057403447983, 1.329124836924906, 3, 3, 0, 0}}},
    {14, {{0.7952263124207708, 1.1175733483744312, 1, 2, 0, 9}}},
    {15, {{0.69150476228849211, 0.94964735133245959, 1, 2, 0, 9}}},
    {16, {{1, 1.1867636743292587, 0, 2, kCut, 8}}},
    {17, {{0.77533922264821076, 0.91824931433211676, 0, 2, 0, 9}}},
    {18, {{0.75483741409759753, 1.2579889549056029, 0, 0, 0, 0}}},
    {19, {{0.70710328342830686, 0.82957710614592972, 0, 2, 0, 1}, {1.0341076815151915, 1.19950101881708, 2, 0, 9, 0}}},
    {20, {{1, 1.2838403591367069, 0, 1, kCut, 0}}},
    {21, {{0.742128178476268, 0.84718239704513765, 1, 2, 0, 0}, {0.98207750832983143, 1.3049230046878399, 2, 1, 9, 0}}},
    {22, {{0.63700897528101064, 0.67236399363400523, 3, 3, 0, 0}, {0.96890483281197692, 1.2352141186458501, 2, 1, 9, 0}}},
    {23, {{0.56755126316678373, 0.69739077041908593, 3, 3, 0, 0}, {0.96551304504376101, 1.2633706968902592, 2, 1, 9, 0}}},
    };
    const auto tree = nested_tree();
    QueryScratch scratch;
    ASSERT_EQ(expected.size(), std::size_t(kQueries));
    for (const ExpectedQuery& query : expected) {
        const std::vector<InsideSpan> spans = spans_of(*tree, query.k, scratch);
        EXPECT_EQ(scratch.depth(), 0u) << "every level is given back";
        ASSERT_EQ(spans.size(), query.spans.size()) << "query " << query.k;
        for (std::size_t i = 0; i < spans.size(); ++i) {
            const ExpectedSpan& e = query.spans[i];
            const std::string what = "query " + std::to_string(query.k) + ", span " + std::to_string(i);
            EXPECT_DOUBLE_EQ(spans[i].enter.t, e.enter) << what;
            EXPECT_DOUBLE_EQ(spans[i].exit.t, e.exit) << what;
            EXPECT_EQ(spans[i].enter.part, e.enter_part) << what;
            EXPECT_EQ(spans[i].exit.part, e.exit_part) << what;
            EXPECT_EQ(spans[i].enter.primitive, e.enter_primitive) << what;
            EXPECT_EQ(spans[i].exit.primitive, e.exit_primitive) << what;
        }
    }
}

// Two threads ask the same tree at once, each with its own scratch, over and over: every answer is the one a
// lone query gives. (Buffers shared between the threads would mix their spans; under ThreadSanitizer, a race.)
TEST(CsgNested, ConcurrentQueriesWithTheirOwnScratchDoNotInterfere) {
    const auto tree = nested_tree();
    std::vector<std::vector<InsideSpan>> alone(kQueries);
    QueryScratch scratch;
    for (int k = 0; k < kQueries; ++k) alone[std::size_t(k)] = spans_of(*tree, k, scratch);

    EXPECT_EQ(mismatches_on_two_threads([&](int k, QueryScratch& own) {
                  return !same_spans(*tree, k, spans_of(*tree, k, own), alone[std::size_t(k)]);
              }),
              0);
}

// The same through RenderScene, whose queries borrow their scratch from the scene: nearest hits from two threads
// at once are those of one thread.
TEST(CsgNested, ConcurrentSceneQueriesDoNotInterfere) {
    auto scene = std::make_unique<RenderScene>();
    SceneObject object;
    object.name = "tree";
    object.shape = nested_tree();
    object.to_world = Transform::scale({1, 1.5, 1});  // not a similarity: the superquadrics are instanced
    scene->add_object(std::move(object));
    scene->commit();
    const auto ray_of = [](int k) {
        const SpanQuery q = span_query(k);
        Ray ray;
        ray.origin = Vec3f(q.origin);
        ray.direction = Vec3f(q.direction);
        ray.t_near = float(q.t_min);
        ray.t_far = float(q.t_max);
        return ray;
    };
    std::vector<std::optional<SurfaceHit>> alone(kQueries);
    int hits = 0;
    for (int k = 0; k < kQueries; ++k) {
        alone[std::size_t(k)] = scene->intersect(ray_of(k), RayKind::Camera);
        hits += alone[std::size_t(k)].has_value();
    }
    EXPECT_GT(hits, kQueries / 2);

    EXPECT_EQ(mismatches_on_two_threads([&](int k, QueryScratch&) {
                  const auto hit = scene->intersect(ray_of(k), RayKind::Camera);
                  const auto& expected = alone[std::size_t(k)];
                  const bool same_hit = hit.has_value() == expected.has_value() &&
                                        (!hit || (hit->t == expected->t && hit->primitive_id == expected->primitive_id));
                  return !same_hit || scene->occluded(ray_of(k)) != expected.has_value();
              }),
              0);
}

TEST(CsgNested, RendersTheSameWithOneThreadAndWithTwo) {
    const testing::SceneFile file(R"({"isotrace": 1, "film": {"resolution": [32, 24], "spp": 4},
  "camera": {"type": "perspective", "fov": 40, "look_at": {"eye": [0.5, 2, 5], "target": [0.4, 0, 0]}},
  "integrator": {"type": "preview", "ambient": 0.3, "ambient_samples": 2, "background": [0, 0, 0]},
  "materials": {"grey": {"type": "diffuse", "reflectance": 0.6}},
  "lights": [{"type": "point", "position": [2, 3, 2], "intensity": 12}],
  "objects": [{"name": "tree", "material": "grey", "transform": {"scale": [1, 1.5, 1]}, "shape": )" +
                                  std::string(kNestedTree) + "}]}");
    const auto scene = load_scene(file.path());
    std::vector<ImageBuffer> images;
    for (int threads : {1, 2}) {
        tbb::task_arena arena(threads);
        RenderOptions options;
        options.tile_size = 4;
        options.spp = scene->spp;
        arena.execute([&] { images.push_back(render_scene(*scene, options).film->resolve()); });
    }
    const ImageBuffer &one = images[0], &two = images[1];
    ASSERT_EQ(one.pixels.size(), two.pixels.size());
    EXPECT_EQ(std::memcmp(one.pixels.data(), two.pixels.data(), one.pixels.size() * sizeof(float)), 0);
    // The tree is in the picture: some pixels are lit (red, the first channel), some are background.
    int lit = 0;
    for (std::size_t p = 0; p < one.pixels.size(); p += one.channels.size()) lit += one.pixels[p] > 0.05f;
    EXPECT_GT(lit, 20);
    EXPECT_LT(lit, 32 * 24 - 20);
}

}  // namespace
}  // namespace isotrace
