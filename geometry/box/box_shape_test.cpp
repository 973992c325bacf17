// The box primitive: hits and outward normals on every face, edges and face planes, rays from inside, affine
// transforms (baked) against the same box as a native triangle mesh, inside spans, and the scene format.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "geometry/box/box_shape.h"
#include "geometry/csg/csg_test_support.h"
#include "geometry/mesh/mesh_test_support.h"
#include "geometry/mesh/triangle_mesh_shape.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace {
namespace {

using namespace csg_test;

TEST(BoxShape, EveryFaceIsHitAtItsDistanceWithItsOutwardNormal) {
    const Vec3d centre(1, 2, 3), half(0.5, 1, 1.5);
    const auto scene = scene_of(box(centre, half));
    for (int axis = 0; axis < 3; ++axis)
        for (double side : {-1.0, 1.0}) {
            Vec3d outward;
            outward[axis] = side;
            Vec3d across(0.05, 0.1, 0.15);  // off the face's centre, within the face
            across[axis] = 0;
            const Vec3d origin = centre + outward * (half[axis] + 4) + across;
            const auto hit = scene->intersect(make_ray(origin, -outward), RayKind::Camera);
            ASSERT_TRUE(hit) << axis << side;
            EXPECT_NEAR(hit->t, 4, 1e-6);
            expect_near(hit->geometric_normal, outward, 1e-7, "face normal");
            // From the centre: the same face from inside (rays starting inside hit the exit).
            const auto exit = scene->intersect(make_ray(centre, outward), RayKind::Camera);
            ASSERT_TRUE(exit);
            EXPECT_NEAR(exit->t, half[axis], 1e-6);
            expect_near(exit->geometric_normal, outward, 1e-7, "exit normal");
        }
}

TEST(BoxShape, EdgesAndFacePlanes) {
    const auto scene = scene_of(box({0, 0, 0}, {0.5, 0.5, 0.5}));
    // Touching an edge only, and running inside a face plane: misses (no interior is crossed).
    EXPECT_FALSE(scene->intersect(make_ray({0, 1, 0}, {1, -1, 0}), RayKind::Camera));
    EXPECT_FALSE(scene->intersect(make_ray({-2, 0.5, 0}, {1, 0, 0}), RayKind::Camera));
    EXPECT_FALSE(scene->occluded(make_ray({-2, 0.5, 0}, {1, 0, 0})));
    // Entering through an edge: hit at the edge with the normal of one of its two faces.
    const auto edge = scene->intersect(make_ray({1, 1, 0.25}, {-1, -1, 0}), RayKind::Camera);
    ASSERT_TRUE(edge);
    EXPECT_NEAR(edge->t, 0.5, 1e-6);
    const Vec3f n = edge->geometric_normal;
    EXPECT_TRUE((n == Vec3f(1, 0, 0)) || (n == Vec3f(0, 1, 0))) << n.x << " " << n.y << " " << n.z;
    // Parallel to a slab and inside it: only the other slabs bound the span.
    const auto parallel = scene->intersect(make_ray({-3, 0.25, -0.25}, {1, 0, 0}), RayKind::Camera);
    ASSERT_TRUE(parallel);
    EXPECT_NEAR(parallel->t, 2.5, 1e-6);
}

TEST(BoxShape, AffineTransformsBakeExactlyAndMatchTheTriangleMeshBox) {
    const Transform to_world = Transform::translate({0.3, -0.2, 0.5}) * Transform::rotate({1, 2, 0.5}, 35) *
                               Transform::scale({1.5, 0.7, 1.1}) * Transform::rotate({0, 0, 1}, 20);
    const Vec3d centre(0.1, 0.2, -0.1), half(0.6, 0.8, 0.5);
    const auto boxed = scene_of(box(centre, half), to_world);
    EXPECT_FALSE(boxed->objects()[0].instanced);
    TriangleMeshData cube;  // the same box as 12 triangles, counter-clockwise from outside
    for (std::uint32_t i = 0; i < 8; ++i)
        cube.positions.push_back(Vec3f(centre + Vec3d(i & 1 ? half.x : -half.x, i & 2 ? half.y : -half.y,
                                                      i & 4 ? half.z : -half.z)));
    cube.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                      {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    const auto meshed = scene_of(std::make_unique<TriangleMeshShape>(cube), to_world);
    std::mt19937 random(21);
    std::uniform_real_distribution<double> unit(-1, 1);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3d origin{unit(random) * 5, unit(random) * 5, unit(random) * 5};
        const Vec3d target{unit(random), unit(random), unit(random)};
        const Ray ray = make_ray(origin, target - origin);
        const auto a = boxed->intersect(ray, RayKind::Camera), b = meshed->intersect(ray, RayKind::Camera);
        if (a.has_value() != b.has_value()) {
            // Only rays within float precision of an edge may disagree.
            const auto hit = a ? a : b;
            ADD_FAILURE() << "ray " << i << " disagrees at t " << hit->t;
            continue;
        }
        if (!a) continue;
        ++hits;
        EXPECT_NEAR(a->t, b->t, 2e-5 * b->t);
        expect_near(a->geometric_normal, Vec3d(b->geometric_normal), 1e-4, "face normal");
        EXPECT_TRUE(boxed->occluded(ray));
    }
    EXPECT_GT(hits, 800);
}

TEST(BoxShape, InsideSpansAreClippedToTheQueryRange) {
    const BoxShape shape({0, 0, 0}, {1, 1, 1});
    std::vector<InsideSpan> spans;
    QueryScratch scratch;
    shape.inside_spans({-5, 0, 0}, {2, 0, 0}, 0, 100, spans, scratch);  // direction of length 2: t halves
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_DOUBLE_EQ(spans[0].enter.t, 2);
    EXPECT_DOUBLE_EQ(spans[0].exit.t, 3);
    EXPECT_EQ(spans[0].enter.normal, Vec3d(-1, 0, 0));
    EXPECT_EQ(spans[0].exit.normal, Vec3d(1, 0, 0));
    spans.clear();
    shape.inside_spans({-5, 0, 0}, {2, 0, 0}, 2.5, 100, spans, scratch);
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_FALSE(spans[0].enter.on_surface());
    EXPECT_DOUBLE_EQ(spans[0].enter.t, 2.5);
    EXPECT_TRUE(spans[0].exit.on_surface());
    spans.clear();
    shape.inside_spans({-5, 0, 0}, {2, 0, 0}, 3.5, 100, spans, scratch);
    EXPECT_TRUE(spans.empty());
}

TEST(BoxShapeScene, LoadsAndRejectsBadHalfSizes) {
    mesh_test::ScratchDirectory dir;
    const auto scene_with = [](const std::string& shape) {
        return R"({"isotrace": 1, "film": {"resolution": [4, 4]},
  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
  "materials": {"m": {"type": "diffuse"}},
  "objects": [{"material": "m", "shape": )" + shape + "}]}";
    };
    const auto loaded = load_scene(dir.write("box.json", scene_with(R"({"type": "box", "center": [0, 1, 0], "half_size": [2, 1, 0.5]})")));
    const auto hit = loaded->scene->intersect(make_ray({0, 1, 10}, {0, 0, -1}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 9.5f);
    for (const char* half : {"[1, 0, 1]", "[1, -1, 1]"}) {
        const std::string path = dir.write("bad.json", scene_with(std::string(R"({"type": "box", "half_size": )") + half + "}"));
        const std::string message = mesh_test::input_error_message([&] { load_scene(path); });
        EXPECT_NE(message.find(path + ":4:"), std::string::npos) << message;
        EXPECT_NE(message.find("objects[0].shape.half_size: every half size must be positive"), std::string::npos)
            << message;
    }
}

TEST(BoxShape, CertainlyOutsideOnlyBeyondTheGivenDistance) {
    BoxShape box({1, 0, 0}, {1, 2, 3});  // x in [0, 2]
    EXPECT_TRUE(box.certainly_outside({3, 3, 0}, 1.41));  // √2 from the edge (2, 2, z)
    EXPECT_FALSE(box.certainly_outside({3, 3, 0}, 1.42));
    EXPECT_FALSE(box.certainly_outside({1, 0, 0}, 0));  // inside
    box.bake(Transform::scale({2, 2, 2}));               // x in [0, 4], y in [−4, 4]
    EXPECT_TRUE(box.certainly_outside({5, 0, 0}, 0.99));
    EXPECT_FALSE(box.certainly_outside({5, 0, 0}, 1.01));
    box.bake(Transform::scale({1, 3, 1}));  // no longer a similarity: undecided
    EXPECT_FALSE(box.certainly_outside({50, 0, 0}, 0.1));
}

}  // namespace
}  // namespace isotrace
